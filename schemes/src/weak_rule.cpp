#include "dualhex/schemes/weak_rule.hpp"

#include <array>

namespace dualhex {
namespace {

struct MrElement {
    const char* base;   ///< the strong element it truncates
    const char* name;   ///< the MR element
    unsigned edges;     ///< canonical truncated edges (bit = axis)
};
// The strong element plus the number of truncated edges decide the MR element.
constexpr std::array<MrElement, 5> kMr{{
    {"E", "E-MR", 0b001}, {"VS", "VS-MR", 0b001},
    {"VC", "VC1-MR", 0b001}, {"VC", "VC2-MR", 0b011}, {"VC", "VC3-MR", 0b111}}};

unsigned permuted_bits(unsigned bits, const std::array<int, 3>& s) {
    unsigned out = 0;
    for (int a = 0; a < 3; ++a)
        if (bits & (1u << a)) out |= 1u << s[static_cast<std::size_t>(a)];
    return out;
}

}  // namespace

unsigned mr_edges(const LeafContext& c) {
    unsigned edges = 0;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, d = (a + 2) % 3;
        std::array<int, 3> fb{0, 0, 0}, fd{0, 0, 0};
        fb[static_cast<std::size_t>(b)] = -1;
        fd[static_cast<std::size_t>(d)] = -1;
        if (c.fine(fb[0], fb[1], fb[2]) && c.fine(fd[0], fd[1], fd[2]) && c.two_finer_across_edge(a)) edges |= 1u << a;
    }
    return edges;
}

LeafContext weak_visible(const LeafContext& context) {
    LeafContext visible = context;
    visible.neighbourhood &= strong_reach();
    std::uint8_t concave = 0;
    for (int a = 0; a < 3; ++a) {
        std::array<int, 3> fb{0, 0, 0}, fd{0, 0, 0};
        fb[static_cast<std::size_t>((a + 1) % 3)] = -1;
        fd[static_cast<std::size_t>((a + 2) % 3)] = -1;
        if (context.fine(fb[0], fb[1], fb[2]) && context.fine(fd[0], fd[1], fd[2])) concave |= static_cast<std::uint8_t>(1U << a);
    }
    visible.edge_two_finer &= concave;
    return visible;
}

std::optional<Placement> WeakRule::place(const LeafContext& full) const {
    const LeafContext context = weak_visible(full);  // what the rule may see, nothing else
    const unsigned mr = mr_edges(context);
    if (mr == 0) return StrongRule().place(context);
    const Signature need = required_signature(context);
    int count = 0;
    for (int a = 0; a < 3; ++a) count += (mr >> a) & 1;
    for (const auto& m : kMr) {
        int k = 0;
        for (int a = 0; a < 3; ++a) k += (m.edges >> a) & 1;
        if (k != count) continue;
        const auto& elements = strong_elements();
        for (const auto& e : elements) {
            if (e.name != m.base) continue;
            for (const auto& s : axis_permutations())
                if (e.signature.permuted(s) == need && permuted_bits(m.edges, s) == mr) return permutation_placement(m.name, s);
        }
    }
    throw UnknownPatternError("no weakly balanced element has signature " + need.to_string() + " with truncated edges " +
                              std::to_string(mr) + " (" + full.describe() + ")");
}

}  // namespace dualhex
