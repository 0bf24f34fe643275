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

/// Runs it for `Coarse` or `Mirror` (oneTBB over the candidate vertices).
[[nodiscard]] WeakRootStarCheck run_weak_root_stars(const TransitionRule& rule, const ElementLibrary& library,
                                                    const WeakStarInfluence& influence, BoundaryPolicy policy,
                                                    const WeakRootStarOptions& options = {});

}  // namespace dualhex
