#pragma once
// Shared by the checkers tests: a pinned copy of F.element as committed in a825e13 (the
// derivation is rewriting schemes/elements in the working tree; these tests exercise the
// checkers, not the current state of the derivation), written to a temporary directory.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dualhex/schemes/placement.hpp"

namespace dualhex::testing {

inline constexpr const char* kFlatElement = R"(# pinned copy of schemes/elements/F.element (a825e13)
dualhex-element 1
name F
leaf 12
vertex 0 0 0 0
vertex 1 0 0 6
vertex 2 0 3 0
vertex 3 6 3 0
vertex 4 6 0 6
vertex 5 6 0 0
vertex 6 12 6 0
vertex 7 12 0 6
vertex 8 12 0 0
vertex 9 0 6 0
vertex 10 0 0 12
vertex 11 6 0 12
vertex 12 0 6 12
vertex 13 0 12 12
vertex 14 12 12 12
vertex 15 12 12 0
vertex 16 0 12 0
vertex 17 12 0 12
cell p1
face 0 1 2
face 3 4 5
face 0 5 4 1
face 2 3 5 0
face 1 4 3 2
end
cell p2
face 5 4 3
face 6 7 8
face 5 8 7 4
face 3 6 8 5
face 4 7 6 3
end
cell q
face 9 3 2
face 10 11 12
face 1 10 12 9 2
face 2 3 4 1
face 1 4 11 10
face 12 11 4 3 9
end
cell lid
face 13 14 15 16
face 6 15 14 17 7
face 11 17 14 13 12
face 12 13 16 9
face 16 15 6 3 9
face 4 7 17 11
face 3 6 7 4
face 9 3 4 11 12
end
)";

/// A fresh directory holding only F.element (removed by the caller when done).
inline std::filesystem::path write_flat_element_dir(const std::string& tag) {
    const auto dir = std::filesystem::temp_directory_path() / ("dualhex_checkers_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "F.element") << kFlatElement;
    return dir;
}

/// F in the right leaves, but with x and z swapped (a reflection that keeps the leaf box)
/// where d_x = -1: the two sides of each plane x = const through application points
/// disagree on the crossing, so installations must fail.
class SwappedCrossingRule : public TransitionRule {
public:
    std::optional<Placement> place(const LeafContext& ctx) const override {
        auto p = FlatOnlyRule().place(ctx);
        if (p && ctx.direction[0] < 0) p->symmetry = CubeSymmetry({2, 1, 0}, {1, 1, 1});
        return p;
    }
};

}  // namespace dualhex::testing
