#pragma once
// Internal: the windows of the compositional argument (compositional.hpp): the 8 parity
// types, the enumeration of their distinct windows (compositional.cpp) and the run that
// checks them, in parallel and class by class (compositional_run.cpp).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dualhex/checkers/compositional.hpp"
#include "dualhex/install/element_templates.hpp"
#include "configuration_parts.hpp"

namespace dualhex::compositional_detail {

using detail::Index3;
constexpr int kLeaves = 8;  // the 2x2x2 leaves of B(g)

/// The indices of a list of at most 127 octants (each at most once) by octant: a dense
/// table over the box they span (the rule asks for octants millions of times; a linear
/// search of the list was a quarter of the compositional run). -1 for an octant not in it.
class OctantIndex {
public:
    OctantIndex() = default;
    explicit OctantIndex(const std::vector<Index3>& octants);
    [[nodiscard]] int operator()(const Index3& o) const {
        std::size_t at = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const std::int64_t d = o[a] - min_[a];
            if (d < 0 || d >= extent_[a]) return -1;
            at = at * static_cast<std::size_t>(extent_[a]) + static_cast<std::size_t>(d);
        }
        return slot_[at];
    }

private:
    Index3 min_{}, extent_{};  // the box the octants span (extent 0: empty)
    std::vector<std::int8_t> slot_;
};

// One parity type: the 8 leaves of B(g), g = parity, and the octants they read.
struct WindowType {
    std::array<int, 3> parity{};
    std::array<LatticePoint, kLeaves> leaves;  // min corners, coarse-leaf units
    std::vector<Index3> reads;                 // R(t)
    std::array<std::vector<int>, kLeaves> read_index;  // per leaf: indices into reads
    std::array<int, kLeaves> own{};            // per leaf: its own octant's index
    OctantIndex read_of;                       // reads' indices by octant
    // Per leaf: its context with no octant fine (application point, direction), and per
    // local octant cube (i, j, k) of that context, entry 16(i+2) + 4(j+2) + (k+2), the
    // cube's index in reads or -1 (not read by the rule, so its value cannot matter (reach):
    // coarse here). Every window of the type has
    // these leaves, so their contexts are looked up once here, not for each window.
    std::array<LeafContext, kLeaves> frame;
    std::array<std::array<std::int8_t, 64>, kLeaves> context_reads{};
};

/// The context of leaf n of the window of type t with this pattern (bit i: reads[i] fine):
/// detail::coarse_leaf_context of the leaf, from the type's tables.
[[nodiscard]] LeafContext leaf_context(const WindowType& t, std::size_t n, std::uint64_t pattern);

[[nodiscard]] std::vector<int> reach_bits(const TransitionRule& rule);
/// The local octant (each in {-2..1}) of neighbourhood bit b.
[[nodiscard]] std::array<int, 3> local_of_bit(int b);
/// The lemma (compositional.hpp, 2) over every context it concerns, into result.
void check_lemma(const TransitionRule& rule, CompositionalResult& result);
[[nodiscard]] WindowType window_type(const std::array<int, 3>& parity, const TransitionRule& rule);
/// Every distinct window of a type (one witness pattern each: bit i = reads[i] fine).
[[nodiscard]] std::vector<std::uint64_t> distinct_windows(const WindowType& t, const TransitionRule& rule, int& shared_count);
/// B(g) for one pattern, translated so that g is the origin: [-U, U]^3.
[[nodiscard]] ConfigurationComplex build_window(const WindowType& t, std::uint64_t pattern, const TransitionRule& rule,
                                                detail::TemplateCache& cache);
/// The same before its CellComplex is made (configuration_parts.hpp): build_window is
/// complete() of it.
[[nodiscard]] detail::ConfigurationParts window_parts(const WindowType& t, std::uint64_t pattern,
                                                      const TransitionRule& rule, detail::TemplateCache& cache);
/// The coarse leaves of that window with what the rule places there (build_window's
/// coarse_leaves, without building). Throws what the rule throws.
[[nodiscard]] std::vector<PlacedLeaf> coarse_placements(const WindowType& t, std::uint64_t pattern,
                                                        const TransitionRule& rule);
[[nodiscard]] std::string describe(const std::array<int, 3>& parity, const std::vector<Index3>& reads,
                                   std::uint64_t pattern);

}  // namespace dualhex::compositional_detail
