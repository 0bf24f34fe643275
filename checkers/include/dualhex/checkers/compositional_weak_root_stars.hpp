#pragma once
// Weak balance on the root surface (proofs/README.md W13): the star enumeration of W9 at the
// vertices v ON the root cube's surface, each inside star checked with the root-boundary
// conditions B1-B5 (compositional_boundary.hpp, boundary_vertex_defect).
//
// v lies on the root planes of a set S of axes (k = |S|: face, edge, corner). A root plane
// is a level-0 plane, so on the level-(m-1) lattice: g_a = v_a and g's parity is 0 on S;
// the plane of axis a is x_a = 0 and the root lies on side +1 (x_a >= 0) or -1. Per S, side
// and parity (0 on S): 3 * 2 * 4 face types, 3 * 4 * 2 edge types, 8 corner types.
//   Mirror: the leaves read the mirrored grid, weakly balanced, paired and symmetric under
//   the reflections across the planes of S; so the configurations are the symmetric ones of
//   all 8 octants, forcing uses all 8 leaves, and a status is one with its mirror images.
//   Coarse: only the inside leaves exist; a cell outside the root is not fine and no
//   implication into it holds.
// The star is built from the inside leaves' pieces only. Computed by dualhex, not certified.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/checkers/compositional_boundary.hpp"
#include "dualhex/checkers/compositional_weak_stars.hpp"

namespace dualhex {

struct WeakRootStarCheck {
    std::string rule, policy;
    std::array<long, 3> types{};  ///< per k = 1, 2, 3: (S, sides, parity) types run
    std::array<long, 3> pairs{}, stars{}, empty{}, passed{}, failed{};  ///< per k
    long search_nodes = 0;
    int max_free = 0;  ///< max over pairs: free statuses (variables of the search)
    std::vector<std::string> failures;  ///< the first few, described
    [[nodiscard]] long total(const std::array<long, 3>& per_k) const { return per_k[0] + per_k[1] + per_k[2]; }
    [[nodiscard]] bool all_passed() const {
        return total(stars) > 0 && total(failed) == 0 && total(passed) == total(stars);
    }
};

/// A star as enumerated: the type, v (relative to g), level - m per sign octant (outside
/// octants: their mirror's under Mirror, -1 under Coarse), the inside leaves (level, cell)
/// with their pieces (-1: no cell at v), and the star as built (v at the origin; null if no
/// leaf has a cell at v or the rule threw).
struct WeakRootStar {
    RootSides sides{};
    std::array<int, 3> parity{};
    LatticePoint v;
    std::array<int, 8> levels{};
    std::vector<std::pair<int, std::array<std::int64_t, 3>>> leaves;
    std::vector<int> pieces;
    const CellComplex* complex = nullptr;
};

struct WeakRootStarOptions {
    unsigned planes = 0b111;  ///< bit k - 1: run the types on k root planes
    long search_limit = 5'000'000;  ///< beyond it at one pair the pair fails (never passes)
    long stop_after = 0;  ///< stop once this many stars failed (0: never)
    /// A wrong policy (tests): `Coarse`, but a cell outside the root reads fine to the leaves
    /// (level - m, cell index in level cells) this accepts, so readers can disagree about it.
    std::function<bool(int, const std::array<std::int64_t, 3>&)> outside_fine_for;
    /// Optional: told every distinct star, built, before it is checked (from several threads).
    std::function<void(const WeakRootStar&)> stars;
};

/// Runs it for `Coarse`, `Mirror` or `AnyOutside` (the inside leaves as under `Coarse`, but
/// each outside cell a free status of its own: every policy that is a function of the
/// outside cell; the weak rule fails there, proofs/README.md W13 (g)) (oneTBB over the
/// candidate vertices).
[[nodiscard]] WeakRootStarCheck run_weak_root_stars(const TransitionRule& rule, const ElementLibrary& library,
                                                    const WeakStarInfluence& influence, BoundaryPolicy policy,
                                                    const WeakRootStarOptions& options = {});

}  // namespace dualhex

namespace dualhex {

/// `Coarse` near the root surface (proofs/README.md W13 (f)): the vertices v whose leaves'
/// enumeration names a cell beyond a root plane not through v. Per (v, configuration) and
/// per choice of root planes through v (none: v inside the root; else as in
/// run_weak_root_stars), each further root plane (an even level-m coordinate within
/// `reach` level-m units of g, v strictly inside it) that makes some named cell outside;
/// then every combination of those. Planes that name no outside cell change nothing (the
/// run is then the one without them). Checked: the interior checks of W9 (vi) when no plane
/// passes through v, B1-B5 otherwise.
struct WeakNearRootStarCheck {
    std::string rule;
    std::array<long, 4> combinations{};  ///< by planes through v (0..3): plane sets run
    long unchanged = 0;  ///< (pair, plane) tried that named no outside cell (skipped)
    long stars = 0, empty = 0, passed = 0, failed = 0, search_nodes = 0, corner_pairs = 0;
    long hits_at_reach = 0;  ///< planes at the end of the reach that named an outside cell (must be 0)
    std::vector<std::string> failures;
    [[nodiscard]] bool all_passed() const { return stars > 0 && failed == 0 && passed == stars && hits_at_reach == 0; }
};

/// What names one star of the near-surface run; labels sort member by member.
struct WeakNearRootStarLabel {
    int parity = 0;               ///< t: g = (t&1, t>>1&1, t>>2&1) level-m units
    LatticePoint v;               ///< relative to g
    std::array<int, 8> levels{};  ///< level - m per sign octant
    RootSides sides{};            ///< the root planes through v (0 on an axis: none)
    /// The further root planes, per axis below v (the root above) and above v (the root below).
    std::array<std::optional<std::int64_t>, 3> below, above;
    std::vector<int> pieces;  ///< per inside leaf (-1: no cell at v)
    auto operator<=>(const WeakNearRootStarLabel&) const = default;
};

struct WeakNearRootStarOptions {
    unsigned parities = 0xFF;
    int max_planes = 3;  ///< at most this many root planes not through v in one combination
    int reach = 8;  ///< level-m units either side of g where a plane is tried
    long search_limit = 5'000'000;
    long stop_after = 0;
    /// Optional: told every star that passes, with its label and its complex (the inside
    /// leaves' whole cells at v, v at the origin). Called from several threads at once.
    std::function<void(const WeakNearRootStarLabel&, const CellComplex&)> passed;
};

[[nodiscard]] WeakNearRootStarCheck run_weak_near_root_stars(const TransitionRule& rule, const ElementLibrary& library,
                                                             const WeakStarInfluence& influence,
                                                             const WeakNearRootStarOptions& options = {});

}  // namespace dualhex
