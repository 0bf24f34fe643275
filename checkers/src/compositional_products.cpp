// distinct_outcome_tuples (compositional_products.hpp): the shared assignments in parallel
// chunks (oneTBB), each chunk keeping its first witness per tuple in order, the chunks merged
// in order: the witnesses and their order are those of a serial enumeration.
#include "compositional_products.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace dualhex::compositional_detail {
namespace {

constexpr std::size_t kMaxLeaves = 8;
using Tuple = std::array<int, kMaxLeaves>;  // unused leaves: -1

// A flat set of tuples (open addressing, linear probing, at most half full): the chunks ask
// it once per window, millions of times, nearly always about a tuple already seen, where a
// node-based set's chained multiplies and pointer chase were a fifth of the enumeration.
class TupleSet {
public:
    TupleSet() { slots_.assign(kInitial, empty()); }
    /// True if the tuple was not in the set (it is now).
    bool insert(const Tuple& t) {
        if (2 * (size_ + 1) > slots_.size()) grow();
        std::size_t i = home(t);
        for (; slots_[i][0] != kEmpty; i = (i + 1) & (slots_.size() - 1))
            if (slots_[i] == t) return false;
        slots_[i] = t;
        ++size_;
        return true;
    }

private:
    static constexpr int kEmpty = -2;  // no outcome id (those are >= 0, unused leaves -1)
    static constexpr std::size_t kInitial = 1024;
    static Tuple empty() {
        Tuple t;
        t.fill(kEmpty);
        return t;
    }
    // Pairs of entries as 64-bit words times odd constants (independent multiplies), mixed once.
    std::size_t home(const Tuple& t) const {
        std::uint64_t h = 0;
        constexpr std::uint64_t kFactor[4] = {0x9e3779b97f4a7c15ULL, 0xd6e8feb86659fd93ULL, 0xa0761d6478bd642fULL,
                                              0xe7037ed1a0b428dbULL};
        for (std::size_t k = 0; k < kMaxLeaves / 2; ++k)
            h += (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t[2 * k])) << 32 |
                  static_cast<std::uint32_t>(t[2 * k + 1])) * kFactor[k];
        h ^= h >> 29;
        h *= 0xbf58476d1ce4e5b9ULL;
        h ^= h >> 32;
        return static_cast<std::size_t>(h) & (slots_.size() - 1);
    }
    void grow() {
        std::vector<Tuple> old = std::move(slots_);
        slots_.assign(2 * old.size(), empty());
        size_ = 0;
        for (const Tuple& t : old)
            if (t[0] != kEmpty) insert(t);
    }

    std::vector<Tuple> slots_;
    std::size_t size_ = 0;
};

std::uint64_t scatter(std::uint64_t a, const std::vector<int>& indices) {
    std::uint64_t pattern = 0;
    for (std::size_t j = 0; j < indices.size(); ++j)
        if ((a >> j) & 1U) pattern |= std::uint64_t{1} << indices[j];
    return pattern;
}

std::uint64_t gather(std::uint64_t pattern, const std::vector<int>& indices) {
    std::uint64_t a = 0;
    for (std::size_t j = 0; j < indices.size(); ++j) a |= ((pattern >> indices[j]) & 1U) << j;
    return a;
}

// The variables several leaves depend on, and per leaf those only it depends on.
struct Split {
    std::vector<int> shared;
    std::vector<std::vector<int>> private_bits;
};

Split split_variables(const std::vector<LeafOutcomes>& leaves, std::size_t variables) {
    std::vector<int> readers(variables, 0);
    for (const LeafOutcomes& l : leaves)
        for (int i : l.depends) ++readers[static_cast<std::size_t>(i)];
    Split out;
    for (std::size_t i = 0; i < variables; ++i)
        if (readers[i] > 1) out.shared.push_back(static_cast<int>(i));
    for (const LeafOutcomes& l : leaves) {
        out.private_bits.emplace_back();
        for (int i : l.depends)
            if (readers[static_cast<std::size_t>(i)] == 1) out.private_bits.back().push_back(i);
    }
    return out;
}

// gather(pattern, depends) for every leaf by tables over the pattern's bytes (the
// enumeration gathers once per leaf for each of up to 2^20 shared assignments). Only the
// bytes that hold variables are looked up: a pattern has no bit at or above `variables`.
class LeafGather {
public:
    LeafGather(const std::vector<LeafOutcomes>& leaves, std::size_t variables)
        : used_bytes_(std::min(kBytes, (variables + 7) / 8)), bytes_(leaves.size()) {
        for (std::size_t n = 0; n < leaves.size(); ++n)
            for (std::size_t k = 0; k < kBytes; ++k)
                for (std::uint64_t v = 0; v < 256; ++v)
                    bytes_[n][k][v] = static_cast<std::uint32_t>(gather(v << (8 * k), leaves[n].depends));
    }
    [[nodiscard]] std::uint64_t operator()(std::size_t n, std::uint64_t pattern) const {
        std::uint64_t a = 0;
        for (std::size_t k = 0; k < used_bytes_; ++k) a |= bytes_[n][k][(pattern >> (8 * k)) & 255U];
        return a;
    }

private:
    static constexpr std::size_t kBytes = 8;
    std::size_t used_bytes_;
    std::vector<std::array<std::array<std::uint32_t, 256>, kBytes>> bytes_;  // 8 KB a leaf: not on a task's stack
};

// scatter(s, indices) by tables over the bytes of s: the enumeration scatters every shared
// assignment (up to 2^20 a type), where the bit-by-bit loop was a third of its time.
class ByteScatter {
public:
    explicit ByteScatter(const std::vector<int>& indices) : used_bytes_((indices.size() + 7) / 8), bytes_(used_bytes_) {
        for (std::size_t k = 0; k < used_bytes_; ++k)
            for (std::uint64_t v = 0; v < 256; ++v) bytes_[k][v] = scatter(v << (8 * k), indices);
    }
    [[nodiscard]] std::uint64_t operator()(std::uint64_t s) const {
        std::uint64_t pattern = 0;
        for (std::size_t k = 0; k < used_bytes_; ++k) pattern |= bytes_[k][(s >> (8 * k)) & 255U];
        return pattern;
    }

private:
    std::size_t used_bytes_;
    std::vector<std::array<std::uint64_t, 256>> bytes_;
};

// Per leaf: its distinct outcomes over its private variables, a witness each (reused from
// one shared assignment to the next).
using Choices = std::array<std::vector<std::pair<int, std::uint64_t>>, kMaxLeaves>;

// Calls emit(tuple, pattern) for every window whose shared variables are the base: a leaf's
// private variables change only its own outcome, so the windows are the product of per-leaf
// choices (one witness per distinct outcome).
// The same when no leaf has a private variable (the types whose octants several leaves all
// read): each base is one window, its tuple the leaves' outcomes at the base, without the
// per-leaf choice lists and the odometer (half the enumeration's instructions).
template <class Emit>
void window_at_base(const std::vector<LeafOutcomes>& leaves, const LeafGather& leaf_gather, std::uint64_t base,
                    Emit&& emit) {
    Tuple tuple;
    tuple.fill(-1);
    for (std::size_t n = 0; n < leaves.size(); ++n) tuple[n] = leaves[n].table[leaf_gather(n, base)];
    emit(tuple, base);
}

template <class Emit>
void windows_over_base(const std::vector<LeafOutcomes>& leaves, const Split& split, const LeafGather& leaf_gather,
                       std::uint64_t base, Choices& choices, Emit&& emit) {
    for (std::size_t n = 0; n < leaves.size(); ++n) {
        const auto& priv = split.private_bits[n];
        auto& mine = choices[n];
        mine.clear();
        for (std::uint64_t q = 0; q < (std::uint64_t{1} << priv.size()); ++q) {
            const std::uint64_t extra = scatter(q, priv);
            const int o = leaves[n].table[leaf_gather(n, base | extra)];
            if (std::none_of(mine.begin(), mine.end(), [o](const auto& c) { return c.first == o; })) mine.emplace_back(o, extra);
        }
    }
    std::array<std::size_t, kMaxLeaves> at{};  // odometer over the product of the choices
    for (bool more = true; more;) {
        Tuple tuple;
        tuple.fill(-1);
        std::uint64_t pattern = base;
        for (std::size_t n = 0; n < leaves.size(); ++n) {
            const auto& c = choices[n][at[n]];
            tuple[n] = c.first;
            pattern |= c.second;
        }
        emit(tuple, pattern);
        more = false;
        for (std::size_t n = 0; n < leaves.size() && !more; ++n) {
            if (++at[n] < choices[n].size()) more = true;
            else at[n] = 0;
        }
    }
}

}  // namespace

std::vector<std::uint64_t> distinct_outcome_tuples(const std::vector<LeafOutcomes>& leaves, std::size_t variables,
                                                   int& shared_count) {
    if (leaves.size() > kMaxLeaves || variables > 63) throw std::length_error("window enumeration: more than 8 leaves or 63 octants");
    const Split split = split_variables(leaves, variables);
    shared_count = static_cast<int>(split.shared.size());
    const std::uint64_t bases = std::uint64_t{1} << split.shared.size();
    constexpr std::uint64_t kChunk = 4096;
    using Firsts = std::vector<std::pair<Tuple, std::uint64_t>>;
    std::vector<Firsts> chunks(static_cast<std::size_t>((bases + kChunk - 1) / kChunk));
    const LeafGather leaf_gather(leaves, variables);
    const ByteScatter shared_scatter(split.shared);
    const bool all_shared = std::all_of(split.private_bits.begin(), split.private_bits.end(),
                                        [](const std::vector<int>& p) { return p.empty(); });
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
        TupleSet seen;
        Choices choices;
        const auto keep_first = [&](const Tuple& tuple, std::uint64_t pattern) {
            if (seen.insert(tuple)) chunks[c].emplace_back(tuple, pattern);
        };
        for (std::uint64_t s = c * kChunk; s < std::min(bases, (c + 1) * kChunk); ++s) {
            if (all_shared) window_at_base(leaves, leaf_gather, shared_scatter(s), keep_first);
            else windows_over_base(leaves, split, leaf_gather, shared_scatter(s), choices, keep_first);
        }
    });
    TupleSet seen;
    std::vector<std::uint64_t> witnesses;
    for (const Firsts& chunk : chunks)
        for (const auto& [tuple, pattern] : chunk)
            if (seen.insert(tuple)) witnesses.push_back(pattern);
    return witnesses;
}

}  // namespace dualhex::compositional_detail
