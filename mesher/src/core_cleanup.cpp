// Core cleanup before the pad (core_cleanup.hpp).
#include "dualhex/mesher/core_cleanup.hpp"

#include <algorithm>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/core_topology.hpp"

namespace dualhex::mesher {
namespace {

// Per hex and face: the hex across that face, -1 on the mesh's outside (faces by sorted ids).
std::vector<std::array<int, 6>> face_neighbours(const std::vector<std::array<int, 8>>& cells) {
    struct FaceUse {
        std::array<int, 4> key;
        int hex, face;
    };
    std::vector<FaceUse> uses;
    uses.reserve(cells.size() * 6);
    for (std::size_t h = 0; h < cells.size(); ++h)
        for (int f = 0; f < 6; ++f) {
            std::array<int, 4> k{};
            for (std::size_t i = 0; i < 4; ++i) k[i] = cells[h][static_cast<std::size_t>(geometry::kHexFaces[f][i])];
            std::sort(k.begin(), k.end());
            uses.push_back({k, static_cast<int>(h), f});
        }
    std::sort(uses.begin(), uses.end(), [](const FaceUse& a, const FaceUse& b) {
        return a.key < b.key || (a.key == b.key && a.hex < b.hex);
    });
    std::vector<std::array<int, 6>> out(cells.size());
    for (auto& n : out) n.fill(-1);
    for (std::size_t i = 1; i < uses.size(); ++i)
        if (uses[i].key == uses[i - 1].key) {
            out[static_cast<std::size_t>(uses[i].hex)][static_cast<std::size_t>(uses[i].face)] = uses[i - 1].hex;
            out[static_cast<std::size_t>(uses[i - 1].hex)][static_cast<std::size_t>(uses[i - 1].face)] = uses[i].hex;
        }
    return out;
}

// Bit f: face f of hex h lies on the other side of the selection from h.
unsigned other_side_faces(const std::array<int, 6>& across, const std::vector<char>& in, std::size_t h) {
    unsigned bits = 0;
    for (std::size_t f = 0; f < 6; ++f) {
        const bool neighbour_in = across[f] >= 0 && in[static_cast<std::size_t>(across[f])];
        if (neighbour_in != static_cast<bool>(in[h])) bits |= 1u << f;
    }
    return bits;
}

}  // namespace

bool exposed_faces(unsigned other) {
    const int n = __builtin_popcount(other & 63u);
    if (n >= 4) return true;
    if (n != 3) return false;
    // kHexFaces: 0/1 bottom/top, 2/4 and 3/5 the opposite sides.
    constexpr std::array<unsigned, 3> kOpposite{(1u << 0) | (1u << 1), (1u << 2) | (1u << 4), (1u << 3) | (1u << 5)};
    return std::any_of(kOpposite.begin(), kOpposite.end(), [&](unsigned pair) { return (other & pair) == pair; });
}

CoreCleanup clean_core(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count, const std::vector<char>& in,
                       const std::vector<char>& flippable) {
    const std::vector<std::array<int, 6>> across = face_neighbours(cells);
    SelectionFlips flips(cells, vertex_count, in);
    std::vector<char> flipped(cells.size(), 0);
    // Only hexes exposed in the given selection may flip, and those a flip leaves with 5 or
    // 6 faces out (a spike): following every hex a flip exposes would erode a plate one hex
    // thick from its rim down to one hex.
    std::vector<char> candidate(cells.size(), 0);
    for (std::size_t h = 0; h < cells.size(); ++h)
        candidate[h] = flippable[h] && exposed_faces(other_side_faces(across[h], in, h));
    CoreCleanup out;
    // Each sweep fills notches first, then removes what still sticks out: a hex beside a
    // notch is not removed as a one-hex wall when the notch can be filled.
    for (bool changed = true; changed;) {
        changed = false;
        ++out.sweeps;
        for (const bool adding : {true, false})
            for (std::size_t h = 0; h < cells.size(); ++h) {
                const bool core = flips.in()[h] != 0;
                if (flipped[h] || core == adding || !flippable[h]) continue;
                const unsigned other = other_side_faces(across[h], flips.in(), h);
                if (!exposed_faces(other) || !(candidate[h] || __builtin_popcount(other) >= 5)) continue;
                if (!flips.simple(static_cast<int>(h))) continue;
                flips.flip(static_cast<int>(h));
                flipped[h] = 1;
                (core ? out.removed : out.added) += 1;
                changed = true;
            }
    }
    for (std::size_t h = 0; h < cells.size(); ++h) {
        const unsigned other = other_side_faces(across[h], flips.in(), h);
        if (!flipped[h] && flippable[h] && exposed_faces(other) && (candidate[h] || __builtin_popcount(other) >= 5))
            ++out.refused;
    }
    out.in = flips.in();
    return out;
}

}  // namespace dualhex::mesher
