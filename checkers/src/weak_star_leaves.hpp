#pragma once
// Internal: the leaves at a vertex v near a lattice point g and what their relevant bits
// read (compositional_weak_stars.hpp; shared by weak_star_reads and run_weak_stars).
//
// World units: a level-(m+3) cell is U (the influence table's leaf size), a level-(m+k)
// cell U * 2^(3-k); g = parity (level-m units) sits at 8U * parity. A status f(x) is named
// by (k, x): x a cell of level m + k (k = -1 .. 2) in level-(m+k) cell indices.
#include <algorithm>
#include <array>
#include <bit>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/install/element_templates.hpp"

namespace dualhex::weak_stars {

using detail::Index3;
using Status = std::pair<int, Index3>;

inline constexpr int kFinest = 3;  // level m+3: plain at v (W5)

inline std::int64_t cell_size(std::int64_t unit, int level) { return unit << (kFinest - level); }

inline Index3 ancestor(const Index3& c, int levels_up) {
    const std::int64_t d = std::int64_t{1} << levels_up;
    return {detail::floor_div(c[0], d), detail::floor_div(c[1], d), detail::floor_div(c[2], d)};
}

// The level-`level` cell holding v + s * eps (sign bit a set: +).
inline Index3 cell_toward(const LatticePoint& v, int s, std::int64_t size) {
    Index3 out{};
    for (int a = 0; a < 3; ++a) out[static_cast<std::size_t>(a)] = detail::floor_div((s >> a) & 1 ? v[a] : v[a] - 1, size);
    return out;
}

struct Leaf {
    int level = 0;
    Index3 cell{};
};

// The leaves at v, one per sign octant s (a level per s), over every possible
// configuration: min level m, siblings of a leaf holding v are leaves of its level
// (pairing; it also keeps a leaf from lying inside another), and leaves across a face
// within one level (weak balance: the leaves of s and s' differing on one axis share a
// square at v). Depth-first, each s checked against the earlier ones.
class Configurations {
public:
    Configurations(const LatticePoint& v, std::int64_t unit) {
        for (int l = 0; l <= kFinest; ++l)
            for (int s = 0; s < 8; ++s) cell_[l][s] = cell_toward(v, s, cell_size(unit, l));
    }
    template <class Visit>
    void each(Visit&& visit) {
        std::array<int, 8> level{};
        descend(0, level, visit);
    }

private:
    bool siblings(int l, int s, int t) const { return ancestor(cell_[l][s], 1) == ancestor(cell_[l][t], 1); }
    bool fits(int s, const std::array<int, 8>& level) const {
        const int l = level[static_cast<std::size_t>(s)];
        for (int t = 0; t < s; ++t) {
            const int k = level[static_cast<std::size_t>(t)];
            if (std::popcount(static_cast<unsigned>(s ^ t)) == 1 && std::abs(l - k) > 1) return false;
            if (k != l && (siblings(l, s, t) || siblings(k, s, t))) return false;
        }
        return true;
    }
    template <class Visit>
    void descend(int s, std::array<int, 8>& level, Visit& visit) {
        if (s == 8) {
            if (*std::min_element(level.begin(), level.end()) != 0) return;
            std::array<Leaf, 8> leaves;
            for (int t = 0; t < 8; ++t) {
                const int l = level[static_cast<std::size_t>(t)];
                leaves[static_cast<std::size_t>(t)] = {l, cell_[l][t]};
            }
            visit(level, leaves);
            return;
        }
        for (int l = 0; l <= kFinest; ++l) {
            level[static_cast<std::size_t>(s)] = l;
            if (fits(s, level)) descend(s + 1, level, visit);
        }
    }
    std::array<std::array<Index3, 8>, kFinest + 1> cell_{};
};

// Cell (level, index) as a box in level-(m+3) cells.
inline std::array<std::array<std::int64_t, 2>, 3> box_of(int level, const Index3& c) {
    const std::int64_t n = std::int64_t{1} << (kFinest - level);
    std::array<std::array<std::int64_t, 2>, 3> out{};
    for (std::size_t a = 0; a < 3; ++a) out[a] = {c[a] * n, (c[a] + 1) * n};
    return out;
}

// The closed cells share a square (a face, or part of one): flat on one axis only.
inline bool face_adjacent(int k, const Index3& x, int l, const Index3& c) {
    const auto bx = box_of(k, x), bc = box_of(l, c);
    int flat = 0;
    for (std::size_t a = 0; a < 3; ++a) {
        const std::int64_t lo = std::max(bx[a][0], bc[a][0]), hi = std::min(bx[a][1], bc[a][1]);
        if (lo > hi) return false;
        flat += lo == hi ? 1 : 0;
    }
    return flat == 1;
}

// What f(x) = 1 implies one level up (pairing and weak balance): x's leaves, two levels
// finer than x, run along all of x's faces, so x and each same-level cell across a face of
// x are subdivided, and with them (pairing) their siblings: their parents are fine.
inline std::array<Status, 7> fine_implies(const Status& x) {
    std::array<Status, 7> out{};
    out[0] = {x.first - 1, ancestor(x.second, 1)};
    for (int n = 0; n < 6; ++n) {
        Index3 y = x.second;
        y[static_cast<std::size_t>(n / 2)] += n % 2 ? 1 : -1;
        out[static_cast<std::size_t>(n + 1)] = {x.first - 1, ancestor(y, 1)};
    }
    return out;
}

// f(x) as the configuration forces it, if it does: a leaf at v two or more levels finer
// inside x makes x fine; one a level finer inside x, or one at x's level or coarser
// containing x, makes it not fine (pairing: x's children are leaves; x is not subdivided);
// so does a leaf at v of x's level or coarser across a face of x (a fine x has leaves two
// levels finer than itself all along its faces: weak balance), and a status fine_implies
// names being forced not fine. Memoised per configuration.
class Forcing {
public:
    /// `one_level_finer_forces_fine`: a wrong rule, for the test of check_weak_star_assumptions.
    explicit Forcing(const std::array<Leaf, 8>& leaves, bool one_level_finer_forces_fine = false)
        : leaves_(leaves.begin(), leaves.end()), finer_(one_level_finer_forces_fine ? 1 : 2) {}
    /// On the root surface under `Coarse` (proofs/README.md W13): only the inside leaves
    /// exist, a cell `outside` the root reads not fine, and no implication into it holds, so
    /// the last clause does not look at it.
    /// `outside_free`: the policy is any function of the outside cell (proofs/README.md W13
    /// (g)), so an outside cell is forced neither way: a free status of its own.
    Forcing(std::vector<Leaf> leaves, std::function<bool(const Status&)> outside, bool outside_free = false)
        : leaves_(std::move(leaves)), finer_(2), outside_(std::move(outside)), outside_free_(outside_free) {}
    std::optional<bool> operator()(const Status& x) {
        if (const auto it = memo_.find(x); it != memo_.end()) return it->second;
        const std::optional<bool> f = compute(x);
        memo_.emplace(x, f);
        return f;
    }

private:
    std::optional<bool> compute(const Status& x) {
        const auto& [k, cell] = x;
        if (outside_ && outside_(x)) return outside_free_ ? std::nullopt : std::optional<bool>(false);
        for (const Leaf& leaf : leaves_) {
            if (leaf.level >= k + 1 && ancestor(leaf.cell, leaf.level - k) == cell) return leaf.level >= k + finer_;
            if (leaf.level <= k && ancestor(cell, k - leaf.level) == leaf.cell) return false;
        }
        for (const Leaf& leaf : leaves_)
            if (leaf.level <= k && face_adjacent(k, cell, leaf.level, leaf.cell)) return false;
        if (k > -1)
            for (const Status& up : fine_implies(x))
                if (!(outside_ && outside_(up)))
                    if (const auto f = (*this)(up); f && !*f) return false;
        return std::nullopt;
    }
    const std::vector<Leaf> leaves_;
    const int finer_;
    const std::function<bool(const Status&)> outside_;
    const bool outside_free_ = false;
    std::map<Status, std::optional<bool>> memo_;
};

inline LeafContext frame_of(const Index3& c) {
    return detail::coarse_leaf_context(LatticePoint{c[0], c[1], c[2]}, [](const Index3&) { return false; });
}

// Where v lies in a leaf's frame, in influence-table terms.
struct LeafAtV {
    Leaf leaf;
    LeafContext frame;
    int position = -1;  ///< index into the table's positions; -1: a constant piece at v
    /// The relevant context bits at v (bit index 0..11) and the status each names.
    std::vector<std::pair<int, Status>> reads;
};

// (none for a plain level-(m+3) cube, nor where v is never a vertex of the leaf's element)
inline LeafAtV leaf_at(const WeakStarInfluence& inf, const std::map<LatticePoint, std::size_t>& index,
                       const LatticePoint& v, const Leaf& leaf) {
    LeafAtV out{leaf, frame_of(leaf.cell)};
    if (leaf.level == kFinest) return out;
    const LeafContext& frame = out.frame;
    const std::int64_t size = cell_size(inf.unit, leaf.level);
    LatticePoint q;
    for (int a = 0; a < 3; ++a) {
        const std::int64_t x = frame.direction[static_cast<std::size_t>(a)] * (v[a] - frame.application_point[a] * size) * inf.unit;
        if (x % size != 0) return out;  // not a vertex of the leaf in any context: a constant piece
        q[a] = x / size;
    }
    const auto it = index.find(q);
    if (it == index.end()) return out;
    out.position = static_cast<int>(it->second);
    const std::uint16_t relevant = inf.positions[it->second].relevant;
    for (int i = 0; i < 9; ++i)
        if ((relevant >> i) & 1U) out.reads.push_back({i, {leaf.level - 1, detail::world_octant(frame, inf.octant_bits[static_cast<std::size_t>(i)])}});
    for (int a = 0; a < 3; ++a) {
        if (!((relevant >> (9 + a)) & 1U)) continue;
        Index3 e{};
        for (int u = 0; u < 3; ++u) {
            const int local = u == a ? 0 : -1;
            e[static_cast<std::size_t>(u)] =
                frame.application_point[u] + (frame.direction[static_cast<std::size_t>(u)] > 0 ? local : -local - 1);
        }
        out.reads.push_back({9 + a, {leaf.level, e}});
    }
    return out;
}

// Candidate vertices within 1/2 of g: every element vertex of a level-m..m+2 cell near g in
// its frame, and every corner of a level-(m+3) cell.
inline std::set<LatticePoint> candidates(const WeakStarInfluence& inf, const LatticePoint& g, std::int64_t half) {
    const auto near_g = [&](const LatticePoint& w) {
        for (int a = 0; a < 3; ++a)
            if (w[a] < g[a] - half || w[a] > g[a] + half) return false;
        return true;
    };
    std::set<LatticePoint> out;
    for (std::int64_t x = -half; x <= half; x += inf.unit)
        for (std::int64_t y = -half; y <= half; y += inf.unit)
            for (std::int64_t z = -half; z <= half; z += inf.unit) out.insert(g + LatticePoint{x, y, z});
    for (int level = 0; level < kFinest; ++level) {
        const std::int64_t S = cell_size(inf.unit, level);
        std::array<std::int64_t, 3> lo{}, hi{};  // every cell whose closure meets the box
        for (int a = 0; a < 3; ++a) {
            lo[static_cast<std::size_t>(a)] = detail::floor_div(g[a] - half - 1, S);
            hi[static_cast<std::size_t>(a)] = detail::floor_div(g[a] + half, S);
        }
        std::vector<Index3> cells;
        for (auto x = lo[0]; x <= hi[0]; ++x)
            for (auto y = lo[1]; y <= hi[1]; ++y)
                for (auto z = lo[2]; z <= hi[2]; ++z) cells.push_back({x, y, z});
        for (const Index3& cell : cells) {
            const LeafContext frame = frame_of(cell);
            for (const auto& info : inf.positions) {
                LatticePoint w;
                for (int a = 0; a < 3; ++a)
                    w[a] = frame.application_point[a] * S + frame.direction[static_cast<std::size_t>(a)] * info.position[a] * S / inf.unit;
                if (near_g(w)) out.insert(w);
            }
        }
    }
    return out;
}


}  // namespace dualhex::weak_stars
