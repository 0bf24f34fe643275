// Congruence keys of the compositional windows (window_classes.hpp).
#include "window_classes.hpp"

#include <algorithm>

#include "dualhex/schemes/variants.hpp"

namespace dualhex::detail {
namespace {

constexpr int kFine = -1, kHex = -2;

// Position index of the leaf box with min corner m (window coordinates, leaf units, m in {-1,0}^3).
int position(const std::array<std::int64_t, 3>& m) {
    return static_cast<int>((m[0] + 1) | (m[1] + 1) << 1 | (m[2] + 1) << 2);
}

}  // namespace

PlacementCodes::PlacementCodes(const ElementLibrary& library) {
    int index = 0;
    for (const Element& e : library.elements())
        stabiliser_.emplace(e.name, std::pair{index++, variants::symmetries_mapping(e.complex, e.complex)});
}

int PlacementCodes::code(const std::string& element, const CubeSymmetry& W) const {
    const auto& [index, stabiliser] = stabiliser_.at(element);
    int best = CubeSymmetry::kOrder;
    for (const CubeSymmetry& S : stabiliser) best = std::min(best, W.compose(S).index());
    return index * CubeSymmetry::kOrder + best;
}

WindowKey window_image_key(const std::array<int, 3>& parity, const std::vector<PlacedLeaf>& coarse,
                           const CubeSymmetry& s, const PlacementCodes& codes) {
    const LatticePoint g{parity[0], parity[1], parity[2]};
    WindowKey key;
    key.fill(kFine);  // positions without a coarse leaf hold 8 fine hexes
    for (const PlacedLeaf& leaf : coarse) {
        std::array<std::int64_t, 3> lo{1, 1, 1};  // the image box's min corner (the window is [-1, 1]^3)
        for (int c = 0; c < 8; ++c) {
            const LatticePoint img = s.apply(leaf.leaf - g + LatticePoint{c & 1, (c >> 1) & 1, (c >> 2) & 1});
            for (int a = 0; a < 3; ++a) lo[static_cast<std::size_t>(a)] = std::min(lo[static_cast<std::size_t>(a)], img[a]);
        }
        key[static_cast<std::size_t>(position(lo))] =
            leaf.placement ? codes.code(leaf.placement->element, s.compose(world_symmetry(leaf.context, *leaf.placement)))
                           : kHex;
    }
    return key;
}

std::pair<WindowKey, CubeSymmetry> window_class_key(const std::array<int, 3>& parity,
                                                    const std::vector<PlacedLeaf>& coarse, const PlacementCodes& codes) {
    WindowKey best{};
    CubeSymmetry best_s;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        const CubeSymmetry s = CubeSymmetry::from_index(i);
        const WindowKey k = window_image_key(parity, coarse, s, codes);
        if (i == 0 || k < best) best = k, best_s = s;
    }
    return {best, best_s};
}

}  // namespace dualhex::detail
