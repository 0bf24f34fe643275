#pragma once
// Internal: one (vertex, configuration) pair of the star run with its free statuses, and
// the two enumerations of its stars (compositional_weak_star_check.cpp: the product of
// shared and private assignments, the reference; compositional_weak_star_search.cpp: the
// backtracking search over partial assignments, proofs/README.md W9 (vi)-(vii)).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <stdexcept>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"
#include "weak_star_leaves.hpp"

namespace dualhex::weak_stars {

// The star check's filters: v (the origin) is the one vertex given the interior checks; the
// star's faces away from v are its expected rim.
inline bool at_v(const LatticePoint& q) { return q == LatticePoint{}; }
inline bool away_from_v(const CellComplex& cx, std::span<const VertexHandle> loop) {
    return std::none_of(loop.begin(), loop.end(), [&](VertexHandle h) { return at_v(cx.position(h)); });
}

// One leaf at v with its context bits split: forced (a value), shared or private (an index
// into the pair's shared / the leaf's private list).
struct LeafBits {
    LeafAtV at;
    int fixed = 0;  // context bits forced by the configuration
    std::vector<std::pair<int, int>> shared, own;  // (context bit, index)
    int n_own = 0;
    /// "a fine => b fine" between its own statuses or one own and one shared: variable
    /// codes, >= 0 own index, < 0: -1 - shared index.
    std::vector<std::pair<int, int>> implies;
    bool hex_corner = false;  // a plain level-(m+3) cube with a corner at v
};

struct Pair {
    LatticePoint v;  // relative to g
    std::vector<LeafBits> leaves;
    int n_shared = 0;
    std::vector<std::pair<int, int>> implies;  // between shared statuses (indices)
};

// How the statuses read at v relate to the root (proofs/README.md W13); off the root
// surface both are empty and statuses are read as they are.
struct StatusModel {
    /// `Mirror`: x's representative among its images under the reflections across the root
    /// planes through v (the mirrored grid is symmetric under them, so they are one status).
    std::function<Status(const Status&)> canonical;
    /// `Coarse`: x lies outside the root: it reads not fine and no implication into it holds
    /// (nor out of it: the policy's value is no fact about a grid cell).
    std::function<bool(const Status&)> outside;
    /// A wrong policy (tests): what x reads to one leaf if not the forced value (readers may
    /// then disagree about a cell).
    std::function<std::optional<bool>(const Status&, const Leaf& reader)> read;
    [[nodiscard]] Status name(const Status& x) const { return canonical ? canonical(x) : x; }
    [[nodiscard]] bool out(const Status& x) const { return outside && outside(x); }
};

// fine_implies among the free statuses read, closed under chains through statuses not read
// (a fine cell's ancestors are fine, and so on up); under a model, chains run over the
// representatives and stop at a cell outside the root.
inline std::vector<std::pair<Status, Status>> implications(const std::map<Status, std::set<int>>& readers,
                                                           const StatusModel& model = {}) {
    std::vector<std::pair<Status, Status>> out;
    for (const auto& [x, who] : readers) {
        if (model.out(x)) continue;  // an outside cell is the policy's: it implies nothing
        std::set<Status> reached, frontier{x};
        while (!frontier.empty()) {
            std::set<Status> next;
            for (const Status& y : frontier)
                if (y.first > -1)
                    for (const Status& raw : fine_implies(y)) {
                        if (model.out(raw)) continue;
                        const Status z = model.name(raw);
                        if (reached.insert(z).second) next.insert(z);
                    }
            frontier = std::move(next);
        }
        for (const Status& z : reached)
            if (z != x && readers.count(z)) out.push_back({x, z});
    }
    return out;
}

Pair split(const WeakStarInfluence& inf, const std::map<LatticePoint, std::size_t>& index, const LatticePoint& v,
           const LatticePoint& g, const std::array<Leaf, 8>& leaves);
/// The same for the leaves `readers` only (their pieces are the star), statuses forced by
/// `forced` (true facts about the leaves of the whole configuration) and named by `model`.
Pair split(const WeakStarInfluence& inf, const std::map<LatticePoint, std::size_t>& index, const LatticePoint& v,
           const LatticePoint& g, const std::vector<Leaf>& readers, Forcing& forced, const StatusModel& model);

/// The distinct stars of a pair: pieces per leaf -> a witness context per leaf.
using Stars = std::map<std::vector<int>, std::vector<int>>;

/// The reference: every shared assignment satisfying the implications, times each leaf's
/// private ones (`assignments` counts the shared assignments).
Stars stars_by_product(const WeakStarInfluence& inf, const Pair& p, long& assignments);

/// Per position of the influence table, the piece on every subcube of its relevant bits
/// (each bit 0, 1 or open): the piece if it is constant there, else kOpen and the bit to
/// branch on.
struct PieceCubes {
    static constexpr int kOpen = -3;
    struct Position {
        std::vector<int> bits;  // the relevant context bits, ascending
        std::vector<int> piece;  // by ternary index (digit j: bits[j] is 0, 1 or 2 = open)
        std::vector<std::int8_t> branch;  // digit to branch on where piece is kOpen
    };
    std::vector<Position> positions;
};
PieceCubes piece_cubes(const WeakStarInfluence& inf);

/// The same set of stars by a search: leaf by leaf, a leaf's piece fixed as soon as the
/// statuses assigned so far make it constant (so a status it does not read given the others
/// is never branched on), implications propagated on every assignment, and a state (the
/// pieces so far, the assigned statuses the remaining leaves read or are tied to) met
/// before skipped. `nodes` counts the search nodes where a leaf's piece is fixed; over
/// `limit` of them at one pair it throws SearchTooLarge.
struct SearchTooLarge : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// `max_stars` > 0: stop once that many stars are found. `first_pieces`: only the stars whose
/// first leaves have these pieces (the others are not searched).
Stars stars_by_search(const PieceCubes& cubes, const Pair& p, long& nodes, long limit, std::size_t max_stars = 0,
                      const std::vector<int>& first_pieces = {});

/// The star: the cells at v of the leaves' elements (or plain cubes), v at the origin;
/// contexts[n] is leaf n's visible context.
ConfigurationComplex build_star(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                                const Pair& p, const LatticePoint& v_world, const std::vector<int>& contexts);

// W11 (compositional_weak_star_corner.cpp): a corner pair (8 leaves, each with v as a
// corner of its cube) checked leaf by leaf and quadrant by quadrant.

/// The pair with only the leaves `keep` (in that order), every status, shared index and
/// implication kept: its search finds the projections of the pair's stars onto them.
Pair restricted(const Pair& p, const std::vector<std::size_t>& keep);
/// True iff p has 8 leaves, each with v (world) as a corner of its cube.
bool is_corner_pair(const WeakStarInfluence& inf, const Pair& p, const LatticePoint& v_world);
/// P1 on one leaf's piece built alone (v at the origin, `sign` the leaf's octant): the
/// first reason it fails, or nothing.
std::optional<std::string> corner_piece_defect(const CellComplex& cx, const std::array<int, 3>& sign);
/// P2 on two leaves across a quadrant, built together.
std::optional<std::string> corner_quadrant_defect(const CellComplex& cx);

struct CornerCheck {
    long pieces = 0, quadrant_tuples = 0, search_nodes = 0;
    bool passed = false;
    std::string defect;  ///< why not, if not passed
    CornerCheck& fail(std::string why) {
        defect = std::move(why);
        return *this;
    }
};
/// P1 on every piece of every leaf, P2 on every tuple of every quadrant, P3 on one star
/// (searches with `limit` nodes each; SearchTooLarge propagates).
CornerCheck check_corner_pair(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                              const PieceCubes& cubes, const Pair& p, const LatticePoint& v_world, long limit);

/// W14 (f): for every quadrant tuple of a corner pair (octants o < o2 across a quadrant, the
/// two leaves' pieces), one star of the pair with those pieces, found by the search with
/// the two leaves first: tell(o, o2, the two pieces, the star). Returns how many.
long corner_witness_stars(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                          const PieceCubes& cubes, const Pair& p, const LatticePoint& v_world, long limit,
                          const std::function<void(int, int, const std::vector<int>&, const ConfigurationComplex&)>& tell);

}  // namespace dualhex::weak_stars
