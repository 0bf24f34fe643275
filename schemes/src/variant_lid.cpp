// The lid of a variant by complement (schemes/derivation/autolid.py): the one cell that
// fills the leaf around the given parts (variants.hpp, with_lid).
#include <set>

#include "dualhex/schemes/variants.hpp"
#include "variant_loops.hpp"

namespace dualhex::variants {

using namespace detail;
namespace {
constexpr std::int64_t U = kLeaf;
}  // namespace

std::vector<PartCell> with_lid(std::vector<PartCell> cells, const std::string& lid_label) {
    std::set<LatticePoint> verts;
    for (const auto& c : cells)
        for (const auto& f : c.faces) verts.insert(f.begin(), f.end());
    for (std::int64_t a : {std::int64_t{0}, U})
        for (std::int64_t b : {std::int64_t{0}, U})
            for (std::int64_t d : {std::int64_t{0}, U}) verts.insert({a, b, d});
    for (auto& c : cells)
        for (auto& f : c.faces) f = insert_tjunctions(f, verts);

    std::map<Loop, std::size_t> count;  // canonical loop -> uses
    std::vector<Loop> order;            // canonical loops in first-use order
    std::map<Loop, Loop> rep;
    for (const auto& c : cells)
        for (const auto& f : c.faces) {
            Loop key = canonical_loop(f);
            if (count[key]++ == 0) order.push_back(key);
            rep[key] = f;
        }
    PartCell lid{lid_label, {}};
    for (const auto& key : order)
        if (count[key] == 1 && leaf_face_of(rep[key]).first < 0) lid.faces.push_back(rep[key]);

    for (int axis = 0; axis < 3; ++axis)
        for (std::int64_t val : {std::int64_t{0}, U}) {
            int o0 = -1, o1 = -1;
            for (int i = 0; i < 3; ++i)
                if (i != axis) (o0 < 0 ? o0 : o1) = i;
            auto P = [&](std::int64_t s, std::int64_t t) {
                LatticePoint p;
                p[axis] = val;
                p[o0] = s;
                p[o1] = t;
                return p;
            };
            const Loop sq = insert_tjunctions({P(0, 0), P(U, 0), P(U, U), P(0, U)}, verts);
            std::map<UEdge, int> edges;
            std::vector<UEdge> edge_order;
            auto add = [&](const Loop& f) {
                for (std::size_t k = 0; k < f.size(); ++k) {
                    const UEdge e = uedge(f[k], f[(k + 1) % f.size()]);
                    if (edges[e]++ == 0) edge_order.push_back(e);
                }
            };
            add(sq);
            for (const auto& key : order)
                if (leaf_face_of(rep[key]) == std::pair<int, std::int64_t>{axis, val}) add(rep[key]);
            std::map<LatticePoint, std::vector<LatticePoint>> adj;
            std::vector<LatticePoint> adj_order;
            for (const auto& e : edge_order) {
                if (edges[e] != 1) continue;
                for (const auto& [p, q] : {std::pair{e.first, e.second}, std::pair{e.second, e.first}}) {
                    if (adj[p].empty()) adj_order.push_back(p);
                    adj[p].push_back(q);
                }
            }
            std::set<LatticePoint> seen;
            for (const auto& start : adj_order) {
                if (seen.count(start)) continue;
                Loop loop{start};
                seen.insert(start);
                LatticePoint prev = start, cur = start;
                bool first = true;
                while (true) {
                    if (adj[cur].size() != 2)
                        throw VariantConstructionError("non-simple lid region on leaf face " + std::to_string(axis) +
                                                       "=" + std::to_string(val) + " at " + point_string(cur));
                    const LatticePoint next = (first || !(adj[cur][0] == prev)) ? adj[cur][0] : adj[cur][1];
                    first = false;
                    if (next == start) break;
                    loop.push_back(next);
                    seen.insert(next);
                    prev = cur;
                    cur = next;
                }
                lid.faces.push_back(std::move(loop));
            }
        }
    cells.push_back(std::move(lid));
    return cells;
}

}  // namespace dualhex::variants
