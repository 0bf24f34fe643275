// The stars of a (vertex, configuration) pair by a search over partial assignments of its
// free statuses (weak_star_pair.hpp, stars_by_search; proofs/README.md W9 (vii)): the same
// set as the product enumeration, without branching on a status that no longer changes the
// piece of the leaf being decided.
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "weak_star_pair.hpp"

namespace dualhex::weak_stars {

namespace {

int power3(int n) {
    int out = 1;
    while (n-- > 0) out *= 3;
    return out;
}

// Piece and branch digit of every subcube of one position's relevant bits, smallest first:
// a subcube with an open digit j is constant iff its two halves (digit j 0 and 1, smaller
// indices) are constant with the same piece. The branch digit prefers one with a constant
// half (so the search gets to a constant piece soon), then the lowest (octant bits first).
PieceCubes::Position cubes_of(const std::vector<int>& row, std::uint16_t relevant) {
    PieceCubes::Position out;
    for (int b = 0; b < 12; ++b)
        if ((relevant >> b) & 1U) out.bits.push_back(b);
    const int r = static_cast<int>(out.bits.size()), n = power3(r);
    out.piece.assign(static_cast<std::size_t>(n), PieceCubes::kOpen);
    out.branch.assign(static_cast<std::size_t>(n), -1);
    for (int idx = 0; idx < n; ++idx) {
        int ctx = 0, best = -1, best_score = -1;
        bool open = false;
        for (int j = 0, rest = idx, p = 1; j < r; ++j, rest /= 3, p *= 3) {
            const int digit = rest % 3;
            if (digit == 1) ctx |= 1 << out.bits[static_cast<std::size_t>(j)];
            if (digit != 2) continue;
            const int a = out.piece[static_cast<std::size_t>(idx - 2 * p)], b = out.piece[static_cast<std::size_t>(idx - p)];
            if (!open) out.piece[static_cast<std::size_t>(idx)] = a == b ? a : PieceCubes::kOpen;
            open = true;
            const int score = (a != PieceCubes::kOpen) + (b != PieceCubes::kOpen);
            if (score > best_score) best = j, best_score = score;
        }
        if (!open) out.piece[static_cast<std::size_t>(idx)] = row[static_cast<std::size_t>(ctx)];
        if (out.piece[static_cast<std::size_t>(idx)] == PieceCubes::kOpen) out.branch[static_cast<std::size_t>(idx)] = static_cast<std::int8_t>(best);
    }
    return out;
}

// The pair's free statuses as variables 0..n-1 (the shared ones first, then each leaf's
// private ones), each leaf's reads as (context bit, variable), the implications as masks.
struct Variables {
    struct LeafVars {
        int position = -1, fixed = 0, constant = -1;
        std::vector<std::pair<int, int>> bits;  // (context bit, variable)
    };
    std::vector<LeafVars> leaves;
    std::vector<std::uint64_t> implies, implied_by;  // per variable: x => y masks, y <= x
    std::vector<std::uint64_t> future;  // per leaf n: variables leaves >= n read or are tied to
};

std::uint64_t bit_of(int x) { return std::uint64_t{1} << x; }

Variables variables_of(const Pair& p) {
    Variables out;
    int n = p.n_shared;
    std::vector<std::pair<int, int>> links;
    for (const auto& [a, b] : p.implies) links.push_back({a, b});
    for (const LeafBits& b : p.leaves) {
        auto& leaf = out.leaves.emplace_back();
        leaf.position = b.at.position;
        leaf.fixed = b.fixed;
        leaf.constant = b.hex_corner ? 0 : -1;
        for (const auto& [bit, i] : b.shared) leaf.bits.push_back({bit, i});
        for (const auto& [bit, i] : b.own) leaf.bits.push_back({bit, n + i});
        const auto var = [&](int code) { return code >= 0 ? n + code : -1 - code; };
        for (const auto& [a, c] : b.implies) links.push_back({var(a), var(c)});
        n += b.n_own;
    }
    if (n > 64) throw std::invalid_argument("weak star search: more than 64 free statuses at one vertex");
    out.implies.assign(static_cast<std::size_t>(n), 0);
    out.implied_by.assign(static_cast<std::size_t>(n), 0);
    for (const auto& [a, c] : links) {
        out.implies[static_cast<std::size_t>(a)] |= bit_of(c);
        out.implied_by[static_cast<std::size_t>(c)] |= bit_of(a);
    }
    out.future.assign(out.leaves.size() + 1, 0);
    for (std::size_t k = out.leaves.size(); k-- > 0;) {
        std::uint64_t read = 0;
        for (const auto& [bit, x] : out.leaves[k].bits) read |= bit_of(x);
        out.future[k] = out.future[k + 1] | read;
    }
    for (std::uint64_t& f : out.future) {
        std::uint64_t tied = f;
        for (int x = 0; x < n; ++x)
            if ((f >> x) & 1U) tied |= out.implies[static_cast<std::size_t>(x)] | out.implied_by[static_cast<std::size_t>(x)];
        f = tied;
    }
    return out;
}

// A partial assignment: `known` variables with their `value`s, closed under the
// implications (x = 1 sets every y with x => y, y = 0 every x with x => y).
struct Partial {
    std::uint64_t known = 0, value = 0;
};

// The open digit to branch on at idx: a status no later leaf reads or is tied to first (it
// never enters a later state), then one with a constant half, then the lowest.
int branch_digit(const PieceCubes::Position& table, int idx, const std::vector<int>& var_of_digit, std::uint64_t later) {
    int best = -1, best_score = -1;
    for (std::size_t j = 0, rest = static_cast<std::size_t>(idx), p = 1; j < table.bits.size(); ++j, rest /= 3, p *= 3) {
        if (rest % 3 != 2) continue;
        const int a = table.piece[static_cast<std::size_t>(idx) - 2 * p], b = table.piece[static_cast<std::size_t>(idx) - p];
        const bool mine = ((later >> var_of_digit[j]) & 1U) == 0;
        const int score = 4 * mine + (a != PieceCubes::kOpen) + (b != PieceCubes::kOpen);
        if (score > best_score) best = static_cast<int>(j), best_score = score;
    }
    return best;
}

// Depth-first over the leaves; a state (leaf n, the pieces of leaves 0..n-1, the assigned
// statuses that leaves n.. read or are tied to) met a second time gives the same stars again,
// so it is skipped.
class Search {
public:
    Search(const PieceCubes& cubes, const Pair& p, long limit, std::size_t max_stars, const std::vector<int>& first_pieces)
        : cubes_(cubes), vars_(variables_of(p)), limit_(limit), max_stars_(max_stars), first_(first_pieces) {
        if (vars_.leaves.size() > 8) throw std::invalid_argument("weak star search: more than 8 leaves at one vertex");
        seen_.resize(vars_.leaves.size());
        pieces_.resize(vars_.leaves.size());
        contexts_.resize(vars_.leaves.size());
    }
    Stars run(long& nodes) {
        visit(0, Partial{}, 0);
        nodes += nodes_;
        return std::move(out_);
    }

private:
    struct Key {
        std::uint64_t known, value, prefix;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            return std::hash<std::uint64_t>()((k.known * 0x9E3779B97F4A7C15ULL ^ k.value) * 0xC2B2AE3D27D4EB4FULL ^ k.prefix);
        }
    };

    // x := v with the implications propagated; false if that contradicts a known value.
    bool assign(Partial& a, int x, bool v) const {
        const std::uint64_t set = bit_of(x) | (v ? vars_.implies[static_cast<std::size_t>(x)] : vars_.implied_by[static_cast<std::size_t>(x)]);
        const std::uint64_t clash = a.known & set & (v ? ~a.value : a.value);
        if (clash) return false;
        a.known |= set;
        if (v) a.value |= set;
        return true;
    }

    // Leaves n.. under a; prefix packs the pieces of leaves 0..n-1 (9 bits each).
    void visit(std::size_t n, const Partial& a, std::uint64_t prefix) {
        if (full()) return;
        if (n == vars_.leaves.size()) {
            out_.emplace(pieces_, contexts_);
            return;
        }
        const std::uint64_t f = vars_.future[n];
        if (!seen_[n].insert(Key{a.known & f, a.value & f, prefix}).second) return;
        decide(n, a, prefix);
    }

    // Leaf n's piece under a: constant (go on with leaf n + 1), or branch on the status its
    // piece table names.
    void decide(std::size_t n, const Partial& a, std::uint64_t prefix) {
        if (full()) return;
        const auto& leaf = vars_.leaves[n];
        if (leaf.position < 0) return fix(n, a, prefix, leaf.constant, 0);
        const auto& table = cubes_.positions[static_cast<std::size_t>(leaf.position)];
        int idx = 0, ctx = leaf.fixed;
        std::vector<int> var_of_digit(table.bits.size(), -1);
        for (std::size_t j = 0, p = 1; j < table.bits.size(); ++j, p *= 3) {
            const int bit = table.bits[j];
            int digit = (leaf.fixed >> bit) & 1;
            for (const auto& [b, x] : leaf.bits) {
                if (b != bit) continue;
                var_of_digit[j] = x;
                digit = (a.known >> x) & 1U ? static_cast<int>((a.value >> x) & 1U) : 2;
            }
            if (digit == 1) ctx |= 1 << bit;
            idx += digit * static_cast<int>(p);
        }
        const int piece = table.piece[static_cast<std::size_t>(idx)];
        if (piece != PieceCubes::kOpen) return fix(n, a, prefix, piece, ctx);
        const int x = var_of_digit[static_cast<std::size_t>(branch_digit(table, idx, var_of_digit, vars_.future[n + 1]))];
        for (const bool v : {false, true}) {
            Partial b = a;
            if (assign(b, x, v)) decide(n, b, prefix);
        }
    }

    void fix(std::size_t n, const Partial& a, std::uint64_t prefix, int piece, int ctx) {
        if (++nodes_ > limit_) {
            std::string states;
            for (const auto& s : seen_) states += " " + std::to_string(s.size());
            throw SearchTooLarge("search over " + std::to_string(limit_) + " nodes; states per leaf" + states + "; stars so far " +
                                 std::to_string(out_.size()) + ", free statuses " + std::to_string(vars_.implies.size()));
        }
        if (n < first_.size() && piece != first_[n]) return;
        pieces_[n] = piece;
        contexts_[n] = ctx;
        visit(n + 1, a, prefix << 9 | static_cast<std::uint64_t>(piece + 3));
    }

    bool full() const { return max_stars_ > 0 && out_.size() >= max_stars_; }

    const PieceCubes& cubes_;
    const Variables vars_;
    const long limit_;
    const std::size_t max_stars_;
    const std::vector<int> first_;
    long nodes_ = 0;
    std::vector<std::unordered_set<Key, KeyHash>> seen_;
    std::vector<int> pieces_, contexts_;
    Stars out_;
};

}  // namespace

PieceCubes piece_cubes(const WeakStarInfluence& inf) {
    if (inf.distinct_pieces + 3 >= 512) throw std::invalid_argument("weak star search: more than 508 distinct pieces");
    PieceCubes out;
    for (std::size_t q = 0; q < inf.positions.size(); ++q) out.positions.push_back(cubes_of(inf.piece[q], inf.positions[q].relevant));
    return out;
}

Stars stars_by_search(const PieceCubes& cubes, const Pair& p, long& nodes, long limit, std::size_t max_stars,
                      const std::vector<int>& first_pieces) {
    return Search(cubes, p, limit, max_stars, first_pieces).run(nodes);
}

}  // namespace dualhex::weak_stars
