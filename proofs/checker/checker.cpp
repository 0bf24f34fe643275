// dualhex-proof-checker: the independent checker of dualhex certificates.
//
// Standard library only; includes nothing of dualhex. The format and what each claim means
// are in proofs/README.md. Usage:
//   dualhex-proof-checker MANIFEST            (a `dualhex-manifest 1` file)
//   dualhex-proof-checker --file CERT_FILE    (one certificate file, no manifest)
// Exit 0 and "VERIFIED: ..." only if every certificate parsed and every claim holds;
// otherwise every rejection is printed with its reason and the exit code is 1 (2: usage).
#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace {

using i64 = std::int64_t;
__extension__ typedef __int128 i128;  // GCC and Clang; every product below is bounded to fit (README, Bounds)
using P3 = std::array<i64, 3>;
// Every coordinate, box bound and period lies in [-2^19, 2^19], so a difference of two
// coordinates is at most 2^20, a cross product component at most 2^41, a triple product at
// most 3 * 2^61 < 2^63; sums of up to 2^28 such terms (the file cap) are taken in 128 bits.
constexpr i64 kMaxCoord = i64{1} << 19;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{256} << 20;    // one file
constexpr std::uintmax_t kMaxManifestBytes = std::uintmax_t{1} << 30;  // all files of a manifest
constexpr std::size_t kMaxFaceSize = 64;  // vertices of one face: keeps every per-face search linear in all

struct Reject {  // one certificate (or file) is rejected, with the reason
    std::string why;
};
[[noreturn]] void reject(const std::string& why) { throw Reject{why}; }

std::uint64_t fnv1a64(const std::string& bytes) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return h;
}

// ---------------------------------------------------------------- reading
struct Line {
    int number = 0;
    std::vector<std::string> tok;
};

// The non-empty lines of a text, '#' comments removed, split at whitespace.
std::vector<Line> tokenize(const std::string& text) {
    std::vector<Line> out;
    std::istringstream in(text);
    std::string s;
    for (int n = 1; std::getline(in, s); ++n) {
        if (auto h = s.find('#'); h != std::string::npos) s.erase(h);
        Line l{n, {}};
        std::istringstream ls(s);
        for (std::string t; ls >> t;) l.tok.push_back(t);
        if (!l.tok.empty()) out.push_back(std::move(l));
    }
    return out;
}

i64 to_int(const std::string& t, int line) {
    i64 v = 0;
    auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size()) reject("line " + std::to_string(line) + ": not an integer: '" + t + "'");
    return v;
}
i64 to_coord(const std::string& t, int line) {  // an integer in [-2^19, 2^19]
    const i64 v = to_int(t, line);
    if (v < -kMaxCoord || v > kMaxCoord) reject("line " + std::to_string(line) + ": coordinate " + t + " outside [-2^19, 2^19]");
    return v;
}

struct Cert {
    std::string name, kind, domain;  // domain: box | torus | none
    i64 lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, period = 0;
    std::vector<P3> pos;
    std::vector<std::vector<int>> faces;  // vertex loops
    std::vector<std::vector<int>> cells;  // 2*face + side (side 1: the loop reversed)
    bool interior_all = false;
    std::vector<int> interior;
    std::map<std::string, std::vector<std::string>> claims;
    std::vector<i64> covers;  // labels (e.g. configuration masks) this certificate stands for
    int first_line = 0;
};

// Parses the certificate starting at lines[at] (a `dualhex-certificate` line); advances `at`.
Cert parse(const std::vector<Line>& L, std::size_t& at) {
    Cert c;
    c.first_line = L[at].number;
    if (L[at].tok != std::vector<std::string>{"dualhex-certificate", "1"})
        reject("line " + std::to_string(L[at].number) + ": expected 'dualhex-certificate 1'");
    ++at;
    auto need = [&](std::size_t i) -> const Line& {
        if (i >= L.size()) reject("truncated: the file ends inside the certificate (no 'end')");
        return L[i];
    };
    auto count_of = [&](const Line& l, std::size_t most) {  // a count, at most `most` (what can follow)
        if (l.tok.size() != 2) reject("line " + std::to_string(l.number) + ": expected '" + l.tok[0] + " COUNT'");
        i64 n = to_int(l.tok[1], l.number);
        if (n < 0 || static_cast<std::uint64_t>(n) > most)
            reject("line " + std::to_string(l.number) + ": bad count " + l.tok[1] + " (0.." + std::to_string(most) + " possible here)");
        return static_cast<std::size_t>(n);
    };
    std::set<std::string> seen;
    for (;;) {
        const Line& l = need(at++);
        const std::string& key = l.tok[0];
        const std::string where = "line " + std::to_string(l.number) + ": ";
        if (key == "end") break;
        if (key != "claim" && !seen.insert(key).second) reject(where + "section '" + key + "' given twice");
        if (key == "name" || key == "kind") {
            if (l.tok.size() != 2) reject(where + "expected '" + key + " WORD'");
            (key == "name" ? c.name : c.kind) = l.tok[1];
        } else if (key == "domain") {
            c.domain = l.tok.size() > 1 ? l.tok[1] : "";
            if (c.domain == "box" && l.tok.size() == 8) {
                for (int a = 0; a < 3; ++a) c.lo[a] = to_coord(l.tok[2 + a], l.number), c.hi[a] = to_coord(l.tok[5 + a], l.number);
                for (int a = 0; a < 3; ++a)
                    if (c.hi[a] <= c.lo[a]) reject(where + "bad box (empty on axis " + std::to_string(a) + ")");
            } else if (c.domain == "torus" && l.tok.size() == 3) {
                c.period = to_coord(l.tok[2], l.number);
                if (c.period < 2 || c.period % 2) reject(where + "bad torus period");
            } else if (!(c.domain == "none" && l.tok.size() == 2)) {
                reject(where + "expected 'domain box X0 Y0 Z0 X1 Y1 Z1', 'domain torus P' or 'domain none'");
            }
        } else if (key == "vertices") {
            std::size_t n = count_of(l, L.size() - at);
            for (std::size_t i = 0; i < n; ++i) {
                const Line& v = need(at++);
                if (v.tok.size() != 3) reject("line " + std::to_string(v.number) + ": vertex " + std::to_string(i) + ": expected 'x y z'");
                P3 p{};
                for (int a = 0; a < 3; ++a) p[a] = to_coord(v.tok[a], v.number);
                c.pos.push_back(p);
            }
        } else if (key == "faces" || key == "cells") {
            if (key == "faces" ? !seen.count("vertices") : !seen.count("faces"))
                reject(where + (key == "faces" ? "faces before vertices" : "cells before faces"));
            std::size_t n = count_of(l, L.size() - at), bound = key == "faces" ? c.pos.size() : c.faces.size();
            for (std::size_t i = 0; i < n; ++i) {
                const Line& r = need(at++);
                if (key == "faces" && r.tok.size() > kMaxFaceSize) reject("line " + std::to_string(r.number) + ": face " + std::to_string(i) + " has more than 64 vertices");
                std::vector<int> row;
                for (const std::string& t : r.tok) {
                    const bool cell = key == "cells";
                    if (cell && t[0] != '+' && t[0] != '-')
                        reject("line " + std::to_string(r.number) + ": cell " + std::to_string(i) + ": face reference '" + t + "' needs a sign");
                    i64 v = to_int(cell ? t.substr(1) : t, r.number);
                    if (v < 0 || static_cast<std::size_t>(v) >= bound)
                        reject("line " + std::to_string(r.number) + ": " + key.substr(0, 4) + " " + std::to_string(i) + ": id " + t + " out of range");
                    row.push_back(cell ? static_cast<int>(2 * v + (t[0] == '-')) : static_cast<int>(v));
                }
                (key == "faces" ? c.faces : c.cells).push_back(std::move(row));
            }
        } else if (key == "interior") {
            if (l.tok.size() == 2 && l.tok[1] == "all") {
                c.interior_all = true;
            } else {
                std::size_t n = count_of(l, c.pos.size());
                std::vector<std::string> ids;
                while (ids.size() < n) {
                    const Line& r = need(at++);
                    ids.insert(ids.end(), r.tok.begin(), r.tok.end());
                }
                if (ids.size() != n) reject(where + "interior: more ids than the count");
                for (const std::string& t : ids) {
                    i64 v = to_int(t, l.number);
                    if (v < 0 || static_cast<std::size_t>(v) >= c.pos.size()) reject(where + "interior vertex " + t + " out of range");
                    c.interior.push_back(static_cast<int>(v));
                }
            }
        } else if (key == "covers") {
            for (std::size_t i = 1; i < l.tok.size(); ++i) c.covers.push_back(to_int(l.tok[i], l.number));
        } else if (key == "claim") {
            if (l.tok.size() < 2 || c.claims.count(l.tok[1])) reject(where + "empty or repeated claim");
            c.claims[l.tok[1]] = std::vector<std::string>(l.tok.begin() + 2, l.tok.end());
        } else {
            reject(where + "unknown keyword '" + key + "'");
        }
    }
    for (const char* s : {"name", "kind", "domain", "vertices", "faces", "cells", "interior"})
        if (!seen.count(s)) reject(std::string("missing section '") + s + "'");
    return c;
}

// ---------------------------------------------------------------- checking
struct Stats {
    std::size_t vertices = 0, edges = 0, faces = 0, cells = 0, interior_vertices = 0, interior_edges = 0, cubes = 0, wound_edges = 0;
};

std::string hist_string(const std::map<i64, i64>& h) {
    std::string s;
    for (auto [k, n] : h) s.append(s.empty() ? "" : " ").append(std::to_string(k)).append(":").append(std::to_string(n));
    return s.empty() ? "(empty)" : s;
}

std::map<i64, i64> parse_hist(const std::vector<std::string>& args) {
    std::map<i64, i64> h;
    for (const std::string& a : args) {
        auto colon = a.find(':');
        if (colon == std::string::npos) reject("histogram entry '" + a + "' is not K:N");
        i64 k = to_int(a.substr(0, colon), 0), n = to_int(a.substr(colon + 1), 0);
        if (n <= 0 || h.count(k)) reject("histogram entry '" + a + "' repeated or not positive");
        h[k] = n;
    }
    return h;
}

// Exact vector arithmetic. sub and cross take differences of coordinates (|x| <= 2^20), so a
// cross component is at most 2^41; dot and det multiply such vectors in 128 bits.
using W3 = std::array<i128, 3>;
P3 sub(P3 a, P3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross(P3 a, P3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
W3 wide_cross(P3 a, P3 b) {
    return {i128{a[1]} * b[2] - i128{a[2]} * b[1], i128{a[2]} * b[0] - i128{a[0]} * b[2], i128{a[0]} * b[1] - i128{a[1]} * b[0]};
}
i128 dot(P3 a, P3 b) { return i128{a[0]} * b[0] + i128{a[1]} * b[1] + i128{a[2]} * b[2]; }
// u . (x cross y) with |u| <= 2^20 and |x|, |y| <= 2^41: at most 3 * 2^20 * 2^83 < 2^127
i128 det(P3 u, P3 x, P3 y) {
    W3 c = wide_cross(x, y);
    return u[0] * c[0] + u[1] * c[1] + u[2] * c[2];
}
std::string str(i128 v) { return v < 0 ? "-" + str(-v) : (v >= 10 ? str(v / 10) : "") + char('0' + int(v % 10)); }

P3 nearest(const Cert& c, P3 p, P3 ref) {  // torus: the copy of p nearest to ref
    if (c.domain != "torus") return p;
    for (int a = 0; a < 3; ++a) {
        i64 d = ((p[a] - ref[a]) % c.period + c.period) % c.period;
        p[a] = ref[a] + (d > c.period / 2 ? d - c.period : d);
    }
    return p;
}

// Face f as a surface is the fan of triangles (l0, lj, lj+1) of its loop l. Returns, for each
// loop edge i (li -> li+1), the normal of the sheet of f at that edge in the listed
// orientation: the normal of the fan triangle holding the edge, or, where that triangle is
// degenerate (three collinear vertices), the plane's normal of a planar face (all its
// non-degenerate fan triangles with normals in one direction). Rejects a face without area.
std::vector<P3> face_sheets(const Cert& c, std::size_t f) {
    const auto& l = c.faces[f];
    const std::size_t n = l.size();
    const P3 o = c.pos[l[0]];
    auto at = [&](std::size_t j) { return sub(nearest(c, c.pos[l[j]], o), o); };
    std::vector<P3> tri(n - 1, P3{0, 0, 0});  // tri[j]: triangle (l0, lj, lj+1), j = 1..n-2
    const P3 zero{0, 0, 0};
    P3 first = zero;
    bool planar = true;
    for (std::size_t j = 1; j + 1 < n; ++j) {
        if ((tri[j] = cross(at(j), at(j + 1))) == zero) continue;
        if (first == zero) first = tri[j];
        planar = planar && wide_cross(first, tri[j]) == W3{0, 0, 0} && dot(first, tri[j]) > 0;
    }
    if (first == zero) reject("face " + std::to_string(f) + " has no area (its vertices are collinear)");
    std::vector<P3> sheet(n);
    for (std::size_t i = 0; i < n; ++i) {
        sheet[i] = tri[std::clamp<std::size_t>(i, 1, n - 2)];
        if (sheet[i] == zero && !planar) reject("face " + std::to_string(f) + " is not planar and degenerate at its edge " + std::to_string(i));
        if (sheet[i] == zero) sheet[i] = first;
    }
    return sheet;
}

// Local injectivity at edge e = (a, b), u = b - a: each cell k at e has a wedge, turning
// positively about u from the sheet of its face that walks b -> a to that of its face that
// walks a -> b. Going from cell to cell, the sheets' angles never pass the first sheet's
// but once: an interior edge's wedges turn exactly once around u; a boundary edge's (box)
// run from one boundary face to the other without passing it, turning by at most pi (the
// box's angle there: a half-turn inside a box face, a quarter at a box edge). A wedge whose
// two sheets agree counts as empty (proofs/README.md, "What subdivision proves").
void check_edge_winding(const Cert& c, std::pair<int, int> e, const std::vector<std::pair<int, int>>& uses,
                        const std::vector<std::vector<P3>>& sheets, const std::vector<std::vector<std::pair<int, int>>>& face_cells) {
    const std::string es = "edge " + std::to_string(e.first) + "-" + std::to_string(e.second);
    const P3 a = c.pos[e.first], u = sub(nearest(c, c.pos[e.second], a), a);
    std::map<int, std::array<int, 2>> role;  // cell -> the use (index in uses) walking a -> b, b -> a
    std::vector<P3> dir(uses.size());         // each use's sheet normal, oriented as walked a -> b
    int start = -1, starts = 0, ends = 0;
    for (std::size_t j = 0; j < uses.size(); ++j) {
        auto [f, i] = uses[j];
        const bool fwd = c.faces[f][i] == e.first;
        dir[j] = sheets[f][i];
        if (!fwd) for (auto& x : dir[j]) x = -x;
        for (auto [k, side] : face_cells[f]) {
            const int r = fwd != (side == 1) ? 0 : 1;  // 0: the cell walks a -> b
            auto& slot = role.try_emplace(k, std::array<int, 2>{-1, -1}).first->second;
            slot[r] = static_cast<int>(j);
            if (face_cells[f].size() == 1) r ? (start = k, ++starts) : ++ends;
        }
    }
    if (starts + ends && (starts != 1 || ends != 1)) reject(es + " has boundary faces that are not one on each side");
    for (const auto& [k, slot] : role)
        if (slot[0] < 0 || slot[1] < 0) reject(es + ": cell " + std::to_string(k) + " does not pass it both ways");
    if (start < 0) start = role.begin()->first;
    std::vector<P3> D{dir[role[start][1]]};
    std::size_t steps = 0;
    for (int k = start; steps <= role.size();) {  // next cell: the other one of the face k walks a -> b
        const int j = role[k][0];
        D.push_back(dir[j]);
        ++steps;
        const auto& fc = face_cells[uses[j].first];
        if (fc.size() == 1 || (k = fc[0].first == k ? fc[1].first : fc[0].first) == start) break;
    }
    if (steps != role.size()) reject(es + ": its cells are not one cycle or fan around it");
    const P3 r = D[0];
    auto half = [&](P3 w) { i128 s = det(u, r, w); return s > 0 || (s == 0 && dot(r, w) > 0) ? 0 : 1; };
    auto before = [&](P3 x, P3 y) { return half(x) != half(y) ? half(x) < half(y) : det(u, x, y) > 0; };
    std::size_t turns = 0;  // a wedge is empty (its sheets agree) or turns by the angle to the next sheet
    for (std::size_t i = 1; i < D.size(); ++i) turns += before(D[i], D[i - 1]);  // passing the reference again
    if (turns != (starts ? 0u : 1u) || (starts && !before(r, D.back())))
        reject(es + ": the cells around it turn " + std::to_string(turns) + " times around it, not exactly once (overlap or fold)");
    if (starts && half(D.back()) && det(u, r, D.back()) != 0) reject(es + ": the cells at this boundary edge turn by more than a half-turn");
}

std::vector<int> half_face_loop(const Cert& c, int h) {  // in its orientation, from the face's first vertex
    std::vector<int> l = c.faces[h / 2];
    if (h % 2) std::reverse(l.begin() + 1, l.end());
    return l;
}

// Each cell is closed, connected, consistently oriented, a manifold at each of its vertices
// and has V - E + F = 2. Returns the cells of each face, (cell, side).
std::vector<std::vector<std::pair<int, int>>> check_cells(const Cert& c) {
    const std::size_t C = c.cells.size(), F = c.faces.size();
    auto vs = [](std::size_t v) { return "vertex " + std::to_string(v); };
    auto fs = [](std::size_t f) { return "face " + std::to_string(f); };
    auto cs = [](std::size_t k) { return "cell " + std::to_string(k); };
    auto loop_of = [&](int h) { return half_face_loop(c, h); };
    std::vector<std::vector<std::pair<int, int>>> face_cells(F);  // (cell, side)
    for (std::size_t k = 0; k < C; ++k) {
        std::map<std::pair<int, int>, int> owner;  // directed edge -> index of the half-face in the cell
        std::set<int> cell_faces, cell_vertices;
        const auto& hs = c.cells[k];
        if (hs.empty()) reject(cs(k) + " has no faces");
        for (std::size_t i = 0; i < hs.size(); ++i) {
            if (!cell_faces.insert(hs[i] / 2).second) reject(cs(k) + " lists " + fs(hs[i] / 2) + " twice");
            face_cells[hs[i] / 2].push_back({static_cast<int>(k), hs[i] % 2});
            auto l = loop_of(hs[i]);
            for (std::size_t j = 0; j < l.size(); ++j) {
                cell_vertices.insert(l[j]);
                if (!owner.emplace(std::pair{l[j], l[(j + 1) % l.size()]}, static_cast<int>(i)).second)
                    reject(cs(k) + ": edge " + std::to_string(l[j]) + "->" + std::to_string(l[(j + 1) % l.size()]) +
                           " walked twice in the same direction (inconsistent orientation or non-manifold edge)");
            }
        }
        std::vector<int> parent(hs.size());  // union-find for connectivity
        for (std::size_t i = 0; i < hs.size(); ++i) parent[i] = static_cast<int>(i);
        auto root = [&](int x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
        for (const auto& [d, i] : owner) {
            auto back = owner.find({d.second, d.first});
            if (back == owner.end()) reject(cs(k) + " is open at edge " + std::to_string(d.first) + "-" + std::to_string(d.second));
            parent[root(i)] = root(back->second);
        }
        for (std::size_t i = 0; i < hs.size(); ++i)
            if (root(static_cast<int>(i)) != root(0)) reject(cs(k) + " is disconnected");
        // around each vertex the cell's faces form one cycle: walk v->w, then the face of w->v
        std::map<int, int> corners;
        for (int h : hs) for (int v : c.faces[h / 2]) ++corners[v];
        for (auto [v, n] : corners) {
            int start = -1, steps = 0, cur = -1;
            for (const auto& [d, i] : owner) if (d.first == v) { start = cur = i; break; }
            do {
                auto l = loop_of(hs[cur]);
                int w = l[(std::find(l.begin(), l.end(), v) - l.begin() + 1) % l.size()];
                cur = owner.at({w, v});
                ++steps;
            } while (cur != start && steps <= n);
            if (steps != n) reject(cs(k) + " is not a manifold at " + vs(v) + " (its faces there are not one cycle)");
        }
        const i64 chi = static_cast<i64>(cell_vertices.size()) - static_cast<i64>(owner.size() / 2) + static_cast<i64>(hs.size());
        if (chi != 2) reject(cs(k) + " has V - E + F = " + std::to_string(chi) + ", not 2");
    }
    return face_cells;
}

// Claim subdivision, volumes and boundary: every cell has positive volume (6V from the fan
// triangles, relative to its first vertex), the volumes sum to the domain's, a torus cell
// spans less than half the period, and in a box the boundary faces tile the box faces.
void check_volumes(const Cert& c, const std::vector<std::vector<std::pair<int, int>>>& face_cells) {
    const std::size_t C = c.cells.size(), F = c.faces.size();
    auto cs = [](std::size_t k) { return "cell " + std::to_string(k); };
    auto fs = [](std::size_t f) { return "face " + std::to_string(f); };
    auto loop_of = [&](int h) { return half_face_loop(c, h); };
    auto near = [&](P3 p, P3 ref) { return nearest(c, p, ref); };
    i128 total = 0;
    for (std::size_t k = 0; k < C; ++k) {
        const P3 ref = c.pos[c.faces[c.cells[k][0] / 2][0]];
        i128 vol = 0;
        P3 lo = ref, hi = ref;
        for (int h : c.cells[k]) {
            auto l = loop_of(h);
            for (int v : l) {
                P3 p = near(c.pos[v], ref);
                for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
            }
            P3 o = sub(near(c.pos[l[0]], ref), ref);
            for (std::size_t j = 1; j + 1 < l.size(); ++j)
                vol += dot(o, cross(sub(near(c.pos[l[j]], ref), ref), sub(near(c.pos[l[j + 1]], ref), ref)));
        }
        // on the torus a cell must span less than half the period, so that the nearest copies
        // of any two of its vertices are the ones it uses (a face or edge means one thing)
        for (int a = 0; a < 3; ++a)
            if (c.domain == "torus" && 2 * (hi[a] - lo[a]) >= c.period) reject(cs(k) + " spans half the torus period or more");
        if (vol <= 0) reject(cs(k) + " has non-positive volume (6V = " + str(vol) + ")");
        total += vol;
    }
    i128 expect = 6;
    for (int a = 0; a < 3; ++a) expect *= c.domain == "torus" ? c.period : c.hi[a] - c.lo[a];
    if (total != expect) reject("cell volumes sum to " + str(total) + "/6, the domain has " + str(expect) + "/6");
    if (c.domain == "box") {  // boundary faces tile the six box faces, outward; no interior face on them
        i128 tiled[6] = {0, 0, 0, 0, 0, 0};
        for (std::size_t f = 0; f < F; ++f) {
            int plane = -1;
            for (int p = 0; p < 6 && plane < 0; ++p) {
                bool on = true;
                const i64 side = p % 2 ? c.hi[p / 2] : c.lo[p / 2];  // not (p % 2 ? hi : lo)[..]: GCC 12 -O2 UBSan misreports it
                for (int v : c.faces[f]) on = on && c.pos[v][p / 2] == side;
                if (on) plane = p;
            }
            if (face_cells[f].size() == 2) {
                if (plane >= 0) reject(fs(f) + " is shared by two cells but lies on the box boundary");
                continue;
            }
            if (plane < 0) reject(fs(f) + " is a boundary face off the box boundary (a hole)");
            auto l = loop_of(2 * static_cast<int>(f) + face_cells[f][0].second);
            i128 out = 0;  // twice the area, along the outward axis
            for (std::size_t j = 1; j + 1 < l.size(); ++j)
                out += (plane % 2 ? 1 : -1) * cross(sub(c.pos[l[j]], c.pos[l[0]]), sub(c.pos[l[j + 1]], c.pos[l[0]]))[plane / 2];
            if (out <= 0) reject(fs(f) + " on the box boundary does not face outward");
            tiled[plane] += out;
        }
        for (int p = 0; p < 6; ++p) {
            int a = p / 2, b = (a + 1) % 3, d = (a + 2) % 3;
            if (tiled[p] != 2 * i128{c.hi[b] - c.lo[b]} * (c.hi[d] - c.lo[d]))
                reject("box face " + std::to_string(p) + " is not tiled: twice-area " + str(tiled[p]));
        }
    }
}

Stats check(const Cert& c) {
    const std::size_t V = c.pos.size(), F = c.faces.size(), C = c.cells.size();
    auto vs = [](std::size_t v) { return "vertex " + std::to_string(v); };
    auto fs = [](std::size_t f) { return "face " + std::to_string(f); };
    auto cs = [](std::size_t k) { return "cell " + std::to_string(k); };
    // what each kind must claim, and where it lives
    const std::map<std::string, std::pair<std::string, std::vector<std::string>>> kinds = {
        {"element", {"box", {"subdivision"}}},
        {"configuration", {"torus", {"subdivision", "valences", "all-hex-dual"}}},
        {"installation", {"box", {"subdivision", "valences", "all-hex-dual"}}},
        {"histogram", {"", {}}}};
    auto k = kinds.find(c.kind);
    if (k == kinds.end()) reject("unknown kind '" + c.kind + "'");
    if (!k->second.first.empty() && c.domain != k->second.first) reject("kind " + c.kind + " needs domain " + k->second.first);
    for (const std::string& cl : k->second.second)
        if (!c.claims.count(cl)) reject("kind " + c.kind + " must claim '" + cl + "'");
    for (const auto& [cl, args] : c.claims)
        if (!std::set<std::string>{"subdivision", "valences", "all-hex-dual", "counts", "face-sizes", "dual-valences", "interior-vertices"}.count(cl))
            reject("unknown claim '" + cl + "'");
    if (c.claims.count("subdivision") && c.domain == "none") reject("claim subdivision needs a box or torus domain");

    // vertices: distinct positions, inside the domain
    std::set<P3> where;
    for (std::size_t v = 0; v < V; ++v) {
        for (int a = 0; a < 3; ++a) {
            i64 x = c.pos[v][a];
            if (c.domain == "box" && (x < c.lo[a] || x > c.hi[a])) reject(vs(v) + " lies outside the box");
            if (c.domain == "torus" && (x < 0 || x >= c.period)) reject(vs(v) + " is not reduced modulo the period");
        }
        if (!where.insert(c.pos[v]).second) reject(vs(v) + " repeats the position of an earlier vertex");
    }
    // faces: simple loops of >= 3 distinct vertices, no two faces on the same vertex set; edges
    std::map<std::pair<int, int>, int> edge_id;
    std::vector<std::pair<int, int>> edges;
    std::vector<std::vector<int>> face_edges(F);
    std::map<std::vector<int>, std::size_t> face_by_set;
    for (std::size_t f = 0; f < F; ++f) {
        std::vector<int> s = c.faces[f];
        std::sort(s.begin(), s.end());
        if (c.faces[f].size() < 3) reject(fs(f) + " has fewer than 3 vertices");
        if (std::adjacent_find(s.begin(), s.end()) != s.end()) reject(fs(f) + " repeats a vertex (not a simple polygon)");
        if (auto [it, fresh] = face_by_set.emplace(s, f); !fresh) reject(fs(f) + " has the same vertices as " + fs(it->second));
        const auto& loop = c.faces[f];
        for (std::size_t i = 0; i < loop.size(); ++i) {
            std::pair<int, int> e = std::minmax(loop[i], loop[(i + 1) % loop.size()]);
            auto [it, fresh] = edge_id.emplace(e, static_cast<int>(edges.size()));
            if (fresh) edges.push_back(e);
            face_edges[f].push_back(it->second);
        }
    }
    const std::size_t E = edges.size();
    auto es = [&](std::size_t e) { return "edge " + std::to_string(edges[e].first) + "-" + std::to_string(edges[e].second); };
    const auto face_cells = check_cells(c);  // (cell, side) of each face
    // conformity; boundary faces; interior vertices and edges = those on no boundary face
    std::vector<char> bdry_v(V, 0), bdry_e(E, 0), used_v(V, 0);
    std::size_t boundary_faces = 0;
    for (std::size_t f = 0; f < F; ++f) {
        const auto& fc = face_cells[f];
        if (fc.empty()) reject(fs(f) + " belongs to no cell");
        if (fc.size() > 2) reject(fs(f) + " belongs to " + std::to_string(fc.size()) + " cells");
        if (fc.size() == 2 && fc[0].second == fc[1].second)
            reject(fs(f) + " is used with the same orientation by " + cs(fc[0].first) + " and " + cs(fc[1].first));
        for (int v : c.faces[f]) used_v[v] = 1;
        if (fc.size() == 1) {
            ++boundary_faces;
            for (int v : c.faces[f]) bdry_v[v] = 1;
            for (int e : face_edges[f]) bdry_e[e] = 1;
        }
    }
    for (std::size_t v = 0; v < V; ++v) if (!used_v[v]) reject(vs(v) + " is on no face");
    if (c.domain == "torus" && boundary_faces) reject("the torus complex has " + std::to_string(boundary_faces) + " faces in only one cell");
    std::vector<char> declared(V, c.interior_all ? 1 : 0);
    for (int v : c.interior) {
        if (declared[v]) reject("interior " + vs(v) + " listed twice");
        declared[v] = 1;
    }
    for (std::size_t v = 0; v < V; ++v)
        if (declared[v] != !bdry_v[v])
            reject(vs(v) + (declared[v] ? " is declared interior but lies on a boundary face" : " lies on no boundary face but is not declared interior"));

    const bool subdivision = c.claims.count("subdivision");
    if (subdivision) check_volumes(c, face_cells);

    // incidences around vertices and edges
    std::vector<std::vector<int>> v_edges(V), v_faces(V), e_faces(E);
    for (std::size_t e = 0; e < E; ++e) v_edges[edges[e].first].push_back(static_cast<int>(e)), v_edges[edges[e].second].push_back(static_cast<int>(e));
    for (std::size_t f = 0; f < F; ++f) {
        for (int v : c.faces[f]) v_faces[v].push_back(static_cast<int>(f));
        for (int e : face_edges[f]) e_faces[e].push_back(static_cast<int>(f));
    }
    Stats st{V, E, F, C, 0, 0, 0, 0};
    if (subdivision) {  // local injectivity at every edge
        std::vector<std::vector<P3>> sheets(F);
        std::vector<std::vector<std::pair<int, int>>> uses(E);  // edge -> (face, loop index)
        for (std::size_t f = 0; f < F; ++f) {
            sheets[f] = face_sheets(c, f);
            for (std::size_t i = 0; i < face_edges[f].size(); ++i) uses[face_edges[f][i]].push_back({static_cast<int>(f), static_cast<int>(i)});
        }
        for (std::size_t e = 0; e < E; ++e) check_edge_winding(c, edges[e], uses[e], sheets, face_cells);
        st.wound_edges = E;
    }
    auto edges_at = [&](std::size_t f, int v) {  // the two edges of face f at its vertex v
        const auto& l = c.faces[f];
        std::size_t i = std::find(l.begin(), l.end(), v) - l.begin(), n = l.size();
        return std::pair{face_edges[f][(i + n - 1) % n], face_edges[f][i]};
    };
    const bool valences = c.claims.count("valences"), dual = c.claims.count("all-hex-dual");
    for (std::size_t v = 0; v < V; ++v) {
        if (bdry_v[v]) continue;
        ++st.interior_vertices;
        if (!valences && !dual) continue;
        // the faces at v are interior (v is on no boundary face): each joins two cells
        std::map<int, std::vector<int>> cell_faces;  // cell at v -> its faces at v
        for (int f : v_faces[v]) for (auto [k, side] : face_cells[f]) cell_faces[k].push_back(f);
        if (valences) {  // 6 edges; link: vertices = edges at v, edges = faces at v, triangles = cells at v
            if (v_edges[v].size() != 6) reject(vs(v) + " has " + std::to_string(v_edges[v].size()) + " edges, not 6");
            std::set<std::pair<int, int>> link_edges;
            std::map<int, int> degree;
            for (int f : v_faces[v]) {
                auto [a, b] = edges_at(f, v);
                if (!link_edges.insert(std::minmax(a, b)).second) reject(vs(v) + ": link is not an octahedron (two faces join the same two edges)");
                ++degree[a], ++degree[b];
            }
            std::set<std::vector<int>> triangles;
            for (const auto& [k, fl] : cell_faces) {
                std::map<int, int> seen;
                for (int f : fl) { auto [a, b] = edges_at(f, v); ++seen[a], ++seen[b]; }
                bool triangle = fl.size() == 3 && seen.size() == 3;
                std::vector<int> t;
                for (auto [e, n] : seen) triangle = triangle && n == 2, t.push_back(e);
                if (!triangle || !triangles.insert(t).second) reject(vs(v) + ": link is not an octahedron (" + cs(k) + " is no triangle of it)");
            }
            bool octa = link_edges.size() == 12 && triangles.size() == 8 && degree.size() == 6;
            for (auto [e, n] : degree) octa = octa && n == 4;
            if (!octa) reject(vs(v) + ": link is not an octahedron (" + std::to_string(link_edges.size()) + " edges, " + std::to_string(triangles.size()) + " triangles)");
        }
        if (dual) {  // dual cell: vertices = cells at v, edges = faces at v, faces = edges at v (cycles of cells)
            bool cube = cell_faces.size() == 8 && v_faces[v].size() == 12 && v_edges[v].size() == 6;
            for (const auto& [k, fl] : cell_faces) cube = cube && fl.size() == 3;
            std::set<std::pair<int, int>> dual_edges;
            for (int f : v_faces[v]) cube = cube && dual_edges.insert(std::minmax(face_cells[f][0].first, face_cells[f][1].first)).second;
            for (int e : v_edges[v]) cube = cube && e_faces[e].size() == 4;  // each dual face a quad (cycle checked below)
            std::set<int> reached{cell_faces.begin()->first};  // connected
            for (std::vector<int> todo{cell_faces.begin()->first}; !todo.empty();) {
                int k = todo.back();
                todo.pop_back();
                for (int f : cell_faces[k]) for (auto [n, s] : face_cells[f]) if (reached.insert(n).second) todo.push_back(n);
            }
            if (!cube || reached.size() != cell_faces.size()) reject(vs(v) + ": its dual cell is not a combinatorial cube");
            ++st.cubes;
        }
    }
    for (std::size_t e = 0; e < E && (valences || dual); ++e) {  // interior edges: 4 cells in one cycle
        if (bdry_e[e]) continue;
        ++st.interior_edges;
        std::map<int, std::vector<int>> around;  // cell -> its faces at e
        for (int f : e_faces[e]) for (auto [k, s] : face_cells[f]) around[k].push_back(f);
        bool cycle = e_faces[e].size() == 4 && around.size() == 4;
        for (const auto& [k, fl] : around) cycle = cycle && fl.size() == 2;
        std::set<int> reached{around.begin()->first};
        for (int k = around.begin()->first, from = -1, step = 0; cycle && step < 4; ++step) {  // walk the cycle
            int f = around[k][0] == from ? around[k][1] : around[k][0];
            from = f;
            k = face_cells[f][0].first == k ? face_cells[f][1].first : face_cells[f][0].first;
            reached.insert(k);
        }
        if (!cycle || reached.size() != 4) reject(es(e) + " is interior with " + std::to_string(around.size()) + " cells / " + std::to_string(e_faces[e].size()) + " faces around it, not one cycle of 4");
    }

    // counts and histograms
    auto compare = [&](const std::string& claim, const std::map<i64, i64>& computed) {
        if (!c.claims.count(claim)) return;
        auto claimed = parse_hist(c.claims.at(claim));
        if (claimed != computed) reject("claim " + claim + " " + hist_string(claimed) + " but computed " + hist_string(computed));
    };
    std::map<i64, i64> sizes, dual_valences;
    for (std::size_t f = 0; f < F; ++f) {
        ++sizes[static_cast<i64>(c.faces[f].size())];
        bool all = face_cells[f].size() == 2;
        for (int v : c.faces[f]) all = all && !bdry_v[v];
        if (all) ++dual_valences[static_cast<i64>(c.faces[f].size())];
    }
    compare("face-sizes", sizes);
    compare("dual-valences", dual_valences);
    if (c.claims.count("counts")) {
        const auto& a = c.claims.at("counts");
        std::vector<i64> got{static_cast<i64>(V), static_cast<i64>(E), static_cast<i64>(F), static_cast<i64>(C)};
        if (a.size() != 4) reject("claim counts needs V E F C");
        for (int i = 0; i < 4; ++i)
            if (to_int(a[i], 0) != got[i]) reject("claim counts " + a[0] + " " + a[1] + " " + a[2] + " " + a[3] + " but computed " + std::to_string(V) + " " + std::to_string(E) + " " + std::to_string(F) + " " + std::to_string(C));
    }
    if (c.claims.count("interior-vertices")) {
        const auto& a = c.claims.at("interior-vertices");
        if (a.size() != 1 || to_int(a[0], 0) != static_cast<i64>(st.interior_vertices))
            reject("claim interior-vertices does not equal the computed " + std::to_string(st.interior_vertices));
    }
    return st;
}

std::string with_commas(std::size_t n) {
    const std::string d = std::to_string(n);
    std::string s;
    for (std::size_t i = 0; i < d.size(); ++i) s.append(i && (d.size() - i) % 3 == 0 ? "," : "").push_back(d[i]);
    return s;
}

struct Totals {
    std::map<std::string, std::size_t> kinds;
    Stats sum;
    std::size_t certificates = 0, rejected = 0;
    std::set<std::string> names;
    std::map<i64, std::string> covered;  // label -> certificate
};

// Checks every certificate of one file; returns how many it holds and the kinds found.
std::size_t check_file(const std::string& path, const std::string& text, Totals& t, std::set<std::string>& kinds) {
    auto L = tokenize(text);
    std::size_t n = 0, at = 0;
    while (at < L.size()) {
        ++n;
        const std::size_t first = at;
        std::string label = path + ": certificate #" + std::to_string(n);
        try {
            Cert c = parse(L, at);
            label = path + ":" + std::to_string(c.first_line) + ": certificate " + c.name;
            if (!t.names.insert(c.name).second) reject("the name " + c.name + " is used twice");
            Stats s = check(c);
            for (i64 x : c.covers)
                if (!t.covered.emplace(x, c.name).second) reject("covers " + std::to_string(x) + ", already covered by " + t.covered[x]);
            ++t.kinds[c.kind];
            kinds.insert(c.kind);
            t.sum.vertices += s.vertices, t.sum.edges += s.edges, t.sum.faces += s.faces, t.sum.cells += s.cells;
            t.sum.interior_vertices += s.interior_vertices, t.sum.interior_edges += s.interior_edges, t.sum.cubes += s.cubes;
            t.sum.wound_edges += s.wound_edges;
        } catch (const Reject& r) {
            std::cout << "REJECTED " << label << ": " << r.why << '\n';
            ++t.rejected;
            at = std::max(at, first + 1);  // resynchronise after the failing line, at the next certificate
            while (at < L.size() && L[at].tok[0] != "dualhex-certificate") ++at;
        }
    }
    t.certificates += n;
    return n;
}

// Reads a regular file of at most kMaxFileBytes (and at most `budget` bytes, which it spends);
// returns the reason it cannot, or "".
std::string read_file(const std::filesystem::path& p, std::string& out, std::uintmax_t& budget) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) return "cannot read " + p.string() + ": not a regular file";
    const std::uintmax_t size = std::filesystem::file_size(p, ec);
    if (ec || size > kMaxFileBytes) return p.string() + ": larger than the 256 MiB a certificate file may have";
    if (size > budget) return p.string() + ": the manifest's files exceed 1 GiB in all";
    std::ifstream in(p, std::ios::binary);
    out.assign(size, '\0');
    if (!in.read(out.data(), static_cast<std::streamsize>(size)) || in.peek() != EOF) return "cannot read " + p.string() + " (changed while read?)";
    budget -= size;
    return "";
}

// One manifest: every listed file hashed, counted and checked; the pinned total and covers.
std::size_t check_manifest(const std::filesystem::path& manifest, const std::string& text, Totals& t, std::uintmax_t& budget, bool& coverage) {
    auto L = tokenize(text);
    i64 total = -1, covers = -1;
    std::size_t listed = 0, files = 0, problems = 0;
    auto bad = [&](int line, const std::string& why) { std::cout << "REJECTED " << manifest.string() << ":" << line << ": " << why << '\n'; ++problems; };
    if (L.empty() || L[0].tok != std::vector<std::string>{"dualhex-manifest", "1"}) { bad(1, "expected 'dualhex-manifest 1'"); L.clear(); }
    for (std::size_t i = 1; i < L.size(); ++i) {
        const Line& l = L[i];
        try {
            if ((l.tok[0] == "total" || l.tok[0] == "covers") && l.tok.size() == 2) {
                i64& slot = l.tok[0] == "total" ? total : covers;
                const i64 v = to_int(l.tok[1], l.number);
                if (slot >= 0 || v < 0 || v > (i64{1} << 40)) reject(l.tok[0] + " given twice, negative or absurd");
                slot = v;
                continue;
            }
            // file NAME COUNT KIND fnv1a64 HEX
            if (l.tok[0] != "file" || l.tok.size() != 6 || l.tok[4] != "fnv1a64") reject("expected 'total N', 'covers N' (once each) or 'file NAME COUNT KIND fnv1a64 HEX'");
        } catch (const Reject& r) { bad(l.number, r.why); continue; }
        ++files;
        const std::filesystem::path p = manifest.parent_path() / l.tok[1];
        std::string body;
        if (std::string why = read_file(p, body, budget); !why.empty()) { bad(l.number, why); continue; }
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(body)));
        if (l.tok[5] != hex) { bad(l.number, p.string() + ": FNV-1a 64 hash is " + hex + ", the manifest says " + l.tok[5]); continue; }
        std::set<std::string> kinds;
        std::size_t before = t.rejected, n = check_file(p.string(), body, t, kinds);
        listed += n;
        std::cout << l.tok[1] << ": " << n << " certificates, hash ok, " << (n - (t.rejected - before)) << " verified\n";
        if (std::to_string(n) != l.tok[2]) bad(l.number, p.string() + " holds " + std::to_string(n) + " certificates, the manifest says " + l.tok[2]);
        if (kinds.size() > 1 || (kinds.size() == 1 && *kinds.begin() != l.tok[3])) bad(l.number, p.string() + ": certificates of another kind than " + l.tok[3]);
    }
    if (total < 0 || static_cast<std::size_t>(total) != listed || files == 0)
        bad(0, "the pinned total " + std::to_string(total) + " differs from the " + std::to_string(listed) + " certificates in the files");
    bool all = covers >= 0 && t.covered.size() == static_cast<std::size_t>(covers);
    for (i64 x = 0; all && x < covers; ++x) all = t.covered.count(x) > 0;
    if (covers >= 0 && !all) bad(0, "the certificates cover " + std::to_string(t.covered.size()) + " labels, not exactly 0.." + std::to_string(covers - 1));
    if (covers < 0 && !t.covered.empty()) bad(0, "certificates carry covers lines but the manifest pins no 'covers N'");
    coverage = covers >= 0;
    return problems;
}

// The whole run on argv-style arguments; prints the verdict, returns the exit code.
int run(const std::vector<std::string>& args) {
    if (args.empty() || args.size() > 2 || (args.size() == 2 && args[0] != "--file") || args[0] == "--help") {
        std::cerr << "usage: dualhex-proof-checker MANIFEST | --file CERTIFICATE_FILE\n";
        return 2;
    }
    Totals t;
    std::size_t problems = 0;
    std::uintmax_t budget = kMaxManifestBytes;
    bool coverage = false;  // checked against a manifest's covers line
    std::string text;
    const std::string& path = args.back();
    if (std::string why = read_file(path, text, budget); !why.empty()) { std::cout << "REJECTED: " << why << '\n'; return 1; }
    if (args.size() == 2) {
        std::set<std::string> kinds;
        const std::size_t n = check_file(path, text, t, kinds);
        std::cout << path << ": " << n << " certificates (covers lines are checked only with a manifest)\n";
    } else {
        problems = check_manifest(path, text, t, budget, coverage);
    }
    std::cout << "parsed: " << t.certificates << " certificates, " << with_commas(t.sum.vertices) << " vertices, " << with_commas(t.sum.edges)
              << " edges, " << with_commas(t.sum.faces) << " faces, " << with_commas(t.sum.cells) << " cells\n";
    if (t.rejected || problems || t.certificates == 0) {
        std::cout << "FAILED: " << t.rejected << " certificates rejected, " << problems << " manifest problems\n";
        return 1;
    }
    std::cout << "VERIFIED:";
    for (const auto& [kind, n] : t.kinds) std::cout << ' ' << n << ' ' << kind << " certificates,";
    if (coverage) std::cout << " covering " << t.covered.size() << " labels (0.." << t.covered.size() - 1 << "),";
    std::cout << ' ' << with_commas(t.sum.interior_vertices) << " interior vertices (" << with_commas(t.sum.cubes) << " cube dual cells), "
              << with_commas(t.sum.interior_edges) << " interior edges checked, " << with_commas(t.sum.wound_edges) << " edges locally injective\n";
    return 0;
}

}  // namespace

#ifdef DUALHEX_CHECKER_FUZZ
// The fuzz entry point (proofs/fuzz/): checks `size` bytes as a certificate file, then as a
// manifest (whose files do not exist), with output discarded.
extern "C" int dualhex_checker_fuzz_one(const char* data, std::size_t size) {
    std::cout.setstate(std::ios::badbit);  // the verdicts are not the point here: no output
    const std::string text(data, size);
    Totals t;
    std::set<std::string> kinds;
    check_file("fuzz", text, t, kinds);
    std::uintmax_t budget = 0;
    bool coverage = false;
    Totals m;
    return static_cast<int>(check_manifest("/nonexistent-dualhex-fuzz/manifest", text, m, budget, coverage) + t.rejected);
}
#else
int main(int argc, char** argv) { return run(std::vector<std::string>(argv + 1, argv + argc)); }
#endif
