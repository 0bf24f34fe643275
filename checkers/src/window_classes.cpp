// Congruence keys of the compositional windows (window_classes.hpp).
#include "window_classes.hpp"

#include <algorithm>

#include "dualhex/schemes/variants.hpp"

namespace dualhex::detail {

PlacementCodes::PlacementCodes(const ElementLibrary& library) {
    int index = 0;
    for (const Element& e : library.elements()) {
        index_.emplace(e.name, index);
        const std::vector<CubeSymmetry> stabiliser = variants::symmetries_mapping(e.complex, e.complex);
        for (int w = 0; w < CubeSymmetry::kOrder; ++w) {
            int best = CubeSymmetry::kOrder;
            for (const CubeSymmetry& S : stabiliser) best = std::min(best, CubeSymmetry::from_index(w).compose(S).index());
            codes_.push_back(index * CubeSymmetry::kOrder + best);
        }
        ++index;
    }
}

namespace {

// compose[i * 48 + j] = index of from_index(i).compose(from_index(j)).
const std::vector<int>& composition_table() {
    static const std::vector<int> table = [] {
        std::vector<int> t;
        for (int i = 0; i < CubeSymmetry::kOrder; ++i)
            for (int j = 0; j < CubeSymmetry::kOrder; ++j)
                t.push_back(CubeSymmetry::from_index(i).compose(CubeSymmetry::from_index(j)).index());
        return t;
    }();
    return table;
}

// A coarse leaf as the keys need it: its box centre about g (twice, so in {-1, 1}^3) and
// its code's element and world symmetry (element -1: a plain hex).
struct KeyedLeaf {
    LatticePoint centre;
    int element = -1;
    int world = 0;
};

std::vector<KeyedLeaf> keyed_leaves(const std::array<int, 3>& parity, const std::vector<PlacedLeaf>& coarse,
                                    const PlacementCodes& codes) {
    const LatticePoint g{parity[0], parity[1], parity[2]};
    std::vector<KeyedLeaf> out;
    for (const PlacedLeaf& leaf : coarse) {
        KeyedLeaf k{(leaf.leaf - g) * 2 + LatticePoint{1, 1, 1}, -1, 0};
        if (leaf.placement) {
            k.element = codes.element_index(leaf.placement->element);
            k.world = world_symmetry(leaf.context, *leaf.placement).index();
        }
        out.push_back(k);
    }
    return out;
}

// The key under symmetry s (index si): a box's image is the box whose centre is the image
// of its centre (s is linear about g); an element's world symmetry W becomes s.W.
WindowKey image_key(const std::vector<KeyedLeaf>& leaves, const CubeSymmetry& s, int si, const PlacementCodes& codes) {
    constexpr int kFine = -1, kHex = -2;
    const std::vector<int>& compose = composition_table();
    WindowKey key;
    key.fill(kFine);  // positions without a coarse leaf hold 8 fine hexes
    for (const KeyedLeaf& leaf : leaves) {
        const LatticePoint c = s.apply(leaf.centre);
        const auto at = static_cast<std::size_t>((c.x > 0) | (c.y > 0) << 1 | (c.z > 0) << 2);
        key[at] = leaf.element < 0
                      ? kHex
                      : codes.code(leaf.element, compose[static_cast<std::size_t>(si * CubeSymmetry::kOrder + leaf.world)]);
    }
    return key;
}

}  // namespace

WindowKey window_image_key(const std::array<int, 3>& parity, const std::vector<PlacedLeaf>& coarse,
                           const CubeSymmetry& s, const PlacementCodes& codes) {
    return image_key(keyed_leaves(parity, coarse, codes), s, s.index(), codes);
}

std::pair<WindowKey, CubeSymmetry> window_class_key(const std::array<int, 3>& parity,
                                                    const std::vector<PlacedLeaf>& coarse, const PlacementCodes& codes) {
    const std::vector<KeyedLeaf> leaves = keyed_leaves(parity, coarse, codes);
    WindowKey best{};
    CubeSymmetry best_s;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        const CubeSymmetry s = CubeSymmetry::from_index(i);
        const WindowKey k = image_key(leaves, s, i, codes);
        if (i == 0 || k < best) best = k, best_s = s;
    }
    return {best, best_s};
}

std::pair<BoundaryWindowKey, CubeSymmetry> boundary_class_key(const std::array<int, 3>& parity,
                                                            const std::array<int, 3>& sides,
                                                            const std::vector<PlacedLeaf>& coarse,
                                                            const PlacementCodes& codes) {
    const std::vector<KeyedLeaf> leaves = keyed_leaves(parity, coarse, codes);
    BoundaryWindowKey best{};
    CubeSymmetry best_s;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        const CubeSymmetry s = CubeSymmetry::from_index(i);
        const LatticePoint side = s.apply({sides[0], sides[1], sides[2]});
        BoundaryWindowKey k{{side.x, side.y, side.z}, image_key(leaves, s, i, codes)};
        if (i == 0 || k < best) best = std::move(k), best_s = s;
    }
    return {best, best_s};
}

}  // namespace dualhex::detail
