#pragma once
// The root boundary (proofs/README.md, "Root boundary"): a finite enumeration whose success
// proves that every strongly balanced paired grid, installed with the strong rule under a
// root policy (OutsideRoot::Coarse or Mirror), is valid at every vertex ON the root cube's
// boundary, and that the clipped dual cell of each such vertex is a positively oriented
// hexahedron whose boundary faces lie on the root faces.
//
// Why finite. The compositional argument's steps 1-4 (compositional.hpp) hold for a vertex
// v on the root boundary as they are (the policy fixes what the rule sees outside). v lies
// on root planes for a set S of axes (1: a face, 2: an edge, 3: a corner); the nearest
// lattice point g has g_a = v_a, an even coordinate, for a in S. Translating by even
// vectors keeps every context, so the root plane of axis a is x_a = 0 and the root lies on
// one side of it (side +1: x_a >= 0, side -1: x_a <= 0). The leaves containing v are among
// the inside leaves of B(g); their contexts read inside octant cubes (free: every value is
// enumerated) and outside ones (fixed by the policy: coarse, or a copy of the reflected
// inside cube). 3 * 2 * 4 face types, 3 * 4 * 2 edge types and 8 corner types: 56.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/checkers/compositional.hpp"
#include "dualhex/install/install.hpp"
#include "dualhex/topology/cell_complex.hpp"

namespace dualhex {

/// Root planes of a boundary window: side[a] = +1 (root plane x_a = 0, inside x_a >= 0),
/// -1 (inside x_a <= 0) or 0 (no root plane on axis a).
using RootSides = std::array<int, 3>;

/// What the rule sees in an outside octant cube: coarse, fine, the status of an inside cube,
/// or free (the cube is enumerated like an inside one: every status).
struct OutsideOctant {
    enum class Kind { Coarse, Fine, Copy, Free } kind = Kind::Coarse;
    std::array<std::int64_t, 3> copy_of{};
};
/// A root policy as the enumeration applies it (octant cube o = [2o, 2o + 2]^3, coarse-leaf
/// units), asked once per reading leaf (min corner `reader`): a policy that is a function of
/// the cube alone gives every reader the same answer; one that is not is a bug the check
/// must catch (tests).
using OutsidePolicy = std::function<OutsideOctant(const std::array<std::int64_t, 3>& outside, const RootSides& sides,
                                                  const LatticePoint& reader)>;
/// Coarse and Mirror as install applies them (Mirror: o_a -> -1 - o_a on every axis where o
/// is outside). kAnyOutside: every outside cube free, so that the result holds for every
/// policy that is a function of the cube.
enum class BoundaryPolicy { Coarse, Mirror, AnyOutside };
[[nodiscard]] OutsidePolicy outside_policy(BoundaryPolicy policy);
[[nodiscard]] const char* to_string(BoundaryPolicy policy);

struct BoundaryTypeResult {
    std::array<int, 3> parity{};  ///< g (0 on every root axis)
    RootSides sides{};
    int planes = 0;              ///< |S|: 1 face, 2 edge, 3 corner
    int leaves = 0;              ///< inside leaves of B(g): 4, 2, 1
    int free_octants = 0;        ///< inside octant cubes the leaves read (enumerated)
    std::size_t windows = 0, passed = 0, checked_vertices = 0;
};

struct BoundaryResult {
    std::string rule, policy;
    std::vector<BoundaryTypeResult> types;  ///< the 56 boundary types
    std::size_t windows = 0, passed = 0, failed = 0;
    std::array<std::size_t, 3> checked_vertices{};  ///< on 1, 2, 3 root planes (face, edge, corner)
    std::vector<std::string> failures;               ///< the first 10 failing windows
    double seconds = 0;
    [[nodiscard]] bool all_passed() const { return windows > 0 && passed == windows && failed == 0; }
};

/// One distinct half window as built (the box of check_boundary_vertices, half = unit).
struct BoundaryWindowView {
    const BoundaryTypeResult* type = nullptr;
    std::size_t index = 0;  ///< in enumeration order over all types
    std::string witness;    ///< the type and a witness pattern
    const CellComplex* half = nullptr;
    std::int64_t unit = 0;
    bool passed = false;
};

struct BoundaryOptions {
    /// Overrides the policy (tests: a broken policy must be caught).
    OutsidePolicy policy;
    std::size_t stop_after_failures = 0;  ///< 0: never stop
    /// Optional: sees every window in enumeration order after all are checked (certificates).
    std::function<void(const BoundaryWindowView&)> on_window;
};

[[nodiscard]] BoundaryResult run_compositional_boundary(const TransitionRule& rule, const ElementLibrary& library,
                                                        BoundaryPolicy policy, const BoundaryOptions& options = {});

/// The boundary conditions (proofs/README.md, "Root boundary", B1-B5) at every vertex of
/// `complex` that lies on a root plane of `sides` (coordinate 0) and strictly inside the
/// box on the other axes. The complex fills the box made of [0, half] or
/// [-half, 0] on root axes and [-half, half] on the others. Empty: every such vertex passes.
struct BoundaryVertexReport {
    std::size_t checked = 0;
    std::vector<std::string> failures;  ///< "vertex (x,y,z): reason"
    [[nodiscard]] bool ok() const { return failures.empty(); }
};
/// The vertices check_boundary_vertices checks: on a root plane, strictly inside the box on
/// every other axis (its star then lies in the box).
[[nodiscard]] bool on_checked_planes(const LatticePoint& p, std::int64_t half, const RootSides& sides);
[[nodiscard]] BoundaryVertexReport check_boundary_vertices(const CellComplex& complex, std::int64_t half,
                                                           const RootSides& sides);

/// B1-B5 at the one vertex at the origin of `complex` (its star: every cell at it), which
/// lies on the root planes x_a = 0 of the axes with sides[a] != 0 (k = their number), the
/// cells on their root sides: the first reason it fails, or nothing. The per-vertex check of
/// check_boundary_vertices, for stars built alone (proofs/README.md W13).
[[nodiscard]] std::optional<std::string> boundary_vertex_defect(const CellComplex& complex, const RootSides& sides);

/// 6 * the signed volume of a hexahedron in VTK order, every corner given as sum / denominator
/// (exact; positive iff positively oriented).
struct RationalCorner {
    std::array<std::int64_t, 3> sum{};
    std::int64_t denominator = 1;
};
[[nodiscard]] bool hex_positively_oriented(const std::array<RationalCorner, 8>& corners);

}  // namespace dualhex
