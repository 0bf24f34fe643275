#pragma once
// The 256 two-level configurations around an application point and their classes.
//
// A configuration is an 8-bit mask: bit b is the octant-sized cube on the side
// (b&1 ? +x : -x, b&2 ? +y : -y, b&4 ? +z : -z) of the application point; a set bit
// means that cube is fine (split once more), a clear bit coarse.
//
// Classes are orbits under a group of cube symmetries, computed by enumeration here
// (never tabulated): 22 under all 48 symmetries (20 without all-coarse / all-fine),
// 23 under the 24 rotations.
#include <cstdint>
#include <vector>

#include "dualhex/topology/cube_symmetry.hpp"

namespace dualhex {

using ConfigMask = std::uint8_t;
inline constexpr int kConfigurationCount = 256;

/// Octant bit of a sign vector (each component +1 or -1) and back.
[[nodiscard]] int octant_bit(int sx, int sy, int sz);
[[nodiscard]] LatticePoint octant_signs(int bit);

/// The configuration seen after moving space by `s` (about the application point):
/// the cube at octant b goes to the octant of s(signs(b)).
[[nodiscard]] ConfigMask apply(const CubeSymmetry& s, ConfigMask mask);

/// Number of fine octants (set bits).
[[nodiscard]] int fine_count(ConfigMask mask);

enum class SymmetryGroup { Full /* 48 */, Rotations /* 24 */ };

/// The elements of the group, identity first.
[[nodiscard]] std::vector<CubeSymmetry> group_elements(SymmetryGroup group);

struct ConfigurationClass {
    ConfigMask representative = 0;  ///< smallest mask in the orbit
    int size = 0;                   ///< orbit size
    int fine = 0;                   ///< fine octants of every member
};

/// The classification of all 256 masks under a group. Classes are ordered by representative.
class ConfigurationSpace {
public:
    explicit ConfigurationSpace(SymmetryGroup group);

    [[nodiscard]] const std::vector<ConfigurationClass>& classes() const { return classes_; }
    /// Classes other than all-coarse (mask 0) and all-fine (mask 255).
    [[nodiscard]] int transition_count() const;
    [[nodiscard]] int class_of(ConfigMask mask) const { return class_of_[mask]; }
    /// A group element g with apply(g, mask) == representative of mask's class.
    [[nodiscard]] const CubeSymmetry& to_representative(ConfigMask mask) const { return to_rep_[mask]; }
    [[nodiscard]] SymmetryGroup group() const { return group_; }

private:
    SymmetryGroup group_;
    std::vector<ConfigurationClass> classes_;
    std::vector<int> class_of_;
    std::vector<CubeSymmetry> to_rep_;
};

}  // namespace dualhex
