#include "dualhex/checkers/compositional.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "dualhex/install/element_templates.hpp"
#include "compositional_products.hpp"
#include "compositional_windows.hpp"

namespace dualhex {
namespace compositional_detail {


std::vector<int> reach_bits(const TransitionRule& rule) {
    std::vector<int> bits;
    for (int b = 0; b < 64; ++b)
        if ((rule.reach() >> b) & 1U) bits.push_back(b);
    return bits;
}

std::array<int, 3> local_of_bit(int b) { return {(b & 3) - 2, ((b >> 2) & 3) - 2, ((b >> 4) & 3) - 2}; }

// Lemma (header, 2): with none of the 7 octants around P fine, the rule places nothing.
// Every value of the other bits of the reach is tried (the own octant stays coarse).
void check_lemma(const TransitionRule& rule, CompositionalResult& result) {
    std::vector<int> free;
    for (int b : reach_bits(rule)) {
        const auto o = local_of_bit(b);
        const bool at_p = o[0] <= 0 && o[0] >= -1 && o[1] <= 0 && o[1] >= -1 && o[2] <= 0 && o[2] >= -1;
        if (!at_p) free.push_back(b);
    }
    for (std::uint64_t a = 0; a < (std::uint64_t{1} << free.size()); ++a) {
        LeafContext ctx;
        for (std::size_t i = 0; i < free.size(); ++i)
            if ((a >> i) & 1U) ctx.neighbourhood |= std::uint64_t{1} << free[i];
        ++result.lemma_contexts;
        try {
            if (!rule.place(ctx)) ++result.lemma_plain;
        } catch (const std::exception&) {  // an error is not "plain": the lemma fails
        }
    }
}

Index3 octant_of(const LatticePoint& leaf) {
    return {detail::floor_div(leaf.x, 2), detail::floor_div(leaf.y, 2), detail::floor_div(leaf.z, 2)};
}

OctantIndex::OctantIndex(const std::vector<Index3>& octants) {
    if (octants.size() > 127) throw std::length_error("octant index: more than 127 octants");
    if (octants.empty()) return;
    std::size_t cells = 1;
    for (std::size_t a = 0; a < 3; ++a) {
        std::int64_t hi = octants.front()[a];
        min_[a] = hi;
        for (const Index3& o : octants) min_[a] = std::min(min_[a], o[a]), hi = std::max(hi, o[a]);
        extent_[a] = hi - min_[a] + 1;
        if (extent_[a] > 64) throw std::length_error("octant index: the octants span more than 64 per axis");
        cells *= static_cast<std::size_t>(extent_[a]);
    }
    slot_.assign(cells, -1);
    for (std::size_t i = 0; i < octants.size(); ++i) {
        std::size_t at = 0;
        for (std::size_t a = 0; a < 3; ++a)
            at = at * static_cast<std::size_t>(extent_[a]) + static_cast<std::size_t>(octants[i][a] - min_[a]);
        slot_[at] = static_cast<std::int8_t>(i);
    }
}

WindowType window_type(const std::array<int, 3>& parity, const TransitionRule& rule) {
    WindowType t;
    t.parity = parity;
    std::map<Index3, int> index;
    const auto intern = [&](const Index3& o) {
        const auto [it, fresh] = index.emplace(o, static_cast<int>(t.reads.size()));
        if (fresh) t.reads.push_back(o);
        return it->second;
    };
    for (int n = 0; n < kLeaves; ++n) {
        const LatticePoint leaf{parity[0] - 1 + (n & 1), parity[1] - 1 + ((n >> 1) & 1), parity[2] - 1 + ((n >> 2) & 1)};
        t.leaves[static_cast<std::size_t>(n)] = leaf;
        const LeafContext frame = detail::coarse_leaf_context(leaf, [](const Index3&) { return false; });
        auto& mine = t.read_index[static_cast<std::size_t>(n)];
        t.own[static_cast<std::size_t>(n)] = intern(octant_of(leaf));
        mine.push_back(t.own[static_cast<std::size_t>(n)]);
        for (int b : reach_bits(rule)) mine.push_back(intern(detail::world_octant(frame, local_of_bit(b))));
        std::sort(mine.begin(), mine.end());
        mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    }
    if (t.reads.size() > 63) throw std::length_error("compositional: more than 63 octants read by one window");
    t.read_of = OctantIndex(t.reads);
    for (std::size_t n = 0; n < kLeaves; ++n) {
        t.frame[n] = detail::coarse_leaf_context(t.leaves[n], [](const Index3&) { return false; });
        for (int i = -2; i <= 1; ++i)
            for (int j = -2; j <= 1; ++j)
                for (int k = -2; k <= 1; ++k)
                    t.context_reads[n][static_cast<std::size_t>(16 * (i + 2) + 4 * (j + 2) + (k + 2))] =
                        static_cast<std::int8_t>(t.read_of(detail::world_octant(t.frame[n], {i, j, k})));
    }
    return t;
}

LeafContext leaf_context(const WindowType& t, std::size_t n, std::uint64_t pattern) {
    LeafContext ctx = t.frame[n];
    const auto& reads = t.context_reads[n];
    for (int i = -2; i <= 1; ++i)
        for (int j = -2; j <= 1; ++j)
            for (int k = -2; k <= 1; ++k) {
                const int r = reads[static_cast<std::size_t>(16 * (i + 2) + 4 * (j + 2) + (k + 2))];
                if (r >= 0 && ((pattern >> r) & 1U)) ctx.set_fine(i, j, k);
            }
    return ctx;
}

// Interned outcomes of a leaf: "fine", "hex", "E/<symmetry>", "error: ...".
class Outcomes {
public:
    int id(const std::string& key) { return ids_.emplace(key, static_cast<int>(ids_.size())).first->second; }

private:
    std::unordered_map<std::string, int> ids_;
};

// Per leaf: the outcome of each assignment of the leaf's own read octants (bit j: read_index[j]).
std::vector<int> outcome_table(const WindowType& t, int n, const TransitionRule& rule, Outcomes& outcomes) {
    const auto& mine = t.read_index[static_cast<std::size_t>(n)];
    std::vector<int> table(std::size_t{1} << mine.size());
    for (std::uint64_t a = 0; a < table.size(); ++a) {
        std::uint64_t pattern = 0;
        for (std::size_t j = 0; j < mine.size(); ++j)
            if ((a >> j) & 1U) pattern |= std::uint64_t{1} << mine[j];
        std::string key;
        if ((pattern >> t.own[static_cast<std::size_t>(n)]) & 1U) {
            key = "fine";
        } else {
            try {
                const auto p = rule.place(leaf_context(t, static_cast<std::size_t>(n), pattern));
                key = p ? p->element + "/" + std::to_string(p->symmetry.index()) : "hex";
            } catch (const std::exception& e) {
                key = std::string("error: ") + e.what();
            }
        }
        table[a] = outcomes.id(key);
    }
    return table;
}

// Every distinct window of a type with one witness pattern each (compositional_products.hpp).
std::vector<std::uint64_t> distinct_windows(const WindowType& t, const TransitionRule& rule, int& shared_count) {
    Outcomes outcomes;
    std::vector<LeafOutcomes> leaves(kLeaves);
    for (int n = 0; n < kLeaves; ++n) {
        leaves[static_cast<std::size_t>(n)].depends = t.read_index[static_cast<std::size_t>(n)];
        leaves[static_cast<std::size_t>(n)].table = outcome_table(t, n, rule, outcomes);
    }
    return distinct_outcome_tuples(leaves, t.reads.size(), shared_count);
}

// About a window's size (8 leaves, fine ones as 8 hexes each): only a reservation.
constexpr std::size_t kWindowVertices = 128, kWindowFaces = 384, kWindowCells = 96;

detail::ConfigurationParts window_parts(const WindowType& t, std::uint64_t pattern, const TransitionRule& rule,
                                        detail::TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    const LatticePoint g{t.parity[0], t.parity[1], t.parity[2]};
    const auto wrap = [&](const LatticePoint& p) { return p - g * U; };
    ConfigurationComplex out;
    out.unit = U;
    ComplexBuilder builder;
    // Room for a typical window up front: grown from empty, the builder's arrays and welding
    // tables were reallocated and rehashed several times for each of the 36,635 windows.
    builder.reserve(kWindowVertices, kWindowFaces, kWindowCells);
    std::vector<VertexHandle> vs, loop;
    std::vector<HalfFaceHandle> hfs;
    for (std::size_t n = 0; n < kLeaves; ++n) {
        const LatticePoint& leaf = t.leaves[n];
        if ((pattern >> t.own[n]) & 1U) {  // its own octant is fine
            for (int c = 0; c < 8; ++c) {
                const LatticePoint at = leaf * U + LatticePoint{c & 1, (c >> 1) & 1, (c >> 2) & 1} * (U / 2);
                detail::emit(builder, cache.hex(U / 2), at, 1, wrap, vs, loop, hfs);
                ++out.fine_hexes;
            }
            continue;
        }
        PlacedLeaf placed{leaf, leaf_context(t, n, pattern), std::nullopt};
        placed.placement = detail::emit_rule_leaf(builder, cache, rule, placed.context,
                                                  placed.context.application_point * U, leaf * U, U, wrap, vs, loop, hfs);
        out.coarse_leaves.push_back(std::move(placed));
    }
    return detail::parts_of(std::move(out), std::move(builder));
}

ConfigurationComplex build_window(const WindowType& t, std::uint64_t pattern, const TransitionRule& rule,
                                  detail::TemplateCache& cache) {
    return detail::complete(window_parts(t, pattern, rule, cache));
}

std::vector<PlacedLeaf> coarse_placements(const WindowType& t, std::uint64_t pattern, const TransitionRule& rule) {
    std::vector<PlacedLeaf> out;
    for (std::size_t n = 0; n < kLeaves; ++n) {
        if ((pattern >> t.own[n]) & 1U) continue;  // its own octant is fine
        PlacedLeaf placed{t.leaves[n], leaf_context(t, n, pattern), std::nullopt};
        placed.placement = rule.place(placed.context);
        out.push_back(std::move(placed));
    }
    return out;
}

std::string describe(const std::array<int, 3>& parity, const std::vector<Index3>& reads, std::uint64_t pattern) {
    std::ostringstream os;
    os << "g=(" << parity[0] << ',' << parity[1] << ',' << parity[2] << ") fine octants {";
    const char* sep = "";
    for (std::size_t i = 0; i < reads.size(); ++i) {
        if (!((pattern >> i) & 1U)) continue;
        os << sep << '(' << reads[i][0] << ',' << reads[i][1] << ',' << reads[i][2] << ')';
        sep = " ";
    }
    os << '}';
    return os.str();
}

}  // namespace compositional_detail

using namespace compositional_detail;

std::string describe_window(const CompositionalWindow& window) {
    return describe(window.parity, window.reads, window.pattern);
}

}  // namespace dualhex
