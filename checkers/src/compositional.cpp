#include "dualhex/checkers/compositional.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include <tbb/parallel_for.h>

#include "dualhex/install/element_templates.hpp"
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

// WindowType::read_of's table.
static void index_reads(WindowType& t) {
    for (std::size_t a = 0; a < 3; ++a) {
        t.read_box_min[a] = t.reads.front()[a];
        for (const Index3& o : t.reads) t.read_box_min[a] = std::min(t.read_box_min[a], o[a]);
    }
    constexpr auto kBox = WindowType::kReadBox;
    t.read_slot.assign(static_cast<std::size_t>(kBox * kBox * kBox), -1);
    for (std::size_t i = 0; i < t.reads.size(); ++i) {
        std::size_t at = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const std::int64_t d = t.reads[i][a] - t.read_box_min[a];
            if (d >= kBox) throw std::length_error("compositional: the octants read span more than 8 per axis");
            at = at * kBox + static_cast<std::size_t>(d);
        }
        t.read_slot[at] = static_cast<std::int8_t>(i);
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
    index_reads(t);
    return t;
}

// Interned outcomes of a leaf: "fine", "hex", "E/<symmetry>", "error: ...".
class Outcomes {
public:
    int id(const std::string& key) { return ids_.emplace(key, static_cast<int>(ids_.size())).first->second; }

private:
    std::unordered_map<std::string, int> ids_;
};

bool fine_in(const WindowType& t, std::uint64_t pattern, const Index3& o) {
    const int i = t.read_of(o);
    return i >= 0 && ((pattern >> i) & 1U);  // not read by the rule: its value cannot matter (reach)
}

// Per leaf: the outcome of each assignment of the leaf's own read octants (bit j: read_index[j]).
std::vector<int> outcome_table(const WindowType& t, int n, const TransitionRule& rule, Outcomes& outcomes) {
    const auto& mine = t.read_index[static_cast<std::size_t>(n)];
    std::vector<int> table(std::size_t{1} << mine.size());
    for (std::uint64_t a = 0; a < table.size(); ++a) {
        std::uint64_t pattern = 0;
        for (std::size_t j = 0; j < mine.size(); ++j)
            if ((a >> j) & 1U) pattern |= std::uint64_t{1} << mine[j];
        const LatticePoint& leaf = t.leaves[static_cast<std::size_t>(n)];
        std::string key;
        if ((pattern >> t.own[static_cast<std::size_t>(n)]) & 1U) {
            key = "fine";
        } else {
            try {
                const auto p = rule.place(detail::coarse_leaf_context(leaf, [&](const Index3& o) { return fine_in(t, pattern, o); }));
                key = p ? p->element + "/" + std::to_string(p->symmetry.index()) : "hex";
            } catch (const std::exception& e) {
                key = std::string("error: ") + e.what();
            }
        }
        table[a] = outcomes.id(key);
    }
    return table;
}

using Signature = std::array<int, kLeaves>;
struct SignatureHash {
    std::size_t operator()(const Signature& s) const {
        std::size_t h = 1469598103934665603ULL;
        for (int x : s) h = (h ^ static_cast<std::size_t>(x)) * 1099511628211ULL;
        return h;
    }
};

std::uint64_t gather(std::uint64_t pattern, const std::vector<int>& indices) {
    std::uint64_t a = 0;
    for (std::size_t j = 0; j < indices.size(); ++j) a |= ((pattern >> indices[j]) & 1U) << j;
    return a;
}

// The parts of a type's octants: those several leaves read (shared) and, per leaf, those
// only it reads (private).
struct ReadSplit {
    std::vector<int> shared;
    std::array<std::vector<int>, kLeaves> private_bits;
};

ReadSplit split_reads(const WindowType& t) {
    std::vector<int> readers(t.reads.size(), 0);
    for (const auto& mine : t.read_index)
        for (int i : mine) ++readers[static_cast<std::size_t>(i)];
    ReadSplit out;
    for (std::size_t i = 0; i < t.reads.size(); ++i)
        if (readers[i] > 1) out.shared.push_back(static_cast<int>(i));
    for (int n = 0; n < kLeaves; ++n)
        for (int i : t.read_index[static_cast<std::size_t>(n)])
            if (readers[static_cast<std::size_t>(i)] == 1) out.private_bits[static_cast<std::size_t>(n)].push_back(i);
    return out;
}

// gather(pattern, read_index[n]) for every leaf n, by tables over the pattern's bytes (the
// enumeration gathers once per leaf for each of up to 2^19 shared assignments).
class LeafGather {
public:
    explicit LeafGather(const WindowType& t) {
        for (std::size_t n = 0; n < kLeaves; ++n)
            for (std::size_t k = 0; k < kBytes; ++k)
                for (std::uint64_t v = 0; v < 256; ++v) bytes_[n][k][v] = static_cast<std::uint32_t>(gather(v << (8 * k), t.read_index[n]));
    }
    [[nodiscard]] std::uint64_t operator()(std::size_t n, std::uint64_t pattern) const {
        std::uint64_t a = 0;
        for (std::size_t k = 0; k < kBytes; ++k) a |= bytes_[n][k][(pattern >> (8 * k)) & 255U];
        return a;
    }

private:
    static constexpr std::size_t kBytes = 8;  // reads <= 63 (window_type)
    std::vector<std::array<std::array<std::uint32_t, 256>, kBytes>> bytes_ = std::vector<std::array<std::array<std::uint32_t, 256>, kBytes>>(kLeaves);  // 64 KB: not on a task's stack
};

// Per leaf: its distinct outcomes over its private octants, with a witness each (reused
// from one base to the next).
using Choices = std::array<std::vector<std::pair<int, std::uint64_t>>, kLeaves>;

// Calls emit(signature, pattern) for every window whose shared octants are the base: for
// each leaf, its private octants (read by no other leaf) only change its own outcome, so
// the windows are the product of per-leaf choices (one witness per distinct outcome).
template <class Emit>
void windows_over_base(const ReadSplit& split, const std::array<std::vector<int>, kLeaves>& tables,
                       const LeafGather& leaf_gather, std::uint64_t base, Choices& choices, Emit&& emit) {
    for (std::size_t n = 0; n < kLeaves; ++n) {
        const auto& priv = split.private_bits[n];
        auto& mine = choices[n];
        mine.clear();
        for (std::uint64_t q = 0; q < (std::uint64_t{1} << priv.size()); ++q) {
            std::uint64_t extra = 0;
            for (std::size_t j = 0; j < priv.size(); ++j)
                if ((q >> j) & 1U) extra |= std::uint64_t{1} << priv[j];
            const int o = tables[n][leaf_gather(n, base | extra)];
            if (std::none_of(mine.begin(), mine.end(), [o](const auto& c) { return c.first == o; })) mine.emplace_back(o, extra);
        }
    }
    std::array<std::size_t, kLeaves> at{};  // odometer over the product of the choices
    for (bool more = true; more;) {
        Signature sig{};
        std::uint64_t pattern = base;
        for (std::size_t n = 0; n < kLeaves; ++n) {
            const auto& c = choices[n][at[n]];
            sig[n] = c.first;
            pattern |= c.second;
        }
        emit(sig, pattern);
        more = false;
        for (std::size_t n = 0; n < kLeaves && !more; ++n) {
            if (++at[n] < choices[n].size()) more = true;
            else at[n] = 0;
        }
    }
}

// Every distinct window of a type with one witness pattern each: the shared octants are
// enumerated jointly (windows_over_base), in chunks in parallel; each chunk keeps its first
// pattern per signature, in order, and the chunks are merged in order, so the witnesses and
// their order are those of the serial enumeration.
std::vector<std::uint64_t> distinct_windows(const WindowType& t, const TransitionRule& rule, int& shared_count) {
    Outcomes outcomes;
    std::array<std::vector<int>, kLeaves> tables;
    for (int n = 0; n < kLeaves; ++n) tables[static_cast<std::size_t>(n)] = outcome_table(t, n, rule, outcomes);
    const ReadSplit split = split_reads(t);
    shared_count = static_cast<int>(split.shared.size());
    const std::uint64_t bases = std::uint64_t{1} << split.shared.size();
    constexpr std::uint64_t kChunk = 4096;
    using Firsts = std::vector<std::pair<Signature, std::uint64_t>>;
    std::vector<Firsts> chunks(static_cast<std::size_t>((bases + kChunk - 1) / kChunk));
    const LeafGather leaf_gather(t);
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
        std::unordered_set<Signature, SignatureHash> seen;
        Choices choices;
        for (std::uint64_t s = c * kChunk; s < std::min(bases, (c + 1) * kChunk); ++s) {
            std::uint64_t base = 0;
            for (std::size_t j = 0; j < split.shared.size(); ++j)
                if ((s >> j) & 1U) base |= std::uint64_t{1} << split.shared[j];
            windows_over_base(split, tables, leaf_gather, base, choices, [&](const Signature& sig, std::uint64_t pattern) {
                if (seen.insert(sig).second) chunks[c].emplace_back(sig, pattern);
            });
        }
    });
    std::unordered_set<Signature, SignatureHash> seen;
    std::vector<std::uint64_t> witnesses;
    for (const Firsts& chunk : chunks)
        for (const auto& [sig, pattern] : chunk)
            if (seen.insert(sig).second) witnesses.push_back(pattern);
    return witnesses;
}

ConfigurationComplex build_window(const WindowType& t, std::uint64_t pattern, const TransitionRule& rule,
                                  detail::TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    const LatticePoint g{t.parity[0], t.parity[1], t.parity[2]};
    const auto wrap = [&](const LatticePoint& p) { return p - g * U; };
    const auto fine = [&](const Index3& o) { return fine_in(t, pattern, o); };
    ConfigurationComplex out;
    out.unit = U;
    ComplexBuilder builder;
    std::vector<VertexHandle> vs, loop;
    std::vector<HalfFaceHandle> hfs;
    for (const LatticePoint& leaf : t.leaves) {
        if (fine(octant_of(leaf))) {
            for (int c = 0; c < 8; ++c) {
                const LatticePoint at = leaf * U + LatticePoint{c & 1, (c >> 1) & 1, (c >> 2) & 1} * (U / 2);
                detail::emit(builder, cache.hex(U / 2), at, 1, wrap, vs, loop, hfs);
                ++out.fine_hexes;
            }
            continue;
        }
        PlacedLeaf placed{leaf, detail::coarse_leaf_context(leaf, fine), std::nullopt};
        placed.placement = detail::emit_rule_leaf(builder, cache, rule, placed.context,
                                                  placed.context.application_point * U, leaf * U, U, wrap, vs, loop, hfs);
        out.coarse_leaves.push_back(std::move(placed));
    }
    out.complex = std::move(builder).build();
    return out;
}

std::vector<PlacedLeaf> coarse_placements(const WindowType& t, std::uint64_t pattern, const TransitionRule& rule) {
    const auto fine = [&](const Index3& o) { return fine_in(t, pattern, o); };
    std::vector<PlacedLeaf> out;
    for (const LatticePoint& leaf : t.leaves) {
        if (fine(octant_of(leaf))) continue;
        PlacedLeaf placed{leaf, detail::coarse_leaf_context(leaf, fine), std::nullopt};
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
