// Strict PLY reader: ASCII, binary little- and big-endian. The header must declare every
// property inside an element and end with "end_header"; each element's count is checked
// against the bytes left (its smallest encoding) before anything is reserved. "vertex"
// needs scalar x, y, z; "face" needs a list vertex_indices (or vertex_index); other
// elements and properties are read and skipped. Every read is bounds-checked.
#include <cmath>
#include <cstring>

#include "surface_parse.hpp"

namespace dualhex::geometry::detail {

namespace {

struct ScalarType {
    std::string_view name, alias;
    int size;
    bool is_float, is_signed;
};
constexpr ScalarType kTypes[] = {
    {"char", "int8", 1, false, true},     {"uchar", "uint8", 1, false, false},  {"short", "int16", 2, false, true},
    {"ushort", "uint16", 2, false, false}, {"int", "int32", 4, false, true},    {"uint", "uint32", 4, false, false},
    {"float", "float32", 4, true, true},  {"double", "float64", 8, true, true},
};

struct Property {
    std::string name;
    const ScalarType* type = nullptr;
    const ScalarType* count_type = nullptr;  // non-null: a list
};

struct Element {
    std::string name;
    std::int64_t count = 0;
    std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
};

const ScalarType* scalar_type(std::string_view name, const LineCursor& cur) {
    for (const auto& t : kTypes)
        if (name == t.name || name == t.alias) return &t;
    cur.fail("unknown PLY property type " + quoted(name));
}

void read_header_line(const std::vector<std::string_view>& f, const LineCursor& cur, Header& h, bool& have_format) {
    if (f[0] == "comment" || f[0] == "obj_info") return;
    if (f[0] == "format") {
        if (f.size() != 3 || f[2] != "1.0") cur.fail("expected 'format <type> 1.0'");
        if (f[1] == "ascii") h.format = Format::Ascii;
        else if (f[1] == "binary_little_endian") h.format = Format::BinaryLittle;
        else if (f[1] == "binary_big_endian") h.format = Format::BinaryBig;
        else cur.fail("unknown PLY format " + quoted(f[1]));
        have_format = true;
    } else if (f[0] == "element") {
        if (f.size() != 3) cur.fail("expected 'element <name> <count>'");
        const std::int64_t n = parse_integer(f[2], cur, "element count");
        if (n < 0) cur.fail("negative element count, " + quoted(f[2]));
        h.elements.push_back({std::string(f[1]), n, {}});
    } else if (f[0] == "property") {
        if (h.elements.empty()) cur.fail("'property' before any 'element'");
        Property p;
        if (f.size() == 5 && f[1] == "list") {
            p.count_type = scalar_type(f[2], cur);
            p.type = scalar_type(f[3], cur);
            if (p.count_type->is_float) cur.fail("list count type must be an integer type, " + quoted(f[2]));
            p.name = f[4];
        } else if (f.size() == 3) {
            p.type = scalar_type(f[1], cur);
            p.name = f[2];
        } else {
            cur.fail("expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
        }
        h.elements.back().properties.push_back(std::move(p));
    } else {
        cur.fail("unknown PLY header line " + quoted(f[0]));
    }
}

// The fewest bytes one instance of `e` can take: the bound its count is checked against.
std::int64_t min_bytes(const Element& e, Format format) {
    std::int64_t n = 0;
    for (const auto& p : e.properties)
        n += format == Format::Ascii ? 2 : (p.count_type ? p.count_type->size : p.type->size);
    return n;
}

Header read_header(LineCursor& cur) {
    std::string_view line;
    if (!cur.next(line) || line != "ply") cur.fail("expected 'ply' as the first line");
    Header h;
    bool have_format = false, ended = false;
    while (!ended && cur.next(line)) {
        const auto f = split_fields(line);
        if (f.empty()) cur.fail("blank line in the PLY header");
        if (f[0] == "end_header") ended = f.size() == 1;
        else read_header_line(f, cur, h, have_format);
        if (f[0] == "end_header" && !ended) cur.fail("expected 'end_header'");
    }
    if (!ended) cur.fail("PLY header without 'end_header'");
    if (!have_format) cur.fail("PLY header without 'format'");
    std::int64_t left = static_cast<std::int64_t>(cur.remaining());
    for (const auto& e : h.elements) {
        const std::int64_t size = std::max<std::int64_t>(min_bytes(e, h.format), 1);
        if (e.count > left / size)
            cur.fail("element '" + e.name + "' count " + std::to_string(e.count) + " exceeds what the file can hold");
        left -= e.count * size;
    }
    return h;
}

// One element's values in file order, from ASCII lines or binary records.
class ValueSource {
public:
    ValueSource(LineCursor& cur, std::string_view bytes, Format format) : cur_(cur), bytes_(bytes), format_(format) {
        pos_ = cur.offset();
    }
    void begin(const Element& e, std::int64_t i) {
        where_ = e.name + " " + std::to_string(i);
        if (format_ != Format::Ascii) return;
        std::string_view line;
        if (!cur_.next(line)) cur_.fail("file ends before " + where_);
        fields_ = split_fields(line);
        field_ = 0;
    }
    void end() {
        if (format_ == Format::Ascii && field_ != fields_.size())
            cur_.fail(where_ + ": " + std::to_string(fields_.size() - field_) + " extra values");
    }
    double coordinate(const ScalarType& t) { return value(t, true, "coordinate"); }
    std::int64_t integer(const ScalarType& t, const char* what) {
        if (t.is_float) fail(std::string(what) + " has a floating-point type");
        return static_cast<std::int64_t>(value(t, false, what));
    }
    void skip(const ScalarType& t) { (void)value(t, false, "value"); }
    [[noreturn]] void fail(const std::string& m) const {
        if (format_ == Format::Ascii) cur_.fail(where_ + ": " + m);
        throw SurfaceError(cur_.source(), where_ + " at byte " + std::to_string(pos_) + ": " + m);
    }

private:
    double value(const ScalarType& t, bool is_coordinate, const char* what) {
        if (format_ == Format::Ascii) {
            if (field_ >= fields_.size()) fail(std::string("missing ") + what);
            const std::string_view token = fields_[field_++];
            if (is_coordinate) return parse_coordinate(token, cur_, "coordinate");
            if (!t.is_float) return static_cast<double>(parse_integer(token, cur_, what));
            check_number(token, cur_, what);
            return 0;
        }
        if (bytes_.size() - pos_ < static_cast<std::size_t>(t.size)) fail(std::string("file ends inside the ") + what);
        std::uint64_t bits = 0;
        for (int b = 0; b < t.size; ++b) {
            const int at = format_ == Format::BinaryLittle ? t.size - 1 - b : b;
            bits = (bits << 8) | static_cast<unsigned char>(bytes_[pos_ + static_cast<std::size_t>(at)]);
        }
        pos_ += static_cast<std::size_t>(t.size);
        return decode(t, bits, is_coordinate);
    }
    double decode(const ScalarType& t, std::uint64_t bits, bool is_coordinate) const {
        double v = 0;
        if (t.is_float && t.size == 4) {
            float f = 0;
            const auto b32 = static_cast<std::uint32_t>(bits);
            std::memcpy(&f, &b32, sizeof f);
            v = f;
        } else if (t.is_float) {
            std::memcpy(&v, &bits, sizeof v);
        } else if (t.is_signed) {
            const int shift = 64 - 8 * t.size;
            v = static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
        } else {
            v = static_cast<double>(bits);
        }
        if (!std::isfinite(v)) fail("value is not finite");
        if (is_coordinate && std::fabs(v) > kMaxCoordinate) fail("coordinate beyond +-1e100");
        return v;
    }

    LineCursor& cur_;
    std::string_view bytes_;
    Format format_;
    std::size_t pos_ = 0;
    std::string where_;
    std::vector<std::string_view> fields_;
    std::size_t field_ = 0;
};

bool is_xyz(const std::string& n) { return n == "x" || n == "y" || n == "z"; }
bool is_index_list(const Property& p) {
    return p.count_type && (p.name == "vertex_indices" || p.name == "vertex_index");
}

void check_elements(const Header& h, const LineCursor& cur) {
    bool vertices_seen = false;
    for (const auto& e : h.elements) {
        if (e.name == "vertex") {
            int xyz = 0;
            for (const auto& p : e.properties) xyz += is_xyz(p.name) && !p.count_type ? 1 : 0;
            if (xyz != 3) cur.fail("PLY element 'vertex' needs scalar properties x, y and z (once each)");
            vertices_seen = true;
        } else if (e.name == "face") {
            int lists = 0;
            for (const auto& p : e.properties) lists += is_index_list(p) ? 1 : 0;
            if (lists != 1) cur.fail("PLY element 'face' needs one list property 'vertex_indices'");
            if (!vertices_seen) cur.fail("PLY element 'face' before element 'vertex'");
        }
    }
}

void read_element(const Element& e, ValueSource& in, PolygonSoup& soup) {
    std::vector<std::int64_t> ids;
    for (std::int64_t i = 0; i < e.count; ++i) {
        in.begin(e, i);
        Eigen::Vector3d p(0, 0, 0);
        for (const auto& prop : e.properties) {
            if (prop.count_type) {
                const std::int64_t n = in.integer(*prop.count_type, "list length");
                if (n < 0) in.fail("negative list length " + std::to_string(n));
                const bool keep = e.name == "face" && is_index_list(prop);
                if (keep) ids.clear();
                for (std::int64_t c = 0; c < n; ++c) {
                    if (keep) ids.push_back(in.integer(*prop.type, "vertex index"));
                    else in.skip(*prop.type);
                }
            } else if (e.name == "vertex" && is_xyz(prop.name)) {
                p[prop.name[0] - 'x'] = in.coordinate(*prop.type);
            } else {
                in.skip(*prop.type);
            }
        }
        in.end();
        if (e.name == "vertex") soup.points.push_back(p);
        if (e.name == "face") add_polygon(soup, ids, [&](const std::string& m) { in.fail(m); });
    }
}

}  // namespace

PolygonSoup read_ply(std::string_view bytes, const std::string& source) {
    LineCursor cur(bytes, source);
    const Header h = read_header(cur);
    check_elements(h, cur);
    PolygonSoup soup;
    for (const auto& e : h.elements)
        if (e.name == "vertex") soup.points.reserve(soup.points.size() + static_cast<std::size_t>(e.count));
    ValueSource in(cur, bytes, h.format);
    for (const auto& e : h.elements) read_element(e, in, soup);
    return soup;
}

}  // namespace dualhex::geometry::detail
