#pragma once
// Shared helpers for the geometry tests: a per-test temporary directory and small
// surfaces written as text files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "dualhex/geometry/surface.hpp"

namespace geometry_test {

/// A fresh directory under the system temp dir, removed at destruction.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path = std::filesystem::temp_directory_path() /
               ("dualhex_geometry_" + std::to_string(::getpid()) + "_" + (info ? info->name() : "x"));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    [[nodiscard]] std::string file(const std::string& name) const { return (path / name).string(); }
};

/// The message read_surface(path) throws (the error must name `path`); a test failure and
/// "" if the file is accepted.
inline std::string error_of(const std::string& path) {
    try {
        (void)dualhex::geometry::read_surface(path);
    } catch (const dualhex::geometry::SurfaceError& e) {
        EXPECT_EQ(e.file(), path);
        return e.what();
    }
    ADD_FAILURE() << path << " was accepted";
    return {};
}

inline std::string write_text(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

/// The unit cube [0,1]^3 as 12 outward triangles.
inline dualhex::geometry::TriangleSurface unit_cube_surface(double lo = 0.0, double hi = 1.0) {
    dualhex::geometry::TriangleSurface s;
    for (int v = 0; v < 8; ++v) s.vertices.emplace_back(v & 1 ? hi : lo, v & 2 ? hi : lo, v & 4 ? hi : lo);
    s.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return s;
}

/// OFF text of a surface, optionally leaving out triangle `skip`.
inline std::string off_text(const dualhex::geometry::TriangleSurface& s, int skip = -1) {
    std::string out = "OFF\n" + std::to_string(s.vertices.size()) + ' ' +
                      std::to_string(s.triangles.size() - (skip >= 0 ? 1 : 0)) + " 0\n";
    for (const auto& p : s.vertices)
        out += std::to_string(p.x()) + ' ' + std::to_string(p.y()) + ' ' + std::to_string(p.z()) + '\n';
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
        if (static_cast<int>(t) != skip)
            out += "3 " + std::to_string(s.triangles[t][0]) + ' ' + std::to_string(s.triangles[t][1]) + ' ' +
                   std::to_string(s.triangles[t][2]) + '\n';
    return out;
}

inline std::string shared_surface(const std::string& name) {
    return std::string(DUALHEX_SHARED_DATA) + "/surfaces/" + name;
}

}  // namespace geometry_test
