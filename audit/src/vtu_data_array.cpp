#include "vtu_data_array.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

#include "dualhex/grid/input_error.hpp"
#include "text_scanner.hpp"

namespace dualhex::audit::detail {
namespace {

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

// Size in bytes of a VTK scalar type, 0 if unknown.
int type_size(const std::string& t) {
    if (t == "Int8" || t == "UInt8") return 1;
    if (t == "Int16" || t == "UInt16") return 2;
    if (t == "Int32" || t == "UInt32" || t == "Float32") return 4;
    if (t == "Int64" || t == "UInt64" || t == "Float64") return 8;
    return 0;
}

std::uint64_t load_le(const unsigned char* p, int size) {
    std::uint64_t v = 0;
    for (int i = size - 1; i >= 0; --i) v = (v << 8) | p[i];
    return v;
}

// One value of type `t` at p, as double or int64 (false: an unsigned value beyond int64).
bool decode_value(const std::string& t, const unsigned char* p, bool as_int, double& real, std::int64_t& integer) {
    const int size = type_size(t);
    const std::uint64_t bits = load_le(p, size);
    if (t == "Float32" || t == "Float64") {
        if (t == "Float32") {
            std::uint32_t b = static_cast<std::uint32_t>(bits);
            float f;
            std::memcpy(&f, &b, 4);
            real = f;
        } else {
            std::memcpy(&real, &bits, 8);
        }
        return std::isfinite(real);
    }
    if (t[0] == 'U') {
        if (bits > static_cast<std::uint64_t>(INT64_MAX)) return false;
        integer = static_cast<std::int64_t>(bits);
    } else {
        const int shift = 64 - 8 * size;  // sign-extend
        integer = static_cast<std::int64_t>(bits << shift) >> shift;
    }
    if (!as_int) real = static_cast<double>(integer);
    return true;
}

// The header and data of the appended block at `offset_text` (false if out of bounds).
bool appended_block(const VtuFileInfo& info, const std::string& offset_text, int header,
                    std::vector<unsigned char>& bytes);

}  // namespace

bool decode_base64(std::string_view text, std::vector<unsigned char>& out) {
    out.clear();
    out.reserve(text.size() / 4 * 3);
    int quad[4], n = 0, pad = 0;
    for (char c : text) {
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
        if (c == '=') {
            if (n < 2) return false;
            quad[n++] = 0;
            ++pad;
        } else {
            const int v = base64_value(c);
            if (v < 0 || pad > 0) return false;
            quad[n++] = v;
        }
        if (n == 4) {
            const unsigned bits = (unsigned(quad[0]) << 18) | (unsigned(quad[1]) << 12) | (unsigned(quad[2]) << 6) | unsigned(quad[3]);
            out.push_back(static_cast<unsigned char>(bits >> 16));
            if (pad < 2) out.push_back(static_cast<unsigned char>(bits >> 8));
            if (pad < 1) out.push_back(static_cast<unsigned char>(bits));
            n = 0;
            pad = 0;  // a further block may follow (VTK encodes header and data separately)
        }
    }
    return n == 0;
}

namespace {
bool appended_block(const VtuFileInfo& info, const std::string& offset_text, int header,
                    std::vector<unsigned char>& bytes) {
    std::uint64_t offset = 0;
    const auto [ptr, ec] = std::from_chars(offset_text.data(), offset_text.data() + offset_text.size(), offset);
    const std::string_view data = info.appended;
    if (offset_text.empty() || ec != std::errc() || ptr != offset_text.data() + offset_text.size() || offset > data.size())
        return false;
    const std::string_view rest = data.substr(static_cast<std::size_t>(offset));
    if (!info.appended_base64) {
        if (rest.size() < static_cast<std::size_t>(header)) return false;
        const std::uint64_t n = load_le(reinterpret_cast<const unsigned char*>(rest.data()), header);
        if (n > rest.size() - static_cast<std::size_t>(header)) return false;
        bytes.assign(rest.begin(), rest.begin() + header + static_cast<std::ptrdiff_t>(n));
        return true;
    }
    // base64: the header's own block (4 chars per 3 bytes), then the data's
    const std::size_t header_chars = (static_cast<std::size_t>(header) + 2) / 3 * 4;
    std::vector<unsigned char> h;
    if (rest.size() < header_chars || !decode_base64(rest.substr(0, header_chars), h) || h.size() < static_cast<std::size_t>(header))
        return false;
    const std::uint64_t n = load_le(h.data(), header);
    const std::uint64_t data_chars = (n + 2) / 3 * 4;
    if (data_chars > rest.size() - header_chars) return false;
    std::vector<unsigned char> d;
    if (!decode_base64(rest.substr(header_chars, static_cast<std::size_t>(data_chars)), d) || d.size() != n) return false;
    bytes.assign(h.begin(), h.begin() + header);
    bytes.insert(bytes.end(), d.begin(), d.end());
    return true;
}
}  // namespace

DataArrayValues read_data_array(XmlScanner& xml, const XmlTag& tag, const VtuFileInfo& info, std::size_t expected,
                                bool as_int, const std::string& what) {
    DataArrayValues v;
    v.tag_line = xml.line_of(tag.begin);
    const auto attr = [&](const char* k) {
        const auto it = tag.attrs.find(k);
        return it == tag.attrs.end() ? std::string() : it->second;
    };
    const std::string type = attr("type"), format = attr("format");
    if (type_size(type) == 0) xml.fail(tag.begin, what + ": unknown DataArray type '" + type + "'");
    if (as_int && (type == "Float32" || type == "Float64"))
        xml.fail(tag.begin, what + ": DataArray type " + type + " (expected an integer type)");
    const std::string_view body = xml.content(tag);
    const bool any_count = expected == kAnyCount;
    if (any_count) expected = 0;
    // Every value takes >= 2 bytes (ascii) or >= 1 byte as base64: checked before allocating.
    if (format != "appended" && expected > body.size()) xml.fail(tag.begin, what + ": " + std::to_string(expected) +
                                                     " values expected, more than the array's " +
                                                     std::to_string(body.size()) + " bytes can hold");
    if (format == "ascii") {
        TextScanner in(xml.path(), body, v.tag_line);
        in.check_count(static_cast<std::int64_t>(expected), 1, what);
        if (as_int) v.ints.resize(expected);
        else v.reals.resize(expected);
        v.lines.resize(expected);
        for (std::size_t i = 0; i < expected; ++i) {
            if (as_int) v.ints[i] = in.read_int(what + " value");
            else v.reals[i] = in.read_double(what + " value");
            v.lines[i] = in.line();
        }
        while (any_count && !in.at_end()) {  // bounded by the body's size
            if (as_int) v.ints.push_back(in.read_int(what + " value"));
            else v.reals.push_back(in.read_double(what + " value"));
            v.lines.push_back(in.line());
        }
        if (!in.at_end()) {
            std::string_view t;
            in.next(t);
            in.fail(what + ": more than the " + std::to_string(expected) + " values expected, at " + quote(t));
        }
        return v;
    }
    const int header = info.header_uint64 ? 8 : 4, size = type_size(type);
    std::vector<unsigned char> bytes;
    if (format == "appended") {
        if (!appended_block(info, attr("offset"), header, bytes))
            xml.fail(tag.begin, what + ": bad appended offset '" + attr("offset") + "' or truncated <AppendedData>");
    } else if (format == "binary") {
        if (!decode_base64(body, bytes)) xml.fail(tag.begin, what + ": invalid base64 data");
    } else {
        xml.fail(tag.begin, what + ": unknown DataArray format '" + format + "'");
    }
    if (bytes.size() < static_cast<std::size_t>(header)) xml.fail(tag.begin, what + ": binary data without its header");
    const std::uint64_t n_bytes = load_le(bytes.data(), header);
    if (any_count && n_bytes % static_cast<std::uint64_t>(size) == 0) expected = n_bytes / static_cast<std::uint64_t>(size);
    if (n_bytes != bytes.size() - static_cast<std::size_t>(header) || n_bytes != expected * static_cast<std::uint64_t>(size))
        xml.fail(tag.begin, what + ": binary header says " + std::to_string(n_bytes) + " bytes, " +
                                std::to_string(bytes.size() - static_cast<std::size_t>(header)) + " present, " +
                                std::to_string(expected * static_cast<std::uint64_t>(size)) + " expected");
    if (as_int) v.ints.resize(expected);
    else v.reals.resize(expected);
    for (std::size_t i = 0; i < expected; ++i) {
        double r = 0;
        std::int64_t k = 0;
        if (!decode_value(type, bytes.data() + header + i * static_cast<std::size_t>(size), as_int, r, k))
            xml.fail(tag.begin, what + ": value " + std::to_string(i) + " is not finite or out of range");
        if (as_int) v.ints[i] = k;
        else v.reals[i] = r;
    }
    return v;
}

}  // namespace dualhex::audit::detail
