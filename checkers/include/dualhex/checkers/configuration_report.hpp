#pragma once
// What a configuration check reports (periodic torus or cube window): the validation, the
// dual (all-hex) count, the singular structure and which elements were placed.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/schemes/placement.hpp"
#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {

/// One coarse leaf of a configuration complex: where it is, what the rule saw and chose.
struct PlacedLeaf {
    LatticePoint leaf;  ///< min corner, coarse-leaf units
    LeafContext context;
    std::optional<Placement> placement;  ///< nullopt: plain hexahedron
};

/// A configuration's complex as built (before checking).
struct ConfigurationComplex {
    std::uint8_t mask = 0;
    std::int64_t unit = 0;  ///< lattice units per coarse leaf
    CellComplex complex;
    std::vector<PlacedLeaf> coarse_leaves;
    std::size_t fine_hexes = 0;
};

struct ConfigurationReport {
    std::uint8_t mask = 0;
    /// False if the complex could not be built (the rule threw, an unknown element, ...);
    /// then `error` says why and nothing else is filled.
    bool built = false;
    std::string error;

    ValidationReport validation;
    std::size_t vertices = 0, edges = 0, faces = 0, cells = 0;
    std::size_t checked_vertices = 0;  ///< interior vertices that got the valence checks
    std::size_t hexes = 0;             ///< of those, the ones whose dual cell is a cube
    /// Faces with one cell that do not lie on the domain's boundary (the torus has none;
    /// the window's is the cube's surface): holes, e.g. where two placed elements do not
    /// match. validate() treats them as boundary, so their vertices and edges would escape
    /// the interior checks; they are checked here instead (6 edges per vertex, 4 cells per
    /// edge), and violations are added to `validation` as VertexValence / EdgeCellCount.
    std::size_t open_faces = 0;
    std::map<int, std::size_t> face_sizes;          ///< over all faces
    std::map<int, std::size_t> dual_edge_valences;  ///< interior faces (all vertices checked)
    /// Placements per element name; plain coarse hexes as "hex", fine hexes as "fine".
    std::map<std::string, std::size_t> elements;

    [[nodiscard]] bool ok() const { return built && validation.ok() && open_faces == 0 && hexes == checked_vertices; }
    /// One line: mask, ok/FAIL, counts, histograms (or the error).
    [[nodiscard]] std::string summary() const;
};

/// "{3:96, 4:960, 5:96}".
[[nodiscard]] std::string format_histogram(const std::map<int, std::size_t>& histogram);
/// "0b11001100".
[[nodiscard]] std::string format_mask(std::uint8_t mask);

}  // namespace dualhex
