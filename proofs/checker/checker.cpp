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
#include <vector>

namespace {

using i64 = std::int64_t;
using P3 = std::array<i64, 3>;
constexpr i64 kMaxExtent = i64{1} << 19;  // keeps every exact volume sum inside int64

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
    auto count_of = [&](const Line& l) {
        if (l.tok.size() != 2) reject("line " + std::to_string(l.number) + ": expected '" + l.tok[0] + " COUNT'");
        i64 n = to_int(l.tok[1], l.number);
        if (n < 0 || n > 100000000) reject("line " + std::to_string(l.number) + ": bad count");
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
                for (int a = 0; a < 3; ++a) c.lo[a] = to_int(l.tok[2 + a], l.number), c.hi[a] = to_int(l.tok[5 + a], l.number);
                for (int a = 0; a < 3; ++a)
                    if (c.hi[a] <= c.lo[a] || c.hi[a] - c.lo[a] > kMaxExtent || std::abs(c.lo[a]) > kMaxExtent)
                        reject(where + "bad box");
            } else if (c.domain == "torus" && l.tok.size() == 3) {
                c.period = to_int(l.tok[2], l.number);
                if (c.period < 2 || c.period % 2 || c.period > kMaxExtent) reject(where + "bad torus period");
            } else if (!(c.domain == "none" && l.tok.size() == 2)) {
                reject(where + "expected 'domain box X0 Y0 Z0 X1 Y1 Z1', 'domain torus P' or 'domain none'");
            }
        } else if (key == "vertices") {
            std::size_t n = count_of(l);
            for (std::size_t i = 0; i < n; ++i) {
                const Line& v = need(at++);
                if (v.tok.size() != 3) reject("line " + std::to_string(v.number) + ": vertex " + std::to_string(i) + ": expected 'x y z'");
                P3 p{};
                for (int a = 0; a < 3; ++a) p[a] = to_int(v.tok[a], v.number);
                c.pos.push_back(p);
            }
        } else if (key == "faces" || key == "cells") {
            if (key == "faces" ? !seen.count("vertices") : !seen.count("faces"))
                reject(where + (key == "faces" ? "faces before vertices" : "cells before faces"));
            std::size_t n = count_of(l), bound = key == "faces" ? c.pos.size() : c.faces.size();
            for (std::size_t i = 0; i < n; ++i) {
                const Line& r = need(at++);
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
                std::size_t n = count_of(l);
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
    std::size_t vertices = 0, edges = 0, faces = 0, cells = 0, interior_vertices = 0, interior_edges = 0, cubes = 0;
};

std::string hist_string(const std::map<i64, i64>& h) {
    std::string s;
    for (auto [k, n] : h) s += (s.empty() ? "" : " ") + std::to_string(k) + ":" + std::to_string(n);
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

// i64 cross/dot helpers
P3 sub(P3 a, P3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross(P3 a, P3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
i64 dot(P3 a, P3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

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
            if (std::abs(x) > 2 * kMaxExtent) reject(vs(v) + ": coordinate too large");
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
    auto loop_of = [&](int h) {  // a half-face's loop in its orientation, from the face's first vertex
        std::vector<int> l = c.faces[h / 2];
        if (h % 2) std::reverse(l.begin() + 1, l.end());
        return l;
    };
    // cells: closed, connected, consistently oriented, vertex-manifold, V - E + F = 2
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

    // geometry: 6 x signed volume of each cell (fan triangles, relative to the cell's first vertex)
    if (c.claims.count("subdivision")) {
        auto unwrap = [&](P3 p, P3 ref) {  // torus: the copy of p nearest to ref
            if (c.domain != "torus") return p;
            for (int a = 0; a < 3; ++a) {
                i64 d = ((p[a] - ref[a]) % c.period + c.period) % c.period;
                p[a] = ref[a] + (d > c.period / 2 ? d - c.period : d);
            }
            return p;
        };
        i64 total = 0;
        for (std::size_t k = 0; k < C; ++k) {
            const P3 ref = c.pos[c.faces[c.cells[k][0] / 2][0]];
            i64 vol = 0;
            for (int h : c.cells[k]) {
                auto l = loop_of(h);
                P3 a = sub(unwrap(c.pos[l[0]], ref), ref);
                for (std::size_t j = 1; j + 1 < l.size(); ++j)
                    vol += dot(a, cross(sub(unwrap(c.pos[l[j]], ref), ref), sub(unwrap(c.pos[l[j + 1]], ref), ref)));
            }
            if (vol <= 0) reject(cs(k) + " has non-positive volume (6V = " + std::to_string(vol) + ")");
            total += vol;
        }
        i64 expect = 6;
        for (int a = 0; a < 3; ++a) expect *= c.domain == "torus" ? c.period : c.hi[a] - c.lo[a];
        if (total != expect) reject("cell volumes sum to " + std::to_string(total) + "/6, the domain has " + std::to_string(expect) + "/6");
        if (c.domain == "box") {  // boundary faces tile the six box faces, outward; no interior face on them
            i64 tiled[6] = {0, 0, 0, 0, 0, 0};
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
                P3 area{0, 0, 0};
                for (std::size_t j = 1; j + 1 < l.size(); ++j) {
                    P3 t = cross(sub(c.pos[l[j]], c.pos[l[0]]), sub(c.pos[l[j + 1]], c.pos[l[0]]));
                    for (int a = 0; a < 3; ++a) area[a] += t[a];
                }
                i64 out = (plane % 2 ? 1 : -1) * area[plane / 2];
                if (out <= 0) reject(fs(f) + " on the box boundary does not face outward");
                tiled[plane] += out;
            }
            for (int p = 0; p < 6; ++p) {
                int a = p / 2, b = (a + 1) % 3, d = (a + 2) % 3;
                if (tiled[p] != 2 * (c.hi[b] - c.lo[b]) * (c.hi[d] - c.lo[d]))
                    reject("box face " + std::to_string(p) + " is not tiled: twice-area " + std::to_string(tiled[p]));
            }
        }
    }

    // incidences around vertices and edges
    std::vector<std::vector<int>> v_edges(V), v_faces(V), e_faces(E);
    for (std::size_t e = 0; e < E; ++e) v_edges[edges[e].first].push_back(static_cast<int>(e)), v_edges[edges[e].second].push_back(static_cast<int>(e));
    for (std::size_t f = 0; f < F; ++f) {
        for (int v : c.faces[f]) v_faces[v].push_back(static_cast<int>(f));
        for (int e : face_edges[f]) e_faces[e].push_back(static_cast<int>(f));
    }
    auto edges_at = [&](std::size_t f, int v) {  // the two edges of face f at its vertex v
        const auto& l = c.faces[f];
        std::size_t i = std::find(l.begin(), l.end(), v) - l.begin(), n = l.size();
        return std::pair{face_edges[f][(i + n - 1) % n], face_edges[f][i]};
    };
    Stats st{V, E, F, C, 0, 0, 0};
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
    for (std::size_t i = 0; i < d.size(); ++i) s += (i && (d.size() - i) % 3 == 0 ? "," : "") + d.substr(i, 1);
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
std::size_t check_file(const std::filesystem::path& path, const std::string& text, Totals& t, std::set<std::string>& kinds) {
    auto L = tokenize(text);
    std::size_t n = 0, at = 0;
    while (at < L.size()) {
        ++n;
        std::string label = path.string() + ": certificate #" + std::to_string(n);
        try {
            Cert c = parse(L, at);
            label = path.string() + ":" + std::to_string(c.first_line) + ": certificate " + c.name;
            if (!t.names.insert(c.name).second) reject("the name " + c.name + " is used twice");
            Stats s = check(c);
            for (i64 x : c.covers)
                if (!t.covered.emplace(x, c.name).second) reject("covers " + std::to_string(x) + ", already covered by " + t.covered[x]);
            ++t.kinds[c.kind];
            kinds.insert(c.kind);
            t.sum.vertices += s.vertices, t.sum.edges += s.edges, t.sum.faces += s.faces, t.sum.cells += s.cells;
            t.sum.interior_vertices += s.interior_vertices, t.sum.interior_edges += s.interior_edges, t.sum.cubes += s.cubes;
        } catch (const Reject& r) {
            std::cout << "REJECTED " << label << ": " << r.why << '\n';
            ++t.rejected;
            while (at < L.size() && L[at].tok[0] != "dualhex-certificate") ++at;  // resynchronise
        }
    }
    t.certificates += n;
    return n;
}

bool read_file(const std::filesystem::path& p, std::string& out) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    out = ss.str();
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args.size() > 2 || (args.size() == 2 && args[0] != "--file") || args[0] == "--help") {
        std::cerr << "usage: dualhex-proof-checker MANIFEST | --file CERTIFICATE_FILE\n";
        return 2;
    }
    Totals t;
    std::size_t problems = 0;
    if (args.size() == 2) {
        std::string text;
        if (!read_file(args[1], text)) { std::cout << "REJECTED: cannot read " << args[1] << '\n'; return 1; }
        std::set<std::string> kinds;
        const std::size_t n = check_file(args[1], text, t, kinds);
        std::cout << args[1] << ": " << n << " certificates\n";
    } else {
        const std::filesystem::path manifest = args[0];
        std::string text;
        if (!read_file(manifest, text)) { std::cout << "REJECTED: cannot read manifest " << manifest << '\n'; return 1; }
        auto L = tokenize(text);
        i64 total = -1, covers = -1;
        std::size_t listed = 0, files = 0;
        auto bad = [&](int line, const std::string& why) { std::cout << "REJECTED " << manifest.string() << ":" << line << ": " << why << '\n'; ++problems; };
        if (L.empty() || L[0].tok != std::vector<std::string>{"dualhex-manifest", "1"}) { bad(1, "expected 'dualhex-manifest 1'"); L.clear(); }
        for (std::size_t i = 1; i < L.size(); ++i) {
            const Line& l = L[i];
            try {
                if (l.tok[0] == "total" && l.tok.size() == 2 && total < 0) { total = to_int(l.tok[1], l.number); continue; }
                if (l.tok[0] == "covers" && l.tok.size() == 2 && covers < 0) { covers = to_int(l.tok[1], l.number); continue; }
                // file NAME COUNT KIND fnv1a64 HEX
                if (l.tok[0] != "file" || l.tok.size() != 6 || l.tok[4] != "fnv1a64") { bad(l.number, "expected 'total N' once or 'file NAME COUNT KIND fnv1a64 HEX'"); continue; }
            } catch (const Reject& r) { bad(l.number, r.why); continue; }
            ++files;
            const std::filesystem::path p = manifest.parent_path() / l.tok[1];
            std::string body;
            if (!read_file(p, body)) { bad(l.number, "cannot read " + p.string()); continue; }
            char hex[17];
            std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(body)));
            if (l.tok[5] != hex) { bad(l.number, p.string() + ": FNV-1a 64 hash is " + hex + ", the manifest says " + l.tok[5]); continue; }
            std::set<std::string> kinds;
            std::size_t before = t.rejected, n = check_file(p, body, t, kinds);
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
    }
    std::cout << "parsed: " << t.certificates << " certificates, " << with_commas(t.sum.vertices) << " vertices, " << with_commas(t.sum.edges)
              << " edges, " << with_commas(t.sum.faces) << " faces, " << with_commas(t.sum.cells) << " cells\n";
    if (t.rejected || problems || t.certificates == 0) {
        std::cout << "FAILED: " << t.rejected << " certificates rejected, " << problems << " manifest problems\n";
        return 1;
    }
    std::cout << "VERIFIED:";
    for (const auto& [kind, n] : t.kinds) std::cout << ' ' << n << ' ' << kind << " certificates,";
    if (!t.covered.empty()) std::cout << " covering " << t.covered.size() << " labels (0.." << t.covered.rbegin()->first << "),";
    std::cout << ' ' << with_commas(t.sum.interior_vertices) << " interior vertices (" << with_commas(t.sum.cubes) << " cube dual cells), "
              << with_commas(t.sum.interior_edges) << " interior edges checked\n";
    return 0;
}
