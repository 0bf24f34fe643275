#pragma once
// Exact integer lattice points. Topology is identified by these keys, never by
// floating-point coordinates: two vertices are the same vertex iff their keys are equal.
#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <ostream>

namespace dualhex {

struct LatticePoint {
    std::int64_t x = 0, y = 0, z = 0;

    constexpr std::int64_t operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
    constexpr std::int64_t& operator[](int axis) { return axis == 0 ? x : axis == 1 ? y : z; }
    constexpr auto operator<=>(const LatticePoint&) const = default;

    constexpr LatticePoint operator+(const LatticePoint& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr LatticePoint operator-(const LatticePoint& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr LatticePoint operator*(std::int64_t s) const { return {x * s, y * s, z * s}; }
};

inline std::ostream& operator<<(std::ostream& os, const LatticePoint& p) {
    return os << '(' << p.x << ',' << p.y << ',' << p.z << ')';
}

struct LatticePointHash {
    std::size_t operator()(const LatticePoint& p) const noexcept {
        // splitmix-style mixing of the three coordinates
        auto mix = [](std::uint64_t v) {
            v += 0x9e3779b97f4a7c15ULL;
            v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9ULL;
            v = (v ^ (v >> 27)) * 0x94d049bb133111ebULL;
            return v ^ (v >> 31);
        };
        return mix(static_cast<std::uint64_t>(p.x) ^ mix(static_cast<std::uint64_t>(p.y) ^ mix(static_cast<std::uint64_t>(p.z))));
    }
};

}  // namespace dualhex
