// dualhex-proof-checker MANIFEST | --file FILE: the independent checker of dualhex certificates
// (proofs/README.md), standard C++ only. Exit 0 and VERIFIED iff all hold; else 1 (2: usage).
#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <locale>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace {
using std::map, std::pair, std::set, std::size_t, std::string, std::vector;
using i64 = std::int64_t;
__extension__ typedef __int128 i128;  // GCC and Clang
using P3 = std::array<i64, 3>;
using Ids = vector<int>;
using Pairs = vector<pair<int, int>>;
// Coordinates, bounds, periods in [-2^19, 2^19]: cross products < 2^41, areas < 2^47, else i128
constexpr i64 kMaxCoord = i64{1} << 19;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{256} << 20;    // one file
constexpr std::uintmax_t kMaxManifestBytes = std::uintmax_t{1} << 30;  // a manifest's files
constexpr size_t kMaxFace = 64;  // vertices of a face: keeps per-face searches linear
struct Reject { string why; };  // one certificate (or file) is rejected, with the reason
template <class... A> string cat(const A&... parts) {
    std::ostringstream s;
    (s << ... << parts);
    return s.str();
}
template <class... A> [[noreturn]] void fail(const A&... parts) { throw Reject{cat(parts...)}; }
string str(i128 v) {  // in decimal
    return v < 0 ? "-" + str(-v) : (v > 9 ? str(v / 10) : "") + char('0' + int(v % 10));
}
template <class T> int len(const T& v) { return static_cast<int>(v.size()); }
bool connected(size_t n, const Pairs& links) {  // the graph on 0..n-1; union-find
    Ids root(n);
    for (int i = 0; i < len(root); ++i) root[i] = i;
    auto find = [&](int x) {
        while (root[x] != x) x = root[x] = root[root[x]];
        return x;
    };
    for (auto [a, b] : links) root[find(a)] = find(b);
    for (int i = 0; i < len(root); ++i)
        if (find(i) != find(0)) return false;
    return true;
}
struct Line { int number = 0; vector<string> tok; };  // reading: a line's number, its tokens
vector<Line> tokenize(const string& text) {  // non-empty lines, '#' comments removed, split
    vector<Line> out;
    std::istringstream in(text);
    string s;
    for (int n = 1; std::getline(in, s); ++n) {
        std::istringstream words(s.substr(0, s.find('#')));
        out.push_back({n, {}});
        for (string t; words >> t;) out.back().tok.push_back(t);
        if (out.back().tok.empty()) out.pop_back();
    }
    return out;
}
i64 to_int(const string& t, int line, bool coordinate = false) {  // a coordinate: |t| <= 2^19
    i64 v = 0;
    auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size()) fail("line ", line, ": not an integer: ", t);
    if (coordinate && (v < -kMaxCoord || v > kMaxCoord)) fail("line ", line, ": ", t, " outside [-2^19, 2^19]");
    return v;
}
// Ids in [0, bound); a signed one ("+f", "-f": a cell's face) becomes 2f or 2f + 1.
Ids to_ids(const vector<string>& toks, int line, size_t bound, bool sign) {
    Ids out;
    for (const string& t : toks) {
        if (sign && t[0] != '+' && t[0] != '-') fail("line ", line, ": unsigned face ", t);
        const i64 v = to_int(sign ? t.substr(1) : t, line);
        if (v < 0 || static_cast<std::uint64_t>(v) >= bound) fail("line ", line, ": bad id ", t);
        out.push_back(static_cast<int>(sign ? 2 * v + (t[0] == '-') : v));
    }
    return out;
}
struct Cert {
    string name, kind, domain;  // domain: box | torus
    i64 lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // torus: lo 0, hi the period
    vector<P3> pos;
    vector<Ids> faces, cells;  // faces: vertex loops; cells: 2 * face + side (1: loop reversed)
    map<string, vector<string>> claims;
    vector<i64> covers;  // labels (e.g. configuration masks) this certificate stands for
};
// box X0 Y0 Z0 X1 Y1 Z1 | torus P, kept as the box [0, P]^3 (hi: the period) | point X Y Z (lo)
void read_domain(Cert& c, const Line& l) {
    c.domain = l.tok.size() > 1 ? l.tok[1] : "";
    const bool box = c.domain == "box" && l.tok.size() == 8, point = c.domain == "point" && l.tok.size() == 5;
    if (!box && !point && !(c.domain == "torus" && l.tok.size() == 3))
        fail("line ", l.number, ": expected 'domain box X0 Y0 Z0 X1 Y1 Z1', 'torus P' or 'point X Y Z'");
    for (int a = 0; a < 3; ++a) {
        c.lo[a] = box || point ? to_int(l.tok[2 + a], l.number, true) : 0;
        c.hi[a] = point ? c.lo[a] : to_int(l.tok[box ? 5 + a : 2], l.number, true);
        if (!point && c.hi[a] <= c.lo[a]) fail("line ", l.number, ": empty domain on axis ", a);
    }
    if (c.domain == "torus" && c.hi[0] % 2) fail("line ", l.number, ": bad torus period (odd)");
}
// A row (v x y z | f VERTEX-IDS | c SIGNED-FACE-IDS) or a section (given once, `claim` per claim)
void read_line(Cert& c, const Line& l, set<string>& seen) {
    static const set<string> known{"v", "f", "c", "name", "kind", "domain", "claim", "covers"};
    const string& key = l.tok[0];
    const vector<string> args(l.tok.begin() + 1, l.tok.end());
    const string at = cat("line ", l.number, ": ");
    if (!known.count(key)) fail(at, "unknown keyword '", key, "'");
    if (key.size() > 1 && key != "claim" && !seen.insert(key).second) fail(at, "section '", key, "' given twice");
    if (key == "v" && args.size() != 3) fail(at, "expected 'v x y z'");
    if (key == "v") c.pos.push_back({});
    for (int a = 0; a < 3 && key == "v"; ++a) c.pos.back()[a] = to_int(args[a], l.number, true);
    if (key == "f" && args.size() > kMaxFace) fail(at, "more than 64 vertices");
    if (key == "f") c.faces.push_back(to_ids(args, l.number, c.pos.size(), false));
    if (key == "c") c.cells.push_back(to_ids(args, l.number, c.faces.size(), true));
    if ((key == "name" || key == "kind") && args.size() != 1) fail(at, "expected ", key, " WORD");
    if (key == "name" || key == "kind") (key == "name" ? c.name : c.kind) = args[0];
    if (key == "domain") read_domain(c, l);
    if (key == "claim" && (args.empty() || c.claims.count(args[0]))) fail(at, "bad claim");
    if (key == "claim") c.claims[args[0]] = vector<string>(args.begin() + 1, args.end());
    for (size_t i = 0; key == "covers" && i < args.size(); ++i) c.covers.push_back(to_int(args[i], l.number));
}
// The certificate from L[at] to its `end`; at: then the line after it (on a Reject the failing one)
Cert parse(const vector<Line>& L, size_t& at) {
    Cert c;
    if (L[at].tok != vector<string>{"dualhex-certificate", "2"})
        fail("line ", L[at].number, ": expected 'dualhex-certificate 2'");
    set<string> seen;
    while (++at < L.size() && L[at].tok[0] != "end") read_line(c, L[at], seen);
    if (at == L.size()) fail("truncated: the file ends inside the certificate (no 'end')");
    ++at;
    for (const char* s : {"name", "kind", "domain"})
        if (!seen.count(s)) fail("missing section '", s, "'");
    return c;
}
P3 sub(P3 a, P3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }  // exact arithmetic
P3 cross(P3 a, P3 b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
i128 dot(P3 a, P3 b) { return i128{a[0]} * b[0] + i128{a[1]} * b[1] + i128{a[2]} * b[2]; }
i128 det(P3 u, P3 x, P3 y) {  // u . (x cross y), |u| <= 2^20, |x|, |y| <= 2^41: below 2^127
    const i128 c0 = i128{x[1]} * y[2] - i128{x[2]} * y[1];
    const i128 c1 = i128{x[2]} * y[0] - i128{x[0]} * y[2];
    return u[0] * c0 + u[1] * c1 + u[2] * (i128{x[0]} * y[1] - i128{x[1]} * y[0]);
}
bool same_direction(P3 x, P3 y) {
    const P3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
    return det(ex, x, y) == 0 && det(ey, x, y) == 0 && det(ez, x, y) == 0 && dot(x, y) > 0;
}
P3 nearest(const Cert& c, P3 p, P3 ref) {  // torus: the copy of p nearest to ref
    for (int a = 0; a < 3 && c.domain == "torus"; ++a) {
        const i64 d = ((p[a] - ref[a]) % c.hi[a] + c.hi[a]) % c.hi[a];
        p[a] = ref[a] + (d > c.hi[a] / 2 ? d - c.hi[a] : d);
    }
    return p;
}
struct Mesh {  // combinatorics: the incidences derived from the lists
    Pairs edges;                  // (a, b), a < b
    vector<Ids> face_edges;       // face -> its loop edges, edge i from loop[i] to loop[i + 1]
    vector<Pairs> edge_uses;      // edge -> (face, index in its loop)
    vector<Pairs> face_cells;     // face -> (cell, side)
    vector<Ids> v_faces;          // vertex -> its faces
    vector<char> bdry_v, bdry_e;  // on a boundary face (a face of one cell)
    string edge_name(int e) const { return cat("edge ", edges[e].first, "-", edges[e].second); }
};
// Faces are loops of >= 3 distinct vertices, no two on one set; their sides are the edges.
void check_faces(const Cert& c, Mesh& m) {
    map<pair<int, int>, int> edge_id;
    map<Ids, int> face_by_set;
    m.v_faces.resize(c.pos.size());
    for (int f = 0; f < len(c.faces); ++f) {
        const Ids& l = c.faces[f];
        Ids s = l;
        std::sort(s.begin(), s.end());
        if (l.size() < 3) fail("face ", f, " has fewer than 3 vertices");
        if (std::adjacent_find(s.begin(), s.end()) < s.end()) fail("face ", f, " repeats a vertex");
        if (!face_by_set.emplace(s, f).second) fail("face ", f, " repeats face ", face_by_set[s]);
        m.face_edges.emplace_back();
        for (int i = 0, n = len(l); i < n; ++i) {
            auto [e, fresh] = edge_id.emplace(std::minmax(l[i], l[(i + 1) % n]), len(m.edges));
            if (fresh) m.edges.push_back(e->first);
            m.edge_uses.resize(m.edges.size());
            m.face_edges[f].push_back(e->second);
            m.edge_uses[e->second].push_back({f, i});
            m.v_faces[l[i]].push_back(f);
        }
    }
}
// A cell: closed, oriented, connected, V - E + F = 2: a sphere, so a manifold (README, The checker)
void check_cell(const Cert& c, Mesh& m, int k) {
    map<pair<int, int>, int> owner;  // directed edge -> index of the half-face in the cell
    set<int> faces, vertices;
    const Ids& hs = c.cells[k];
    for (int i = 0; i < len(hs); ++i) {
        if (!faces.insert(hs[i] / 2).second) fail("cell ", k, " lists face ", hs[i] / 2, " twice");
        m.face_cells[hs[i] / 2].push_back({k, hs[i] % 2});
        Ids l = c.faces[hs[i] / 2];  // in the cell's orientation, from the face's first vertex
        if (hs[i] % 2) std::reverse(l.begin() + 1, l.end());
        for (int j = 0, n = len(l); j < n; ++j) {
            vertices.insert(l[j]);
            if (!owner.emplace(pair{l[j], l[(j + 1) % n]}, i).second)
                fail("cell ", k, ": edge ", l[j], "->", l[(j + 1) % n], " walked twice alike");
        }
    }
    Pairs links;  // half-faces sharing an edge
    for (const auto& [d, i] : owner) {
        auto back = owner.find({d.second, d.first});
        if (back == owner.end()) fail("cell ", k, " is open at edge ", d.first, "-", d.second);
        links.push_back({i, back->second});
    }
    if (!connected(hs.size(), links)) fail("cell ", k, " is disconnected");
    const int chi = len(vertices) - len(owner) / 2 + len(hs);
    if (chi != 2) fail("cell ", k, " has V - E + F = ", chi, ", not 2 (not a sphere)");
}
// Faces in 1 or 2 cells (2: opposite sides; torus: closed); vertices distinct, in the domain, used
void check_conformity(const Cert& c, Mesh& m) {
    m.bdry_v.assign(c.pos.size(), 0);
    m.bdry_e.assign(m.edges.size(), 0);
    set<P3> seen;
    for (int f = 0; f < len(c.faces); ++f) {
        const Pairs& fc = m.face_cells[f];
        if (fc.empty() || fc.size() > 2) fail("face ", f, " belongs to ", fc.size(), " cells");
        if (fc.size() == 2 && fc[0].second == fc[1].second) fail("face ", f, " used twice alike");
        if (fc.size() == 2) continue;
        if (c.domain == "torus") fail("face ", f, " is in one cell, but a torus is closed");
        for (int v : c.faces[f]) m.bdry_v[v] = 1;
        for (int e : m.face_edges[f]) m.bdry_e[e] = 1;
    }
    for (int v = 0; v < len(c.pos); ++v) {
        for (int a = 0; a < 3 && c.domain != "point"; ++a)  // in [lo, hi], on a torus in [0, period)
            if (c.pos[v][a] < c.lo[a] || c.pos[v][a] > c.hi[a] - (c.domain == "torus"))
                fail("vertex ", v, " is outside the domain");
        if (!seen.insert(c.pos[v]).second) fail("vertex ", v, " repeats an earlier position");
        if (m.v_faces[v].empty()) fail("vertex ", v, " is on no face");
    }
}
struct FaceFan {  // subdivision: face f as the fan of triangles (l0, lj, lj+1) of its loop l
    vector<P3> sheet;  // at loop edge i (li -> li+1): the normal of the fan there, as listed
    P3 area{0, 0, 0};  // twice the vector area: the sum of the triangles' normals
};
// The sheet at an edge: its fan triangle's normal or, if degenerate, that of a planar face's plane
FaceFan face_fan(const Cert& c, int f) {
    const Ids& l = c.faces[f];
    const int n = len(l);
    const P3 o = c.pos[l[0]], zero{0, 0, 0};
    vector<P3> tri(n - 1, zero);  // tri[j]: triangle (l0, lj, lj+1), j = 1..n-2
    FaceFan fan;
    P3 first = zero;
    bool planar = true;
    for (int j = 1; j + 1 < n; ++j) {
        tri[j] = cross(sub(nearest(c, c.pos[l[j]], o), o), sub(nearest(c, c.pos[l[j + 1]], o), o));
        for (int a = 0; a < 3; ++a) fan.area[a] += tri[j][a];
        first = first == zero ? tri[j] : first;
        planar = planar && (tri[j] == zero || same_direction(first, tri[j]));
    }
    if (first == zero) fail("face ", f, " has no area (its vertices are collinear)");
    for (int i = 0; i < n; ++i) {
        fan.sheet.push_back(tri[std::clamp(i, 1, n - 2)]);
        if (fan.sheet[i] == zero && !planar) fail("face ", f, " is non-planar, degenerate at ", i);
        if (fan.sheet[i] == zero) fan.sheet[i] = first;
    }
    return fan;
}
// Positive volumes summing to the domain's (a star: any), 6V = sum of l0 . area; torus: spans < P/2
void check_volumes(const Cert& c, const vector<FaceFan>& fans) {
    const bool torus = c.domain == "torus";
    i128 total = 0;
    for (int k = 0; k < len(c.cells); ++k) {
        const P3 ref = c.pos[c.faces[c.cells[k][0] / 2][0]];
        auto at = [&](int v) { return sub(nearest(c, c.pos[v], ref), ref); };
        i128 vol = 0;
        P3 lo{0, 0, 0}, hi{0, 0, 0};  // relative to ref
        for (int h : c.cells[k]) {
            for (int v : c.faces[h / 2])
                for (int a = 0; a < 3; ++a) {
                    lo[a] = std::min(lo[a], at(v)[a]);
                    hi[a] = std::max(hi[a], at(v)[a]);
                }
            vol += (h % 2 ? -1 : 1) * dot(at(c.faces[h / 2][0]), fans[h / 2].area);
        }
        for (int a = 0; a < 3 && torus; ++a)
            if (2 * (hi[a] - lo[a]) >= c.hi[a]) fail("cell ", k, " spans half the torus period");
        if (vol <= 0) fail("cell ", k, " has non-positive volume (6V = ", str(vol), ")");
        total += vol;
    }
    i128 expect = 6;
    for (int a = 0; a < 3; ++a) expect *= c.hi[a] - c.lo[a];
    if (c.domain != "point" && total != expect) fail("6 x the volumes sum to ", str(total), ", not ", str(expect));
}
// Boundary faces on the box surface, outward, no others on it: with the volume sum, a tiling
void check_box_boundary(const Cert& c, const Mesh& m, const vector<FaceFan>& fans) {
    auto on = [&](int p, int v) { return c.pos[v][p / 2] == (p % 2 ? c.hi[p / 2] : c.lo[p / 2]); };
    for (int f = 0; f < len(c.faces); ++f) {
        int plane = -1;  // the box face f is on, if any (one: f is not on a line); axis plane / 2
        for (int p = 0; p < 6; ++p)  // at lo if p is even
            if (std::ranges::all_of(c.faces[f], [&](int v) { return on(p, v); })) plane = p;
        const bool shared = m.face_cells[f].size() == 2;
        if (shared && plane >= 0) fail("face ", f, " of two cells lies on the box boundary");
        if (shared) continue;
        if (plane < 0) fail("face ", f, " is a boundary face off the box boundary (a hole)");
        const bool flip = (plane % 2 == 0) != (m.face_cells[f][0].second == 1);
        if ((flip ? -1 : 1) * fans[f].area[plane / 2] <= 0)  // twice the area, outward
            fail("face ", f, " on the box boundary does not face outward");
    }
}
// The uses of edge e = (a, b) in turning order (a cell's face walking a -> b leads to the next):
// one cycle or one fan of cells, else a Reject; from the first cell's use b -> a; if a fan.
pair<Ids, bool> fan_around(const Cert& c, const Mesh& m, int e) {
    const Pairs& uses = m.edge_uses[e];
    map<int, std::array<int, 2>> role;  // cell -> its use walking a -> b, its use walking b -> a
    int start = -1;
    for (int j = 0; j < len(uses); ++j) {
        const auto [f, i] = uses[j];
        for (auto [k, side] : m.face_cells[f]) {
            const int r = (c.faces[f][i] == m.edges[e].first) == (side == 1);  // 1: k walks b -> a
            role[k][r] = j;
            start = r && m.face_cells[f].size() == 1 ? k : start;
        }
    }
    const bool fan = start >= 0;
    start = fan ? start : role.begin()->first;
    Ids order{role[start][1]};
    for (int k = start; len(order) <= len(role) + 1;) {
        order.push_back(role[k][0]);
        const Pairs& fc = m.face_cells[uses[order.back()].first];
        if (fc.size() == 1 || (k = fc[0].first == k ? fc[1].first : fc[0].first) == start) break;
    }
    if (len(order) != len(role) + 1) fail(m.edge_name(e), ": its cells are not one cycle or fan");
    return {order, fan};
}
// Local injectivity: the sheets about u = b - a pass the first once around, a fan never (<= pi)
void check_winding(const Cert& c, const Mesh& m, const vector<FaceFan>& fans, int e) {
    const auto [order, fan] = fan_around(c, m, e);
    const auto [a, b] = m.edges[e];
    const P3 u = sub(nearest(c, c.pos[b], c.pos[a]), c.pos[a]);
    vector<P3> D;  // the sheets' normals in turning order, each oriented as walked a -> b
    for (int j : order) {
        const auto [f, i] = m.edge_uses[e][j];
        const P3 n = fans[f].sheet[i];
        D.push_back(c.faces[f][i] == a ? n : P3{-n[0], -n[1], -n[2]});
    }
    const P3 r = D[0];
    auto half = [&](P3 w) { return det(u, r, w) < 0 || (det(u, r, w) == 0 && dot(r, w) <= 0); };
    auto before = [&](P3 x, P3 y) { return half(x) != half(y) ? half(y) : det(u, x, y) > 0; };
    int turns = 0;  // how often the sequence passes the reference again
    for (int i = 1; i < len(D); ++i) turns += before(D[i], D[i - 1]);
    if (turns != (fan ? 0 : 1) || (fan && !before(r, D.back())))
        fail(m.edge_name(e), ": cells turn ", turns, " times, not exactly once (overlap or fold)");
    if (fan && half(D.back()) && det(u, r, D.back()) != 0) fail(m.edge_name(e), ": turn over pi");
}
// valences, all-hex-dual: at an interior vertex v the link (its edges, faces, cells) is an
// octahedron, the dual cell (cells, faces, edges) a cube: one shape, two conditions each (README)
void check_star(const Cert& c, const Mesh& m, int v, bool valences, bool dual) {
    map<int, Ids> cell_edges;  // cell at v -> its edges at v, sorted (each twice)
    set<pair<int, int>> link_edges, dual_edges;
    bool shape = m.v_faces[v].size() == 12;
    for (int f : m.v_faces[v]) {
        const Ids& l = c.faces[f];
        const int i = static_cast<int>(std::find(l.begin(), l.end(), v) - l.begin());
        const int x = m.face_edges[f][(i + len(l) - 1) % len(l)], y = m.face_edges[f][i];
        const Pairs& fc = m.face_cells[f];  // two cells: v is on no boundary face
        link_edges.insert(std::minmax(x, y));
        dual_edges.insert(std::minmax(fc[0].first, fc[1].first));
        shape = shape && m.edge_uses[x].size() == 4 && m.edge_uses[y].size() == 4;
        for (auto [k, side] : fc) cell_edges[k].insert(cell_edges[k].end(), {x, y});
    }
    set<Ids> triangles;
    map<int, int> index;  // cell at v -> 0, 1, ...
    for (auto& [k, t] : cell_edges) {
        shape = shape && t.size() == 6;
        std::sort(t.begin(), t.end());
        triangles.insert(t);
        index.emplace(k, len(index));
    }
    shape = shape && cell_edges.size() == 8;  // and 6 edges at v: 12 faces x 2 of them = 6 x 4
    if (valences && !(shape && link_edges.size() == 12 && triangles.size() == 8))
        fail("vertex ", v, ": link is not an octahedron (6 edges, 12 faces, 8 cells at v)");
    Pairs links;
    for (auto [x, y] : dual_edges) links.push_back({index[x], index[y]});
    if (dual && !(shape && dual_edges.size() == 12 && connected(index.size(), links)))
        fail("vertex ", v, ": its dual cell is not a combinatorial cube");
}
enum Count { kVertices, kEdges, kFaces, kCells, kInnerVertices, kInnerEdges, kCubes, kWound, kN };
using Stats = std::array<size_t, kN>;  // one certificate: what it counts, then its claims
void check_kind(const Cert& c) {  // the kind fixes the domain and the minimum claims
    const vector<string> hexes{"subdivision", "valences", "all-hex-dual"};
    const map<string, pair<string, vector<string>>> kinds = {{"element", {"box", {"subdivision"}}}, {"histogram", {}},
        {"configuration", {"torus", hexes}}, {"installation", {"box", hexes}}, {"star", {"point", hexes}}};
    const auto k = kinds.find(c.kind);
    if (k == kinds.end()) fail("unknown kind '", c.kind, "'");
    const auto& [domain, needed] = k->second;
    if (!domain.empty() && c.domain != domain) fail("kind ", c.kind, " needs domain ", domain);
    for (const string& claim : needed)
        if (!c.claims.count(claim)) fail("kind ", c.kind, " must claim '", claim, "'");
}
// A claim is followed by exactly what is computed: histograms K:N in increasing K (dual-valences:
// faces with all vertices interior, thus of two cells); nothing after a checked property
void check_claims(const Cert& c, const Mesh& m, const Stats& st) {
    map<string, vector<string>> is{{"subdivision", {}}, {"valences", {}}, {"all-hex-dual", {}},
        {"face-sizes", {}}, {"dual-valences", {}}, {"interior-vertices", {cat(st[kInnerVertices])}},
        {"counts", {cat(st[kVertices]), cat(st[kEdges]), cat(st[kFaces]), cat(st[kCells])}}};
    map<int, int> sizes, inner;
    const auto on_boundary = [&](int v) { return m.bdry_v[v]; };
    for (int f = 0; f < len(c.faces); ++f) {
        ++sizes[len(c.faces[f])];
        if (std::ranges::none_of(c.faces[f], on_boundary)) ++inner[len(c.faces[f])];
    }
    for (auto [k, n] : sizes) is["face-sizes"].push_back(cat(k, ":", n));
    for (auto [k, n] : inner) is["dual-valences"].push_back(cat(k, ":", n));
    for (const auto& [claim, args] : c.claims) {
        if (!is.count(claim)) fail("unknown claim '", claim, "'");
        string computed;
        for (const string& t : is[claim]) computed += " " + t;
        if (args != is[claim]) fail("a claim is not the computed '", claim, computed, "'");
    }
}
// A star (domain point p): p on no boundary face, so its cells close around it; 8 (check_star: at p)
int star_point(const Cert& c, const Mesh& m) {
    const int p = static_cast<int>(std::ranges::find(c.pos, P3{c.lo[0], c.lo[1], c.lo[2]}) - c.pos.begin());
    if (p == len(c.pos) || m.bdry_v[p]) fail("the star's point is not a vertex on no boundary face");
    if (c.cells.size() != 8) fail("a star has its point's 8 cells and no other, not ", c.cells.size(), " cells");
    return p;
}
Stats check(const Cert& c) {
    check_kind(c);
    Mesh m;
    check_faces(c, m);
    m.face_cells.resize(c.faces.size());
    for (int k = 0; k < len(c.cells); ++k) check_cell(c, m, k);
    check_conformity(c, m);
    Stats st{c.pos.size(), m.edges.size(), c.faces.size(), c.cells.size(), 0, 0, 0, 0};
    const int p = c.domain == "point" ? star_point(c, m) : -1;  // a star: only p's edges are wound
    if (c.claims.count("subdivision")) {  // cover with degree 1, locally injective at every edge (or p's)
        vector<FaceFan> fans;
        for (int f = 0; f < len(c.faces); ++f) fans.push_back(face_fan(c, f));
        check_volumes(c, fans);
        if (c.domain == "box") check_box_boundary(c, m, fans);
        for (int e = 0; e < len(m.edges); ++e)
            if (p < 0 || m.edges[e].first == p || m.edges[e].second == p) check_winding(c, m, fans, e), ++st[kWound];
    }
    const bool valences = c.claims.count("valences"), dual = c.claims.count("all-hex-dual");
    for (int v = 0; v < len(c.pos); ++v) {
        st[kInnerVertices] += !m.bdry_v[v];
        if (!m.bdry_v[v] && (valences || dual)) check_star(c, m, v, valences, dual);
        st[kCubes] += !m.bdry_v[v] && dual;
    }
    for (int e = 0; e < len(m.edges) && (valences || dual); ++e) {  // interior: 4 cells around
        st[kInnerEdges] += !m.bdry_e[e];
        if (!m.bdry_e[e] && len(fan_around(c, m, e).first) != 5)
            fail(m.edge_name(e), " is interior but not in a cycle of 4 cells");
    }
    check_claims(c, m, st);
    return st;
}
struct Totals {  // files and manifests: what a run has checked
    map<string, size_t> kinds;
    Stats sum{};
    size_t certificates = 0, rejected = 0, problems = 0;  // problems: of the manifest
    set<string> names;
    map<i64, string> covered;  // label -> certificate
    i64 covers = -1;           // the manifest's `covers N`, checked
    std::uintmax_t budget = kMaxManifestBytes;
};
// Checks every certificate of one file (of kind `kind`, if given); returns how many it holds.
size_t check_file(const string& path, const string& text, Totals& t, const string& kind = "") {
    const vector<Line> L = tokenize(text);
    size_t n = 0, at = 0;
    while (at < L.size()) {
        const size_t first = at;
        string label = cat(path, ": certificate #", ++n);
        try {
            const Cert c = parse(L, at);
            label = cat(path, ":", L[first].number, ": certificate ", c.name);
            if (!t.names.insert(c.name).second) fail("the name ", c.name, " is used twice");
            const Stats s = check(c);
            for (i64 x : c.covers)
                if (!t.covered.emplace(x, c.name).second) fail("covers ", x, " as ", t.covered[x]);
            if (!kind.empty() && c.kind != kind) fail("not of the manifest's kind ", kind);
            ++t.kinds[c.kind];
            for (int i = 0; i < kN; ++i) t.sum[i] += s[i];
        } catch (const Reject& r) {
            std::cout << "REJECTED " << label << ": " << r.why << '\n';
            ++t.rejected;
            at = std::max(at, first + 1);  // resume at the next header from the failing line on
            while (at < L.size() && L[at].tok[0] != "dualhex-certificate") ++at;
        }
    }
    t.certificates += n;
    return n;
}
// A regular file of at most kMaxFileBytes and at most the budget (spent), or a Reject.
string read_file(const std::filesystem::path& p, std::uintmax_t& budget) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) fail("cannot read ", p.string(), ": not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(p, ec);
    if (ec || size > kMaxFileBytes) fail(p.string(), ": larger than the 256 MiB a file may have");
    if (size > budget) fail(p.string(), ": the manifest's files exceed 1 GiB in all");
    std::ifstream in(p, std::ios::binary);
    string out(size, '\0');
    if (!in.read(out.data(), static_cast<std::streamsize>(size)) || in.peek() != EOF)
        fail("cannot read ", p.string(), " (changed while read?)");
    budget -= size;
    return out;
}
// One manifest: every listed file read, hashed and checked, the pinned total and covers.
void check_manifest(const std::filesystem::path& manifest, const string& text, Totals& t) {
    const vector<Line> L = tokenize(text);
    i64 total = -1;
    size_t listed = 0, files = 0;
    auto bad = [&](int line, const string& why) {
        std::cout << "REJECTED " << cat(manifest.string(), ":", line, ": ", why) << '\n';
        ++t.problems;
    };
    const bool head = !L.empty() && L[0].tok == vector<string>{"dualhex-manifest", "1"};
    if (!head) bad(1, "expected 'dualhex-manifest 1'");
    for (size_t i = 1; head && i < L.size(); ++i) {
        const vector<string>& tok = L[i].tok;
        try {
            if ((tok[0] == "total" || tok[0] == "covers") && tok.size() == 2) {
                i64& slot = tok[0] == "total" ? total : t.covers;
                const i64 v = to_int(tok[1], L[i].number);
                if (slot >= 0 || v < 0 || v > i64{1} << 40) fail(tok[0], " given twice, negative or absurd");
                slot = v;
                continue;
            }
            if (tok[0] != "file" || tok.size() != 6 || tok[4] != "fnv1a64")
                fail("expected 'total N', 'covers N' or 'file NAME COUNT KIND fnv1a64 HEX'");
            ++files;
            const string p = (manifest.parent_path() / tok[1]).string();
            const string body = read_file(p, t.budget);
            std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64
            for (unsigned char ch : body) hash = (hash ^ ch) * 1099511628211ull;
            string hex;
            for (int s = 60; s >= 0; s -= 4) hex += "0123456789abcdef"[hash >> s & 15];
            if (tok[5] != hex) fail(p, ": FNV-1a 64 hash is ", hex, ", not ", tok[5]);
            const size_t rejected = t.rejected, held = check_file(p, body, t, tok[3]);
            listed += held;
            std::cout << tok[1] << ": " << held << " certificates, hash ok, ";
            std::cout << held - (t.rejected - rejected) << " verified\n";
            if (cat(held) != tok[2]) fail(p, " holds ", held, " certificates, not ", tok[2]);
        } catch (const Reject& r) {
            bad(L[i].number, r.why);
        }
    }
    if (total < 0 || static_cast<size_t>(total) != listed || files == 0)
        bad(0, cat("the pinned total ", total, " is not the ", listed, " certificates listed"));
    bool all = t.covers >= 0 && t.covered.size() == static_cast<size_t>(t.covers);
    for (i64 x = 0; all && x < t.covers; ++x) all = t.covered.count(x) > 0;
    if (t.covers >= 0 && !all)
        bad(0, cat("the certificates cover ", t.covered.size(), " labels, not 0..", t.covers - 1));
    if (t.covers < 0 && !t.covered.empty())
        bad(0, "certificates carry covers lines but the manifest pins no 'covers N'");
}
struct Commas : std::numpunct<char> {  // the summary's numbers as 19,152
    char do_thousands_sep() const override { return ','; }
    string do_grouping() const override { return "\3"; }
};
// The whole run on argv-style arguments; prints the verdict, returns the exit code.
int run(const vector<string>& args) {
    const bool usage = args.empty() || args.size() > 2 || args[0] == "--help";
    if (usage || (args.size() == 2 && args[0] != "--file")) {
        std::cerr << "usage: dualhex-proof-checker MANIFEST | --file CERTIFICATE_FILE\n";
        return 2;
    }
    Totals t;
    try {
        const string text = read_file(args.back(), t.budget);
        if (args.size() == 1) check_manifest(args[0], text, t);
        if (args.size() == 2) {
            const size_t n = check_file(args[1], text, t);
            std::cout << args[1] << ": " << n << " certificates (covers lines are checked only with a manifest)\n";
        }
    } catch (const Reject& r) {
        std::cout << "REJECTED: " << r.why << '\n';
        return 1;
    }
    const Stats& s = t.sum;
    std::cout.imbue(std::locale(std::cout.getloc(), new Commas));
    std::cout << "parsed: " << t.certificates << " certificates, " << s[kVertices] << " vertices, "
              << s[kEdges] << " edges, " << s[kFaces] << " faces, " << s[kCells] << " cells\n";
    if (t.rejected || t.problems || t.certificates == 0) {
        std::cout << "FAILED: " << t.rejected << " certificates rejected, " << t.problems << " manifest problems\n";
        return 1;
    }
    std::cout << "VERIFIED:";
    for (const auto& [kind, n] : t.kinds) std::cout << ' ' << n << ' ' << kind << " certificates,";
    if (t.covers >= 0)  // then the labels are 0..covers-1
        std::cout << " covering " << t.covers << " labels (0.." << cat(t.covers - 1) << "),";
    std::cout << ' ' << s[kInnerVertices] << " interior vertices (" << s[kCubes]
              << " cube dual cells), " << s[kInnerEdges] << " interior edges checked, " << s[kWound]
              << " edges locally injective\n";
    return 0;
}
}  // namespace

int main(int argc, char** argv) { return run(vector<string>(argv + 1, argv + argc)); }
