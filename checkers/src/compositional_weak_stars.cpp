// The influence of each visible context bit on the star pieces of a weak leaf, and the
// joint reads of a vertex's star (compositional_weak_stars.hpp; proofs/README.md W7).
#include "dualhex/checkers/compositional_weak_stars.hpp"

#include <algorithm>
#include <optional>
#include <set>

#include "dualhex/install/element_templates.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex {
namespace {

using detail::ElementTemplate;
using detail::Index3;
using Key = std::vector<std::int64_t>;

constexpr int kOctantBits = 9, kBits = 12, kContexts = 1 << kBits;
constexpr int kRefused = -2;  // a refused context's piece at every position

std::array<std::array<int, 3>, 9> octant_bits(const TransitionRule& rule) {
    std::array<std::array<int, 3>, 9> out{};
    int n = 0;
    for (int b = 0; b < 64; ++b) {
        const std::array<int, 3> o{(b & 3) - 2, ((b >> 2) & 3) - 2, ((b >> 4) & 3) - 2};
        if (!((rule.reach() >> b) & 1U) || o == std::array<int, 3>{0, 0, 0}) continue;
        if (n == kOctantBits) throw std::invalid_argument("weak_star_influence: the rule reads more than 10 octant cubes");
        out[static_cast<std::size_t>(n++)] = o;
    }
    if (n != kOctantBits) throw std::invalid_argument("weak_star_influence: the rule reads fewer than 10 octant cubes");
    return out;
}

}  // namespace

LeafContext set_visible_context(LeafContext ctx, int index, const std::array<std::array<int, 3>, 9>& bits) {
    for (int i = 0; i < kOctantBits; ++i)
        if ((index >> i) & 1) ctx.set_fine(bits[static_cast<std::size_t>(i)][0], bits[static_cast<std::size_t>(i)][1], bits[static_cast<std::size_t>(i)][2]);
    ctx.edge_two_finer = static_cast<std::uint8_t>(index >> kOctantBits);
    return ctx;
}

namespace {

// A cell by its oriented faces (those through the point `at` only, unless `at` is null):
// each loop rotated to start at its least point, faces sorted.
Key cell_key(const ElementTemplate& t, std::size_t c, const std::uint32_t* at) {
    std::vector<Key> faces;
    for (std::uint32_t f = t.cell_offsets[c]; f < t.cell_offsets[c + 1]; ++f) {
        std::vector<LatticePoint> loop;
        bool through = at == nullptr;
        for (std::uint32_t q = t.face_offsets[f]; q < t.face_offsets[f + 1]; ++q) {
            loop.push_back(t.points[t.face_points[q]]);
            through = through || t.face_points[q] == *at;
        }
        if (!through) continue;
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        Key k;
        for (const LatticePoint& p : loop) k.insert(k.end(), {p.x, p.y, p.z});
        faces.push_back(std::move(k));
    }
    std::sort(faces.begin(), faces.end());
    Key out;
    for (const Key& f : faces) {
        out.push_back(static_cast<std::int64_t>(f.size()));
        out.insert(out.end(), f.begin(), f.end());
    }
    return out;
}

template <class K>
int intern(std::map<K, int>& ids, K key) {
    return ids.emplace(std::move(key), static_cast<int>(ids.size())).first->second;
}

// Every vertex of the element with its piece (interned cell ids, sorted, then interned).
std::map<LatticePoint, int> pieces_of(const ElementTemplate& t, StarPiece kind, std::map<Key, int>& cells,
                                      std::map<std::vector<int>, int>& pieces) {
    std::map<LatticePoint, std::vector<int>> at;
    for (std::size_t c = 0; c < t.n_cells(); ++c) {
        const int whole = kind == StarPiece::Cells ? intern(cells, cell_key(t, c, nullptr)) : -1;
        std::set<std::uint32_t> corners;
        for (std::uint32_t f = t.cell_offsets[c]; f < t.cell_offsets[c + 1]; ++f)
            for (std::uint32_t q = t.face_offsets[f]; q < t.face_offsets[f + 1]; ++q) corners.insert(t.face_points[q]);
        for (std::uint32_t p : corners) at[t.points[p]].push_back(whole >= 0 ? whole : intern(cells, cell_key(t, c, &p)));
    }
    std::map<LatticePoint, int> out;
    for (auto& [p, ids] : at) {
        std::sort(ids.begin(), ids.end());
        out[p] = intern(pieces, std::move(ids));
    }
    return out;
}

}  // namespace

int WeakStarInfluence::max_relevant() const { return relevant_histogram.empty() ? 0 : relevant_histogram.rbegin()->first; }

WeakStarInfluence weak_star_influence(const TransitionRule& rule, const ElementLibrary& library, StarPiece kind) {
    WeakStarInfluence r;
    r.rule = rule.name();
    r.kind = kind;
    r.octant_bits = octant_bits(rule);
    detail::TemplateCache cache(library);
    r.unit = cache.unit();
    std::map<Key, int> cells;
    std::map<std::vector<int>, int> pieces;
    std::vector<std::optional<std::map<LatticePoint, int>>> per_context(kContexts);
    std::map<LatticePoint, int> index;
    for (int c = 0; c < kContexts; ++c) {
        ++r.contexts;
        const LeafContext ctx = set_visible_context({}, c, r.octant_bits);
        try {
            const std::optional<Placement> p = rule.place(ctx);
            if (p) detail::check_placement_symmetry(*p);
            const ElementTemplate& t =
                p ? cache.placed(cache.element_index(p->element), world_symmetry(ctx, *p)) : cache.hex(r.unit);
            per_context[static_cast<std::size_t>(c)] = pieces_of(t, kind, cells, pieces);
            for (const auto& [q, id] : *per_context[static_cast<std::size_t>(c)]) index.emplace(q, 0);
        } catch (const std::exception&) {
            ++r.refused;
        }
    }
    r.distinct_pieces = static_cast<int>(pieces.size());
    for (auto& [q, n] : index) {
        n = static_cast<int>(r.positions.size());
        r.positions.push_back({q});
    }
    r.piece.assign(r.positions.size(), std::vector<int>(kContexts, -1));
    for (int c = 0; c < kContexts; ++c) {
        const auto& at = per_context[static_cast<std::size_t>(c)];
        for (std::size_t q = 0; q < r.positions.size(); ++q) {
            if (!at) r.piece[q][static_cast<std::size_t>(c)] = kRefused;
            else if (const auto it = at->find(r.positions[q].position); it != at->end()) {
                r.piece[q][static_cast<std::size_t>(c)] = it->second;
                ++r.positions[q].vertex_contexts;
            }
        }
    }
    for (std::size_t q = 0; q < r.positions.size(); ++q) {
        const auto& row = r.piece[q];
        auto& info = r.positions[q];
        for (int c = 0; c < kContexts; ++c)
            for (int b = 0; b < kBits; ++b)
                if (row[static_cast<std::size_t>(c)] != row[static_cast<std::size_t>(c ^ (1 << b))]) info.relevant |= static_cast<std::uint16_t>(1U << b);
        info.pieces = static_cast<int>(std::set<int>(row.begin(), row.end()).size());
        ++r.relevant_histogram[std::popcount(info.relevant)];
    }
    return r;
}

}  // namespace dualhex
