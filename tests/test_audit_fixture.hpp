#pragma once
// Hand-made meshes for the audit tests, written to a per-test temp directory: VTK legacy
// text with any cells, polyhedral complexes from groups of unit lattice cubes (each group
// one cell: the outward unit quads of its boundary), and a minimal base64 encoder for VTU
// binary arrays.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "dualhex/topology/complex_builder.hpp"

namespace audit_test {

namespace fs = std::filesystem;

class TempDir : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("dualhex_audit_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path(name), std::ios::binary) << text;
        return path(name);
    }
    fs::path dir_;
};

/// A VTK legacy ASCII file with these points and cells (each cell: type, CELLS row).
struct VtkCell {
    int type;
    std::vector<long> row;  ///< the CELLS row after its count
};
inline std::string vtk_text(const std::vector<std::array<double, 3>>& points, const std::vector<VtkCell>& cells) {
    std::string s = "# vtk DataFile Version 4.2\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " +
                    std::to_string(points.size()) + " double\n";
    for (const auto& p : points) s += std::to_string(p[0]) + ' ' + std::to_string(p[1]) + ' ' + std::to_string(p[2]) + '\n';
    std::size_t size = 0;
    for (const auto& c : cells) size += 1 + c.row.size();
    s += "CELLS " + std::to_string(cells.size()) + ' ' + std::to_string(size) + '\n';
    for (const auto& c : cells) {
        s += std::to_string(c.row.size());
        for (long v : c.row) s += ' ' + std::to_string(v);
        s += '\n';
    }
    s += "CELL_TYPES " + std::to_string(cells.size()) + '\n';
    for (const auto& c : cells) s += std::to_string(c.type) + '\n';
    return s;
}

using Cube = std::array<int, 3>;  ///< the unit cube [x, x+1] x [y, y+1] x [z, z+1]

/// One cell per group of unit cubes: the group's boundary unit quads, outward.
inline dualhex::CellComplex complex_of_cube_groups(const std::vector<std::vector<Cube>>& groups) {
    using dualhex::LatticePoint;
    dualhex::ComplexBuilder b;
    for (const auto& group : groups) {
        const std::set<Cube> in(group.begin(), group.end());
        std::vector<std::vector<LatticePoint>> loops;
        for (const Cube& c : group)
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    Cube n = c;
                    n[static_cast<std::size_t>(axis)] += side == 0 ? -1 : 1;
                    if (in.count(n) != 0) continue;  // shared inside the group
                    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                    LatticePoint o{c[0], c[1], c[2]};
                    o[axis] += side;
                    LatticePoint du{}, dv{};
                    du[u] = 1;
                    dv[v] = 1;
                    // (u, v, axis) is right-handed: o, o+du, o+du+dv, o+dv has normal +axis
                    std::vector<LatticePoint> loop{o, o + du, o + du + dv, o + dv};
                    if (side == 0) std::swap(loop[1], loop[3]);
                    loops.push_back(loop);
                }
        b.add_cell_from_loops(loops);
    }
    return b.build();
}

/// Every unit cube of [0, n)^3, one group each.
inline std::vector<std::vector<Cube>> unit_cubes(int n) {
    std::vector<std::vector<Cube>> g;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) g.push_back({{x, y, z}});
    return g;
}

/// Removes the single-cube groups of `cubes` and adds them as one group.
inline void merge(std::vector<std::vector<Cube>>& groups, const std::vector<Cube>& cubes) {
    std::erase_if(groups, [&](const std::vector<Cube>& g) {
        return g.size() == 1 && std::find(cubes.begin(), cubes.end(), g[0]) != cubes.end();
    });
    groups.push_back(cubes);
}

inline std::string base64(const std::string& bytes) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k[v & 63] : '=';
    }
    return out;
}

/// Little-endian bytes of integral values of `Int` (for VTU binary arrays).
template <class Int, class Range>
std::string le_bytes(const Range& values) {
    std::string s;
    for (auto v : values) {
        const auto u = static_cast<std::uint64_t>(static_cast<Int>(v));
        for (std::size_t b = 0; b < sizeof(Int); ++b) s += static_cast<char>((u >> (8 * b)) & 0xff);
    }
    return s;
}

}  // namespace audit_test
