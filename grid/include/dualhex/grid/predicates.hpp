#pragma once
// Grid predicates with diagnostics: each names one offending pair of leaves (with source
// lines when the grid was read from a file), so a failing grid can be fixed or shrunk.
#include <cstddef>
#include <optional>
#include <string>

#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"

namespace dualhex {

struct GridCheck {
    bool ok = true;
    /// Indices (into the grid) of an offending pair; set iff !ok.
    std::optional<std::size_t> first, second;
    /// Empty iff ok, e.g. "f.leaves: not weakly balanced: leaves 3 4 4 4 (line 9) and
    /// 1 0 1 1 (line 2) share a face but differ by 2 levels" (file only if read from one).
    std::string message;

    explicit operator bool() const { return ok; }
};

/// Paired: for every leaf, its 7 siblings (same parent) are leaves too. The witness pair is
/// a leaf and a finer leaf inside one of its siblings.
[[nodiscard]] GridCheck is_paired(const LeafGrid& grid);
/// Leaves in contact (through the contacts `mode` constrains) differ by <= 1 level.
[[nodiscard]] GridCheck is_balanced(const LeafGrid& grid, Balance mode);
/// Vertex-, edge- and face-sharing leaves differ by at most one level.
[[nodiscard]] GridCheck is_strongly_balanced(const LeafGrid& grid);
/// Face-sharing leaves differ by at most one level.
[[nodiscard]] GridCheck is_weakly_balanced(const LeafGrid& grid);

}  // namespace dualhex
