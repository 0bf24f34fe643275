// grid_bench: times the grid layer on a random octree refined towards a sphere.
//
//   grid_bench [depth=8] [seed=1]
//
// The octree: cells crossing the sphere |p - (1/2,1/2,1/2)| = 0.3 are split down to
// `depth`; elsewhere cells split at random (probability 1/8, down to depth - 3), so the
// input is neither balanced nor paired. All geometry is exact integer arithmetic at the
// finest level. Prints one row per operation: leaves in, leaves out, seconds.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "dualhex/grid/grid_complex.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"

using namespace dualhex;

namespace {

// Does the cell's box cross the sphere? Squared distances in units of 2^-(depth+1).
bool crosses_sphere(const Leaf& cell, int depth) {
    const LeafBox box = box_at(cell, depth);
    const std::int64_t c = std::int64_t{1} << depth;              // centre, doubled units
    const std::int64_t r = (std::int64_t{6} << depth) / 10;       // 0.3, doubled units
    std::int64_t near = 0, far = 0;
    for (int a = 0; a < 3; ++a) {
        const std::int64_t lo = 2 * box.lo[a] - c, hi = 2 * box.hi[a] - c;
        const std::int64_t n = lo > 0 ? lo : (hi < 0 ? -hi : 0);
        const std::int64_t f = std::max(lo < 0 ? -lo : lo, hi < 0 ? -hi : hi);
        near += n * n;
        far += f * f;
    }
    return near <= r * r && r * r <= far;
}

std::vector<Leaf> random_octree(int depth, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Leaf> leaves, stack{Leaf{}};
    while (!stack.empty()) {
        const Leaf cell = stack.back();
        stack.pop_back();
        const bool split = cell.level < depth &&
                           (crosses_sphere(cell, depth) || (cell.level < depth - 3 && rng() % 8 == 0));
        if (!split) {
            leaves.push_back(cell);
            continue;
        }
        for (const Leaf& c : children(cell)) stack.push_back(c);
    }
    return leaves;
}

template <class F>
double seconds(F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void row(const char* what, std::size_t in, std::size_t out, double s) {
    std::printf("%-34s %10zu %10zu %9.3f\n", what, in, out, s);
}

}  // namespace

int main(int argc, char** argv) {
    const int depth = argc > 1 ? std::atoi(argv[1]) : 8;
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    std::printf("%-34s %10s %10s %9s\n", "operation", "in", "out", "seconds");

    std::vector<Leaf> raw;
    double t = seconds([&] { raw = random_octree(depth, seed); });
    row(("generate depth " + std::to_string(depth)).c_str(), 0, raw.size(), t);
    std::optional<LeafGrid> grid;
    t = seconds([&] { grid.emplace(std::move(raw)); });
    row("LeafGrid (validate tiling)", grid->size(), grid->size(), t);

    for (const Balance mode : {Balance::Strong, Balance::Weak}) {
        const char* name = mode == Balance::Strong ? "strong" : "weak";
        LeafGrid out;
        t = seconds([&] { out = balance(*grid, mode); });
        row((std::string("balance(") + name + ")").c_str(), grid->size(), out.size(), t);
        t = seconds([&] { (void)is_balanced(out, mode); });
        row((std::string("is_balanced(") + name + ")").c_str(), out.size(), out.size(), t);
        LeafGrid paired;
        t = seconds([&] { paired = pair(*grid, mode); });
        row((std::string("pair(") + name + ") incl. balancing").c_str(), grid->size(), paired.size(), t);
        t = seconds([&] { (void)is_paired(paired); });
        row("is_paired", paired.size(), paired.size(), t);
    }

    const std::int64_t n = 64;  // a 64^3 box of level-6 leaves
    const auto box = leaf_box(6, {0, 0, 0}, {n, n, n});
    std::size_t cells = 0;
    t = seconds([&] { cells = leaves_to_complex(box).n_cells(); });
    row("box 64^3 -> CellComplex", box.size(), cells, t);

    const auto shared = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_strong_d7.leaves";
    if (std::filesystem::exists(shared)) {
        std::size_t count = 0;
        t = seconds([&] { count = read_leaf_file(shared).size(); });
        row("read sphere_strong_d7.leaves", count, count, t);
    }
    return 0;
}
