#include "dualhex/grid/neighbours.hpp"

namespace dualhex {

namespace {

constexpr std::array<Offset, 6> kFaces{{{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}}};

constexpr std::array<Offset, 26> all_directions() {
    std::array<Offset, 26> out{};
    int n = 0;
    // Faces first, then edges, then vertices: a diagnostic then names the largest contact.
    for (int order = 1; order <= 3; ++order)
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (Offset{dx, dy, dz}.order() == order) out[static_cast<std::size_t>(n++)] = {dx, dy, dz};
    return out;
}

constexpr std::array<Offset, 26> kAll = all_directions();

}  // namespace

std::span<const Offset> neighbour_offsets(Balance mode) {
    if (mode == Balance::Weak) return kFaces;
    return kAll;
}

const char* contact_name(const Offset& d) {
    switch (d.order()) {
        case 1: return "face";
        case 2: return "edge";
        default: return "vertex";
    }
}

}  // namespace dualhex
