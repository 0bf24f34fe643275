#include "dualhex/grid/leaf_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>

#include "dualhex/grid/input_error.hpp"

namespace dualhex {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

// Splits on whitespace; returns the field count (fields beyond 5 are not stored).
int split_fields(std::string_view s, std::array<std::string_view, 5>& out) {
    int n = 0;
    std::size_t p = 0;
    while (p < s.size()) {
        while (p < s.size() && is_space(s[p])) ++p;
        if (p == s.size()) break;
        std::size_t q = p;
        while (q < s.size() && !is_space(s[q])) ++q;
        if (n < 5) out[static_cast<std::size_t>(n)] = s.substr(p, q - p);
        ++n;
        p = q;
    }
    return n;
}

std::int64_t parse_integer(std::string_view token, std::string_view text, const std::string& source, int line) {
    std::int64_t v = 0;
    const char* first = token.data();
    // from_chars rejects '+'; allow one before a digit ("+3"), never before a sign ("+-0").
    if (token.size() > 1 && token[0] == '+' && token[1] >= '0' && token[1] <= '9') ++first;
    const auto [end, ec] = std::from_chars(first, token.data() + token.size(), v);
    if (ec == std::errc::result_out_of_range)
        throw InputError(source, line, "integer out of range: '" + std::string(token) + "' in '" + std::string(text) + "'");
    if (ec != std::errc() || end != token.data() + token.size())
        throw InputError(source, line, "not an integer: '" + std::string(token) + "' in '" + std::string(text) + "'");
    return v;
}

// One non-empty, comment-stripped line -> a leaf, range-checked.
Leaf parse_leaf(std::string_view text, const std::string& source, int line) {
    std::array<std::string_view, 5> f;
    const int n = split_fields(text, f);
    if (n != 4)
        throw InputError(source, line, "expected 4 fields 'L i j k', found " + std::to_string(n) + " in '" +
                                           std::string(text) + "'");
    std::array<std::int64_t, 4> v{};
    for (std::size_t t = 0; t < 4; ++t) v[t] = parse_integer(f[t], text, source, line);
    if (v[0] < 0 || v[0] > kMaxLevel)
        throw InputError(source, line, "invalid leaf '" + std::string(text) + "': level " + std::to_string(v[0]) +
                                           " must be in [0, " + std::to_string(kMaxLevel) + "]");
    const Leaf leaf{static_cast<int>(v[0]), v[1], v[2], v[3]};
    if (!leaf.valid())
        throw InputError(source, line, "invalid leaf " + to_string(leaf) + ": coordinates must be in [0, 2^" +
                                           std::to_string(leaf.level) + ")");
    return leaf;
}

}  // namespace

std::optional<Leaf> parse_leaf_line(std::string_view raw, const std::string& source, int line) {
    if (const auto hash = raw.find('#'); hash != std::string_view::npos) raw = raw.substr(0, hash);
    raw = trim(raw);
    if (raw.empty()) return std::nullopt;
    return parse_leaf(raw, source, line);
}

LeafGrid parse_leaves(std::string_view text, const std::string& source) {
    std::vector<Leaf> leaves;
    std::vector<int> lines;
    leaves.reserve(text.size() / 12);
    lines.reserve(text.size() / 12);
    int line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos) eol = text.size();
        const std::string_view content = text.substr(pos, eol - pos);
        pos = eol + 1;
        // Lines are numbered with int (InputError, LeafGrid): refuse rather than overflow.
        if (line == std::numeric_limits<int>::max())
            throw InputError(source, 0, "more than " + std::to_string(line) + " lines");
        ++line;
        const std::optional<Leaf> leaf = parse_leaf_line(content, source, line);
        if (!leaf) continue;
        leaves.push_back(*leaf);
        lines.push_back(line);
    }
    return LeafGrid(std::move(leaves), source, std::move(lines));
}

LeafGrid read_leaf_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    // A FIFO or device (/dev/zero) would block or never end: only regular files are read.
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw InputError(name, 0, "cannot open leaf file: no such file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(name, 0, "not a regular file");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(name, 0, "cannot open leaf file");
    std::string text;
    std::array<char, 1 << 16> buffer{};
    for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), file.get())) > 0;)
        text.append(buffer.data(), got);
    if (std::ferror(file.get())) throw InputError(name, 0, "cannot read leaf file");
    return parse_leaves(text, name);
}

std::string format_leaves(const LeafGrid& grid, std::string_view header) {
    std::string out;
    out.reserve(grid.size() * 16 + header.size() + 16);
    while (!header.empty()) {
        const std::size_t eol = std::min(header.find('\n'), header.size());
        out += "# ";
        out += header.substr(0, eol);
        out += '\n';
        header.remove_prefix(std::min(eol + 1, header.size()));
    }
    std::array<char, 24> num{};
    auto put = [&](std::int64_t v, char sep) {
        const auto res = std::to_chars(num.data(), num.data() + num.size(), v);
        out.append(num.data(), res.ptr);
        out += sep;
    };
    for (const Leaf& l : grid.leaves()) {
        put(l.level, ' ');
        put(l.i, ' ');
        put(l.j, ' ');
        put(l.k, '\n');
    }
    return out;
}

void write_leaf_file(const LeafGrid& grid, const std::filesystem::path& path, std::string_view header) {
    std::ofstream out(path, std::ios::binary);
    const std::string text = format_leaves(grid, header);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out) throw InputError(path.string(), 0, "cannot write leaf file");
}

}  // namespace dualhex
