#pragma once
// mesh_quality: a small, independent reader of legacy ASCII VTK unstructured grids made
// of hexahedra only (VTK_HEXAHEDRON = 12). Deliberately not the geometry layer's code:
// the benchmark measures the pipeline's output with its own eyes.
//
// Accepts: "# vtk DataFile Version ...", a title line, ASCII, DATASET UNSTRUCTURED_GRID,
// then POINTS n <type>, CELLS n size (each cell "8 i0 ... i7"), CELL_TYPES n (all 12);
// anything after (POINT_DATA, CELL_DATA, ...) is ignored.
// Errors: std::runtime_error "<file>:<line>: <message>" for a wrong header, a count that
// the file cannot hold, a non-hex cell, an id out of range, a bad number, a short file.
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesh_quality {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

struct HexGrid {
    std::vector<Vec3> points;
    std::vector<std::array<std::int64_t, 8>> hexes;
};

// Whitespace-separated tokens with the line each starts on.
class Tokens {
public:
    Tokens(std::string path) : path_(std::move(path)), in_(path_) {
        if (!in_) throw std::runtime_error(path_ + ": cannot open");
        in_.seekg(0, std::ios::end);
        bytes_ = static_cast<std::uint64_t>(in_.tellg());
        in_.seekg(0);
    }
    [[nodiscard]] std::uint64_t bytes() const { return bytes_; }
    [[nodiscard]] int line() const { return line_; }
    [[nodiscard]] std::runtime_error error(const std::string& message, int line = 0) const {
        return std::runtime_error(path_ + ":" + std::to_string(line > 0 ? line : line_) + ": " + message);
    }
    std::string next_line() {  // the rest of the current line, or the next one
        std::string s;
        if (!std::getline(in_, s)) throw error("unexpected end of file");
        ++line_;
        return s;
    }
    bool next(std::string& token) {
        token.clear();
        int c;
        while ((c = in_.get()) != EOF && std::isspace(c))
            if (c == '\n') ++line_;
        if (c == EOF) return false;
        do token.push_back(static_cast<char>(c));
        while ((c = in_.get()) != EOF && !std::isspace(c));
        if (c == '\n') in_.unget();
        return true;
    }
    std::string word(const char* what) {
        std::string t;
        if (!next(t)) throw error(std::string("unexpected end of file, expected ") + what);
        return t;
    }
    std::int64_t integer(const char* what) {
        const std::string t = word(what);
        std::size_t used = 0;
        std::int64_t v = 0;
        try {
            v = std::stoll(t, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != t.size() || t.empty()) throw error(std::string("expected ") + what + ", got '" + t + "'");
        return v;
    }
    double real(const char* what) {
        const std::string t = word(what);
        std::size_t used = 0;
        double v = 0;
        try {
            v = std::stod(t, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != t.size() || !std::isfinite(v)) throw error(std::string("expected ") + what + ", got '" + t + "'");
        return v;
    }
    // A count that the rest of the file can hold with `tokens_each` tokens per item.
    std::int64_t count(const char* what, int tokens_each) {
        const std::int64_t n = integer(what);
        if (n < 0 || static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(2 * tokens_each) > bytes_ + 2)
            throw error(std::string(what) + " " + std::to_string(n) + " does not fit in a file of " +
                        std::to_string(bytes_) + " bytes");
        return n;
    }

private:
    std::string path_;
    std::ifstream in_;
    std::uint64_t bytes_ = 0;
    int line_ = 1;
};

inline HexGrid read_vtk_hexes(const std::string& path) {
    Tokens in(path);
    if (in.next_line().rfind("# vtk DataFile", 0) != 0) throw in.error("not a legacy VTK file", 1);
    (void)in.next_line();  // title
    std::string format = in.next_line();
    if (format.rfind("ASCII", 0) != 0) throw in.error("only ASCII VTK is read, got '" + format + "'", 3);
    if (in.word("DATASET") != "DATASET" || in.word("UNSTRUCTURED_GRID") != "UNSTRUCTURED_GRID")
        throw in.error("expected DATASET UNSTRUCTURED_GRID");
    HexGrid g;
    if (in.word("POINTS") != "POINTS") throw in.error("expected POINTS");
    g.points.resize(static_cast<std::size_t>(in.count("point count", 3)));
    (void)in.word("point type");
    for (auto& p : g.points) p = {in.real("x"), in.real("y"), in.real("z")};
    if (in.word("CELLS") != "CELLS") throw in.error("expected CELLS");
    const std::int64_t cells = in.count("cell count", 9);
    (void)in.integer("cell list size");
    g.hexes.resize(static_cast<std::size_t>(cells));
    for (std::int64_t c = 0; c < cells; ++c) {
        if (in.integer("corner count") != 8)
            throw in.error("cell " + std::to_string(c) + " is not a hexahedron (not 8 corners)");
        for (auto& v : g.hexes[static_cast<std::size_t>(c)]) {
            v = in.integer("point id");
            if (v < 0 || v >= static_cast<std::int64_t>(g.points.size()))
                throw in.error("cell " + std::to_string(c) + ": point id " + std::to_string(v) + " out of range");
        }
    }
    if (in.word("CELL_TYPES") != "CELL_TYPES") throw in.error("expected CELL_TYPES");
    if (in.integer("cell type count") != cells) throw in.error("CELL_TYPES count differs from CELLS");
    for (std::int64_t c = 0; c < cells; ++c)
        if (in.integer("cell type") != 12)
            throw in.error("cell " + std::to_string(c) + " has a cell type other than 12 (VTK_HEXAHEDRON)");
    return g;
}

}  // namespace mesh_quality
