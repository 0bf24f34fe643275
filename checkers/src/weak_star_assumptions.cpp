// The star run's assumptions tested on a real grid (weak_star_assumptions.hpp): the
// configuration at v, the forced statuses and the implications, against f computed from
// the grid's leaves.
#include "dualhex/checkers/weak_star_assumptions.hpp"

#include <set>
#include <sstream>

#include "weak_star_leaves.hpp"

namespace dualhex {
namespace {

namespace ws = weak_stars;

// Units: a level-D cell (D the grid's finest level) is U; a level-l cell U * 2^(D - l).
class RealStatuses {
public:
    RealStatuses(const LeafGrid& grid, std::int64_t unit) : grid_(grid), unit_(unit), depth_(grid.max_level()) {}
    int depth() const { return depth_; }
    bool inside(const Leaf& c) const { return c.level >= 0 && c.valid(); }
    // f(c): c subdivided and so are all its children
    bool fine(const Leaf& c) const {
        if (!grid_.is_subdivided(c)) return false;
        for (const Leaf& child : children(c))
            if (!grid_.is_subdivided(child)) return false;
        return true;
    }
    // The leaf holding v + s * eps, if inside the root.
    std::optional<Leaf> leaf_toward(const LatticePoint& v, int s) const {
        const ws::Index3 c = ws::cell_toward(v, s, unit_);
        const Leaf cell{depth_, c[0], c[1], c[2]};
        if (!cell.valid()) return std::nullopt;
        const auto n = grid_.locate(cell);
        if (!n) return std::nullopt;
        return grid_.leaf(*n);
    }

private:
    const LeafGrid& grid_;
    std::int64_t unit_;
    int depth_;
};

// Every element position of every stride-th leaf, in level-D units U.
std::set<LatticePoint> points_of(const LeafGrid& grid, const WeakStarInfluence& inf, std::size_t stride) {
    std::set<LatticePoint> out;
    const int depth = grid.max_level();
    for (std::size_t n = 0; n < grid.size(); n += stride) {
        const Leaf& leaf = grid.leaf(n);
        const LeafContext frame = ws::frame_of({leaf.i, leaf.j, leaf.k});
        for (const auto& info : inf.positions) {
            LatticePoint w;
            for (int a = 0; a < 3; ++a)
                w[a] = (frame.application_point[a] * inf.unit + frame.direction[static_cast<std::size_t>(a)] * info.position[a])
                       << (depth - leaf.level);
            out.insert(w);
        }
    }
    return out;
}

Leaf real_cell(int m, const ws::Status& x) { return Leaf{m + x.first, x.second[0], x.second[1], x.second[2]}; }

std::vector<ws::Status> implied_fine(const ws::Status& x, WeakStarRuleMutation mutation) {
    const auto direct = ws::fine_implies(x);
    std::vector<ws::Status> out(direct.begin(), direct.end());
    if (mutation == WeakStarRuleMutation::ImpliesChildFine) out.push_back({x.first + 1, {2 * x.second[0], 2 * x.second[1], 2 * x.second[2]}});
    return out;
}

class Checker {
public:
    Checker(const LeafGrid& grid, const WeakStarInfluence& inf, WeakStarRuleMutation mutation)
        : real_(grid, inf.unit), inf_(inf), mutation_(mutation) {
        for (std::size_t q = 0; q < inf.positions.size(); ++q) index_[inf.positions[q].position] = q;
    }
    void at(const LatticePoint& v);
    WeakStarAssumptionReport report;

private:
    void violation(const std::string& what) {
        if (++report.violated <= 10) report.violations.push_back(what);
    }
    void check_chain(int m, const ws::Status& x, const std::string& where);

    RealStatuses real_;
    const WeakStarInfluence& inf_;
    WeakStarRuleMutation mutation_;
    std::map<LatticePoint, std::size_t> index_;
};

void Checker::at(const LatticePoint& v) {
    std::array<Leaf, 8> leaves{};
    for (int s = 0; s < 8; ++s) {
        const auto leaf = real_.leaf_toward(v, s);
        if (!leaf) return;  // on the root surface
        leaves[static_cast<std::size_t>(s)] = *leaf;
    }
    int m = leaves[0].level, top = m;
    for (const Leaf& l : leaves) m = std::min(m, l.level), top = std::max(top, l.level);
    std::ostringstream where;
    where << "v=" << v << " (level-" << real_.depth() << " units of " << inf_.unit << ")";
    if (top > m + ws::kFinest) return violation(where.str() + ": more than 4 levels at v (W3)");
    // v in units where a level-(m+3) cell is U
    const int shift = real_.depth() - (m + ws::kFinest);
    LatticePoint local = v;
    for (int a = 0; a < 3; ++a) {
        if (shift > 0 && v[a] % (std::int64_t{1} << shift) != 0) return violation(where.str() + ": off the level-(m+3) lattice");
        local[a] = shift > 0 ? v[a] >> shift : v[a] << -shift;
    }
    ++report.vertices;
    std::array<int, 8> level{};
    std::array<ws::Leaf, 8> mine{};
    for (std::size_t s = 0; s < 8; ++s) {
        level[s] = leaves[s].level - m;
        mine[s] = {level[s], {leaves[s].i, leaves[s].j, leaves[s].k}};
    }
    bool found = false;
    ws::Configurations(local, inf_.unit).each([&](const std::array<int, 8>& l, const auto&) { found = found || l == level; });
    if (!found) violation(where.str() + ": its configuration is not enumerated (W9 ii)");
    ws::Forcing forced(mine, mutation_ == WeakStarRuleMutation::OneLevelFinerForcesFine);
    std::set<std::pair<int, ws::Index3>> distinct;
    for (const ws::Leaf& leaf : mine) {
        if (leaf.level == ws::kFinest || !distinct.insert({leaf.level, leaf.cell}).second) continue;
        for (const auto& [bit, x] : ws::leaf_at(inf_, index_, local, leaf).reads) {
            const Leaf cell = real_cell(m, x);
            if (!real_.inside(cell)) continue;
            ++report.statuses;
            const bool truth = real_.fine(cell);
            if (const auto f = forced(x)) {
                ++report.forced;
                if (*f != truth) violation(where.str() + ": f(" + to_string(cell) + ") is " + std::to_string(truth) + ", taken as forced " + std::to_string(*f) + " (W9 iv)");
            }
            if (truth) check_chain(m, x, where.str());
        }
    }
}

// Every status a chain of implications from the fine x names is fine (W9 v).
void Checker::check_chain(int m, const ws::Status& x, const std::string& where) {
    std::set<ws::Status> reached, frontier{x};
    while (!frontier.empty()) {
        std::set<ws::Status> next;
        for (const ws::Status& y : frontier)
            for (const ws::Status& z : implied_fine(y, mutation_)) {
                const Leaf cell = real_cell(m, z);
                if (!real_.inside(cell) || !reached.insert(z).second) continue;
                ++report.implications;
                if (real_.fine(cell)) next.insert(z);
                else violation(where + ": f(" + to_string(real_cell(m, x)) + ") = 1 but f(" + to_string(cell) + ") = 0 (W9 v)");
            }
        frontier = std::move(next);
    }
}

}  // namespace

WeakStarAssumptionReport check_weak_star_assumptions(const LeafGrid& grid, const WeakStarInfluence& influence, std::size_t stride,
                                                     WeakStarRuleMutation mutation) {
    Checker checker(grid, influence, mutation);
    for (const LatticePoint& v : points_of(grid, influence, std::max<std::size_t>(stride, 1))) checker.at(v);
    return checker.report;
}

}  // namespace dualhex
