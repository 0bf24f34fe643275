#include "surface_parse.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

namespace dualhex::geometry::detail {

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
}  // namespace

std::string quoted(std::string_view text) {
    constexpr std::size_t kMax = 60;
    std::string out = "'";
    for (std::size_t i = 0; i < text.size() && i < kMax; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\') {
            out += static_cast<char>(c);
        } else {
            static const char* hex = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    if (text.size() > kMax) out += "...";
    return out + "'";
}

bool LineCursor::next(std::string_view& line) {
    if (pos_ >= bytes_.size()) return false;
    std::size_t eol = bytes_.find('\n', pos_);
    if (eol == std::string_view::npos) eol = bytes_.size();
    line = bytes_.substr(pos_, eol - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = eol + 1 > bytes_.size() ? bytes_.size() : eol + 1;
    ++line_;
    return true;
}

bool LineCursor::next_content(std::string_view& line) {
    while (next(line)) {
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        while (!line.empty() && is_space(line.front())) line.remove_prefix(1);
        while (!line.empty() && is_space(line.back())) line.remove_suffix(1);
        if (!line.empty()) return true;
    }
    return false;
}

void LineCursor::fail(const std::string& message) const { throw SurfaceError(source_, line_, message); }

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t p = 0;
    while (p < line.size()) {
        while (p < line.size() && is_space(line[p])) ++p;
        if (p == line.size()) break;
        std::size_t q = p;
        while (q < line.size() && !is_space(line[q])) ++q;
        out.push_back(line.substr(p, q - p));
        p = q;
    }
    return out;
}

namespace {
// std::from_chars takes neither '+' nor hex without chars_format::hex, and with
// chars_format::general it accepts "nan"/"inf": those are refused by the finiteness check.
bool parse_double(std::string_view token, double& v) {
    const char* first = token.data();
    const char* last = first + token.size();
    if (first != last && *first == '+') {  // "+1.5" is decimal; "++1" and "+-1" are not
        ++first;
        if (first != last && (*first == '+' || *first == '-')) return false;
    }
    if (first == last) return false;
    const auto [end, ec] = std::from_chars(first, last, v, std::chars_format::general);
    return ec == std::errc() && end == last && std::isfinite(v);
}
}  // namespace

double parse_coordinate(std::string_view token, const LineCursor& cursor, const char* what) {
    double v = 0;
    if (!parse_double(token, v)) cursor.fail(std::string("not a finite decimal number (") + what + "), " + quoted(token));
    if (std::fabs(v) > kMaxCoordinate)
        cursor.fail(std::string(what) + " beyond +-1e100, " + quoted(token));
    return v;
}

void check_number(std::string_view token, const LineCursor& cursor, const char* what) {
    double v = 0;
    if (!parse_double(token, v)) cursor.fail(std::string("not a finite decimal number (") + what + "), " + quoted(token));
}

std::int64_t parse_integer(std::string_view token, const LineCursor& cursor, const char* what) {
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec == std::errc::result_out_of_range) cursor.fail(std::string(what) + " out of range, " + quoted(token));
    if (ec != std::errc() || end != token.data() + token.size())
        cursor.fail(std::string("not a decimal integer (") + what + "), " + quoted(token));
    return v;
}

std::size_t PointWelder::Hash::operator()(const std::array<double, 3>& p) const {
    std::size_t h = 0;
    for (double x : p) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ULL + (h >> 29);
    }
    return h;
}

int PointWelder::id(const Eigen::Vector3d& p) {
    // + 0.0 turns -0 into +0, so equal values get equal keys (and equal hashes).
    const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    const auto [it, inserted] = ids_.try_emplace(key, static_cast<int>(soup_.points.size()));
    if (inserted) soup_.points.emplace_back(key[0], key[1], key[2]);
    return it->second;
}

}  // namespace dualhex::geometry::detail
