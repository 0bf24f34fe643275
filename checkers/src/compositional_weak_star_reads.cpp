// The joint reads of a vertex's star, relevant bits only, per leaf configuration at the
// vertex (compositional_weak_stars.hpp, weak_star_reads; proofs/README.md W7).
#include <cmath>

#include "weak_star_leaves.hpp"

namespace dualhex {

using namespace weak_stars;

std::vector<WeakStarReads> weak_star_reads(const WeakStarInfluence& inf) {
    std::map<LatticePoint, std::size_t> index;
    for (std::size_t q = 0; q < inf.positions.size(); ++q) index[inf.positions[q].position] = q;
    const std::int64_t half = cell_size(inf.unit, 0) / 2;
    std::vector<WeakStarReads> out;
    for (int t = 0; t < 8; ++t) {
        WeakStarReads r;
        r.parity = {t & 1, (t >> 1) & 1, (t >> 2) & 1};
        const LatticePoint g = LatticePoint{r.parity[0], r.parity[1], r.parity[2]} * cell_size(inf.unit, 0);
        for (const LatticePoint& v : candidates(inf, g, half)) {
            ++r.vertices;
            Configurations(v, inf.unit).each([&](const std::array<int, 8>& level, const std::array<Leaf, 8>& leaves) {
                ++r.configurations;
                std::map<Status, int> readers;
                Forcing forced(leaves);
                std::set<std::pair<int, Index3>> distinct;  // a leaf spanning several s counts once
                for (const Leaf& leaf : leaves) {
                    if (!distinct.insert({leaf.level, leaf.cell}).second) continue;
                    std::set<Status> mine;
                    for (const auto& [bit, x] : leaf_at(inf, index, v, leaf).reads)
                        if (!forced(x)) mine.insert(x);
                    for (const Status& x : mine) ++readers[x];
                }
                const int shared = static_cast<int>(std::count_if(readers.begin(), readers.end(), [](const auto& e) { return e.second > 1; }));
                ++r.shared_histogram[shared];
                r.joint += std::ldexp(1.0, shared);
                r.max_free = std::max(r.max_free, static_cast<int>(readers.size()));
                r.max_leaves = std::max(r.max_leaves, static_cast<int>(distinct.size()));
                if (shared > r.max_shared || r.configurations == 1) r.max_shared = shared, r.worst = v - g, r.worst_levels = level;
            });
        }
        out.push_back(r);
    }
    return out;
}

}  // namespace dualhex
