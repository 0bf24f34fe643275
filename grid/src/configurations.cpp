#include "dualhex/grid/configurations.hpp"

#include <bit>

namespace dualhex {

int octant_bit(int sx, int sy, int sz) { return (sx > 0 ? 1 : 0) | (sy > 0 ? 2 : 0) | (sz > 0 ? 4 : 0); }

LatticePoint octant_signs(int bit) { return {bit & 1 ? 1 : -1, bit & 2 ? 1 : -1, bit & 4 ? 1 : -1}; }

ConfigMask apply(const CubeSymmetry& s, ConfigMask mask) {
    unsigned out = 0;
    for (int b = 0; b < 8; ++b) {
        if (!(mask >> b & 1)) continue;
        const LatticePoint p = s.apply(octant_signs(b));
        out |= 1u << octant_bit(static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(p.z));
    }
    return static_cast<ConfigMask>(out);
}

int fine_count(ConfigMask mask) { return std::popcount(static_cast<unsigned>(mask)); }

std::vector<CubeSymmetry> group_elements(SymmetryGroup group) {
    std::vector<CubeSymmetry> out;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        const auto s = CubeSymmetry::from_index(i);
        if (group == SymmetryGroup::Full || s.is_rotation()) out.push_back(s);
    }
    return out;
}

// Masks are visited in increasing order, so the first unclassified mask is the smallest
// of its orbit; sweeping the group over it finds the whole orbit and, for each member m
// = g(rep), the element g^-1 taking m back to the representative.
ConfigurationSpace::ConfigurationSpace(SymmetryGroup group)
    : group_(group), class_of_(kConfigurationCount, -1), to_rep_(kConfigurationCount) {
    const auto elements = group_elements(group);
    for (int m = 0; m < kConfigurationCount; ++m) {
        if (class_of_[m] >= 0) continue;
        const auto rep = static_cast<ConfigMask>(m);
        const int index = static_cast<int>(classes_.size());
        ConfigurationClass cls{rep, 0, fine_count(rep)};
        for (const auto& g : elements) {
            const ConfigMask image = apply(g, rep);
            if (class_of_[image] >= 0) continue;
            class_of_[image] = index;
            to_rep_[image] = g.inverse();
            ++cls.size;
        }
        classes_.push_back(cls);
    }
}

int ConfigurationSpace::transition_count() const {
    int n = 0;
    for (const auto& c : classes_)
        if (c.representative != 0 && c.representative != 255) ++n;
    return n;
}

}  // namespace dualhex
