#pragma once
// Union-find over ids 0..n-1 with path halving. The root of a class is its smallest id, so
// which id names a class does not depend on the order of the unions (deterministic output).
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace dualhex::geometry {

struct UnionFind {
    std::vector<std::size_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
    std::size_t find(std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

}  // namespace dualhex::geometry
