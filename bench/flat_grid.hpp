#pragma once
// The generated flat grid of the install benchmarks: root refined to level `base`, the half
// y < 1/2 to base + 1 (paired, strongly balanced, flat transitions only; 9 * 8^base / 2
// leaves: 18,432 for base 4, 1.18M for 6, 9.4M for 7).
#include <vector>

#include "dualhex/grid/leaf_grid.hpp"

namespace dualhex::bench {

inline LeafGrid flat_grid(int base) {
    std::vector<Leaf> leaves;
    const std::int64_t n = std::int64_t{1} << base;
    for (std::int64_t i = 0; i < n; ++i)
        for (std::int64_t j = 0; j < n; ++j)
            for (std::int64_t k = 0; k < n; ++k) {
                const Leaf c{base, i, j, k};
                if (2 * j < n) {
                    for (const Leaf& ch : children(c)) leaves.push_back(ch);
                } else {
                    leaves.push_back(c);
                }
            }
    return LeafGrid(std::move(leaves));
}

}  // namespace dualhex::bench
