#include "dualhex/schemes/element.hpp"

#include <charconv>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "dualhex/topology/complex_builder.hpp"

namespace dualhex {

namespace {

std::string format_what(const std::string& file, int line, const std::string& message) {
    if (file.empty()) return message;
    if (line <= 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ": " + message;
}

bool valid_name(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                        c == '+' || c == '-' || c == '.';
        if (!ok) return false;
    }
    return true;
}

class Parser {
public:
    Parser(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    ElementData run() {
        std::string raw;
        bool have_version = false, in_cell = false;
        int cell_line = 0;
        std::unordered_map<std::int64_t, int> vertex_line;  // id -> declaring line
        std::map<LatticePoint, std::int64_t> position_id;
        std::set<std::string> labels;
        bool have_name = false, have_leaf = false;
        while (std::getline(in_, raw)) {
            ++line_;
            if (auto hash = raw.find('#'); hash != std::string::npos) raw.erase(hash);
            std::istringstream ls(raw);
            std::vector<std::string> tok;
            for (std::string t; ls >> t;) tok.push_back(t);
            if (tok.empty()) continue;
            const std::string& d = tok[0];
            if (!have_version) {
                if (d != "dualhex-element") fail("expected 'dualhex-element <version>' as the first directive, got '" + d + "'");
                expect_args(tok, 1);
                const auto v = integer(tok[1], "format version");
                if (v != kElementFormatVersion)
                    fail("unsupported format version " + tok[1] + " (this build reads version " +
                         std::to_string(kElementFormatVersion) + ")");
                have_version = true;
                continue;
            }
            if (d == "dualhex-element") fail("repeated 'dualhex-element' directive");
            if (d == "name") {
                expect_args(tok, 1);
                if (have_name) fail("repeated 'name' directive");
                if (!valid_name(tok[1])) fail("bad element name '" + tok[1] + "' (allowed: letters, digits, _ + - .)");
                out_.name = tok[1];
                have_name = true;
            } else if (d == "leaf") {
                expect_args(tok, 1);
                if (have_leaf) fail("repeated 'leaf' directive");
                out_.leaf = integer(tok[1], "leaf resolution");
                if (out_.leaf <= 0) fail("leaf resolution must be positive, got " + tok[1]);
                have_leaf = true;
            } else if (d == "vertex") {
                if (!have_name || !have_leaf) fail("'vertex' before 'name' and 'leaf'");
                if (in_cell) fail("'vertex' inside cell '" + out_.cells.back().label + "' (missing 'end'?)");
                expect_args(tok, 4);
                ElementVertex v;
                v.id = integer(tok[1], "vertex id");
                if (v.id < 0) fail("negative vertex id " + tok[1]);
                for (int a = 0; a < 3; ++a) {
                    const auto c = integer(tok[2 + a], "vertex coordinate");
                    if (c < 0 || c > out_.leaf)
                        fail("vertex " + tok[1] + " coordinate " + tok[2 + a] + " outside [0, " +
                             std::to_string(out_.leaf) + "]");
                    v.position[a] = c;
                }
                if (auto it = vertex_line.find(v.id); it != vertex_line.end())
                    fail("duplicate vertex id " + tok[1] + " (first declared on line " + std::to_string(it->second) + ")");
                if (auto it = position_id.find(v.position); it != position_id.end())
                    fail("vertex " + tok[1] + " at the same position as vertex " + std::to_string(it->second));
                vertex_line.emplace(v.id, line_);
                position_id.emplace(v.position, v.id);
                out_.vertices.push_back(v);
            } else if (d == "cell") {
                if (!have_name || !have_leaf) fail("'cell' before 'name' and 'leaf'");
                if (in_cell)
                    fail("cell '" + out_.cells.back().label + "' (line " + std::to_string(cell_line) +
                         ") not closed by 'end' before the next 'cell'");
                expect_args(tok, 1);
                if (!valid_name(tok[1])) fail("bad cell label '" + tok[1] + "'");
                if (!labels.insert(tok[1]).second) fail("duplicate cell label '" + tok[1] + "'");
                out_.cells.push_back({tok[1], {}});
                in_cell = true;
                cell_line = line_;
            } else if (d == "face") {
                if (!in_cell) fail("'face' outside a cell");
                if (tok.size() < 4) fail("face with " + std::to_string(tok.size() - 1) + " vertices (at least 3 needed)");
                std::vector<std::int64_t> loop;
                for (std::size_t i = 1; i < tok.size(); ++i) {
                    const auto id = integer(tok[i], "vertex id");
                    if (!vertex_line.contains(id)) fail("face uses unknown vertex id " + tok[i]);
                    loop.push_back(id);
                }
                out_.cells.back().faces.push_back(std::move(loop));
            } else if (d == "end") {
                expect_args(tok, 0);
                if (!in_cell) fail("'end' without an open cell");
                if (out_.cells.back().faces.empty()) fail("cell '" + out_.cells.back().label + "' has no faces");
                in_cell = false;
            } else {
                fail("unknown directive '" + d + "'");
            }
        }
        if (in_.bad()) fail("read error");
        if (!have_version) fail("empty file: no 'dualhex-element <version>' directive");
        if (in_cell)
            fail("cell '" + out_.cells.back().label + "' (line " + std::to_string(cell_line) +
                 ") not closed by 'end' at end of file");
        if (!have_name) fail("missing 'name' directive");
        if (!have_leaf) fail("missing 'leaf' directive");
        if (out_.cells.empty()) fail("element without cells");
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw SchemeFormatError(file_, line_, message); }

    void expect_args(const std::vector<std::string>& tok, std::size_t n) const {
        if (tok.size() - 1 != n)
            fail("'" + tok[0] + "' takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s") + ", got " +
                 std::to_string(tok.size() - 1));
    }

    std::int64_t integer(const std::string& s, const char* what) const {
        std::int64_t v = 0;
        const char* b = s.data();
        const char* e = b + s.size();
        if (!s.empty() && *b == '+') ++b;
        auto [p, ec] = std::from_chars(b, e, v);
        if (ec != std::errc{} || p != e || b == e) fail(std::string("expected an integer ") + what + ", got '" + s + "'");
        return v;
    }

    std::istream& in_;
    std::string file_;
    int line_ = 0;
    ElementData out_;
};

}  // namespace

SchemeFormatError::SchemeFormatError(std::string file, int line, std::string message)
    : std::runtime_error(format_what(file, line, message)),
      file_(std::move(file)),
      line_(line),
      message_(std::move(message)) {}

ElementData parse_element(std::istream& in, const std::string& file) { return Parser(in, file).run(); }

ElementData parse_element_string(const std::string& text, const std::string& file) {
    std::istringstream in(text);
    return parse_element(in, file);
}

ElementData read_element_file(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw SchemeFormatError(path.string(), 0, "cannot open element file");
    return parse_element(in, path.string());
}

void write_element(std::ostream& out, const ElementData& element, const std::vector<std::string>& comments) {
    out << "# dualhex atomic element (format: schemes/README.md)\n";
    for (const auto& c : comments) out << "# " << c << '\n';
    out << "dualhex-element " << kElementFormatVersion << '\n';
    out << "name " << element.name << '\n';
    out << "leaf " << element.leaf << '\n';
    for (const auto& v : element.vertices)
        out << "vertex " << v.id << ' ' << v.position.x << ' ' << v.position.y << ' ' << v.position.z << '\n';
    for (const auto& c : element.cells) {
        out << "cell " << c.label << '\n';
        for (const auto& f : c.faces) {
            out << "face";
            for (auto id : f) out << ' ' << id;
            out << '\n';
        }
        out << "end\n";
    }
}

std::string element_to_string(const ElementData& element) {
    std::ostringstream os;
    write_element(os, element);
    return os.str();
}

CellComplex to_complex(const ElementData& element) {
    ComplexBuilder builder;
    std::unordered_map<std::int64_t, VertexHandle> handle;
    for (const auto& v : element.vertices) {
        if (handle.contains(v.id))
            throw SchemeFormatError(element.name, 0, "duplicate vertex id " + std::to_string(v.id));
        const auto before = builder.n_vertices();
        const auto h = builder.add_vertex(v.position);
        if (builder.n_vertices() == before)
            throw SchemeFormatError(element.name, 0, "vertex " + std::to_string(v.id) + " shares its position");
        handle.emplace(v.id, h);
    }
    std::vector<VertexHandle> loop;
    std::vector<HalfFaceHandle> halffaces;
    for (const auto& c : element.cells) {
        halffaces.clear();
        for (const auto& f : c.faces) {
            loop.clear();
            for (auto id : f) {
                auto it = handle.find(id);
                if (it == handle.end())
                    throw SchemeFormatError(element.name, 0,
                                            "cell '" + c.label + "': face uses unknown vertex id " + std::to_string(id));
                loop.push_back(it->second);
            }
            if (loop.empty()) throw SchemeFormatError(element.name, 0, "cell '" + c.label + "': empty face");
            halffaces.push_back(builder.add_face(loop));
        }
        builder.add_cell(halffaces);
    }
    return std::move(builder).build();
}

ElementData element_from_complex(const std::string& name, std::int64_t leaf, const CellComplex& complex,
                                 const std::vector<std::string>& labels) {
    ElementData d;
    d.name = name;
    d.leaf = leaf;
    for (std::size_t v = 0; v < complex.n_vertices(); ++v)
        d.vertices.push_back({static_cast<std::int64_t>(v), complex.position(VertexHandle(v))});
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        ElementCell cell;
        if (c < labels.size()) {
            cell.label = labels[c];
        } else {
            cell.label = std::to_string(c);
            cell.label.insert(cell.label.begin(), 'c');
        }
        for (auto h : complex.cell_halffaces(CellHandle(c))) {
            std::vector<std::int64_t> loop;
            for (auto v : complex.halfface_vertices(h)) loop.push_back(v.idx);
            cell.faces.push_back(std::move(loop));
        }
        d.cells.push_back(std::move(cell));
    }
    return d;
}

}  // namespace dualhex
