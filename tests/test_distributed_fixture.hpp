#pragma once
// Shared by the distributed tests: the serial reference summary of a leaf grid (pair and
// balance it, install with the rule `dualhex install` uses, clipped dual, summarize) and
// random leaf grids.
#include <filesystem>
#include <random>
#include <vector>

#include "dualhex/distributed/canonical.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex::test {

inline InstallResult serial_install(const LeafGrid& paired, Balance b, OutsideRoot outside = OutsideRoot::Coarse) {
    static const auto library = load_default_element_library();
    const InstallOptions options{.outside_root = outside, .balance = b};
    return b == Balance::Strong ? install(paired, StrongRule(), *library, options) : install(paired, WeakRule(), *library, options);
}

inline ClippedDual root_dual(const InstallResult& r, const Incidence& inc) {
    const std::int64_t e = r.unit << r.max_level;
    return clipped_dual(r.complex, inc, {0, 0, 0}, {e, e, e});
}

/// The serial summary of `raw` after the least pairing + balancing (what dualhex-dist builds).
inline CanonicalSummary serial_summary(const LeafGrid& raw, Balance b, OutsideRoot outside = OutsideRoot::Coarse) {
    const InstallResult r = serial_install(pair(raw, b), b, outside);
    const Incidence inc(r.complex);
    return summarize(r, inc, root_dual(r, inc));
}

/// A random octree: the root split, then each cell split with probability p, to max_level.
inline LeafGrid random_grid(unsigned seed, int max_level, double p) {
    std::mt19937 rng(seed);
    std::bernoulli_distribution split(p);
    std::vector<Leaf> leaves, stack{Leaf{}};
    while (!stack.empty()) {
        const Leaf c = stack.back();
        stack.pop_back();
        if (c.level < max_level && (c.level == 0 || split(rng))) {
            for (const Leaf& ch : children(c)) stack.push_back(ch);
        } else {
            leaves.push_back(c);
        }
    }
    return LeafGrid(leaves);
}

}  // namespace dualhex::test
