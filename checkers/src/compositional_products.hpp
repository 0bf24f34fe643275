#pragma once
// Internal: the distinct windows of a window type, whichever the type (the compositional
// windows, compositional.cpp; the root-boundary half windows, compositional_boundary.cpp).
// A window is an assignment of the type's octant variables (bit i: variable i fine); what
// is checked depends only on the tuple of its leaves' outcomes, so one witness assignment
// per distinct tuple covers every window of the type.
#include <cstdint>
#include <vector>

namespace dualhex::compositional_detail {

/// One leaf of a window type: the variables its outcome depends on (sorted) and its
/// outcome id for each assignment of them (entry a: bit j of a is variable depends[j]).
struct LeafOutcomes {
    std::vector<int> depends;
    std::vector<int> table;
};

/// One witness assignment per distinct tuple of leaf outcomes (at most 8 leaves, at most 63
/// variables), in the order of the serial enumeration: the variables several leaves depend
/// on (shared_count of them) jointly, in increasing binary order, and for each of those the
/// product of each leaf's distinct outcomes over its private variables.
[[nodiscard]] std::vector<std::uint64_t> distinct_outcome_tuples(const std::vector<LeafOutcomes>& leaves,
                                                                 std::size_t variables, int& shared_count);

}  // namespace dualhex::compositional_detail
