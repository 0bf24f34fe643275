#pragma once
// `dualhex audit`: the checks a simulation (or a transition-scheme implementation) needs,
// run on a MeshFile read from anyone's file, every violation located.
//
// Topology comes from point ids only, never from coordinates: the file's connectivity is
// the combinatorics. Coordinates are used only for the scaled Jacobian (the one
// floating-point check), to locate violations, and, for --certify, as exact integers.
//
// Hex mode (every volume cell should be a VTK_HEXAHEDRON; MEDIT Hexahedra):
//   hexahedra            every volume cell is a hexahedron
//   distinct-vertices    every hexahedron has 8 distinct point ids
//   conforming-faces     every quad face in <= 2 hexes, in 2 with opposite directions
//   boundary-edges       every boundary edge in exactly 2 boundary quads
//   boundary-orientation the 2 boundary quads at an edge traverse it oppositely
//   boundary-vertices    the boundary quads around each boundary vertex form one cycle
//   connected            one face-connected component of hexes
//   not-inverted         scaled Jacobian > 0 for every hex
//   Statistics: components, boundary components with V - E + F, scaled Jacobian histogram,
//   interior and boundary edge valence histograms (hexes per edge).
//   A non-conforming junction (a big quad against four small ones) is not a combinatorial
//   face defect: the mismatched faces stay on the boundary, pinched at their shared corners,
//   and fail boundary-vertices (and usually boundary-edges) there.
// Polyhedral mode (a transition mesh; any VTK_POLYHEDRON cell selects it), DESIGN.md 4:
//   faces-simple         faces with >= 3 distinct points
//   cells-closed         each cell's faces a closed, connected, consistently oriented sphere
//   conforming-faces     every face in <= 2 cells, in 2 with opposite orientations, no duplicate cells
//   vertex-valence       interior vertices: 6 edges and an octahedral link
//   edge-valence         interior edges: 4 cells in one cycle
//   dual-all-hex         the dual cell of every interior vertex is a combinatorial cube
//   Interior: on no boundary face. Boundary vertices get no valence check (reported).
//   Face loops are taken as written: outward by the right-hand rule (VTK's convention).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dualhex/audit/mesh_file.hpp"
#include "dualhex/topology/progress.hpp"

namespace dualhex::audit {

enum class AuditMode { Auto, Hex, Polyhedral };

struct AuditOptions {
    AuditMode mode = AuditMode::Auto;
    std::size_t max_listed = 10;  ///< violations listed per check
    /// Optional: before each step of the audit (hex: 6, polyhedral: 3), the steps done of all.
    Progress progress;
};

/// One located violation.
struct Violation {
    std::string what;                           ///< e.g. "hex with a repeated point"
    std::int64_t cell = -1;                     ///< the cell's index in the file, -1 if none
    int line = 0;                               ///< the cell's line in the file, 0 if none
    std::vector<std::int64_t> points;           ///< file point ids
    std::vector<std::array<double, 3>> coordinates;
};

struct CheckResult {
    std::string name, description;
    std::size_t violations = 0;
    std::size_t checked = 0;       ///< entities examined (cells, faces, interior vertices, ...)
    std::string checked_what;      ///< what they are, e.g. "interior vertices"
    std::vector<Violation> first;  ///< the first max_listed
    [[nodiscard]] bool passed() const { return violations == 0; }
};

struct AuditReport {
    std::string path, format;
    std::string mode;  ///< "hex" or "polyhedral"
    std::size_t points = 0, cells = 0, lower_dimensional_cells = 0;
    std::vector<CheckResult> checks;   ///< exactly the checks that ran
    std::vector<std::string> notes;    ///< what was not checked, and why
    nlohmann::json statistics = nlohmann::json::object();  ///< counts and histograms
    [[nodiscard]] bool ok() const;
    [[nodiscard]] std::string text() const;  ///< the human summary
    [[nodiscard]] nlohmann::json json() const;
};

[[nodiscard]] AuditReport audit_mesh(const MeshFile& mesh, const AuditOptions& options = {});

/// Adds a violation to `check` (counted always, kept if fewer than `max` are listed).
void add_violation(CheckResult& check, std::size_t max, Violation v);
/// A Violation at these file points (coordinates filled from `mesh`).
[[nodiscard]] Violation at_points(const MeshFile& mesh, std::string what, std::vector<std::int64_t> points,
                                  std::int64_t file_cell = -1);

}  // namespace dualhex::audit
