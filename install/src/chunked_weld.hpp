#pragma once
// Internal: welding the leaves' cells into one complex in parallel, numbered exactly as
// one ComplexBuilder fed the leaves in order would number them.
//
// The leaves are cut into chunks of consecutive leaves; each chunk is emitted into its own
// builder (its vertices and faces in first-use order within the chunk). A serial run numbers
// a vertex (face) when it first occurs, i.e. in the first chunk holding it, at its place in
// that chunk's first-use order: so the vertices a chunk owns (those no earlier chunk holds)
// get consecutive ids after those of all earlier chunks, in the chunk's own order, and the
// others take their owner's id. Owners come from a shared table (owner_table.hpp) keyed by
// lattice point (vertex) or by the loop over global vertex ids up to rotation and reversal
// (face); a face keeps its owner's stored loop, and a half-face of another chunk flips its
// side where that chunk first met the face in the opposite direction. Cells stay in leaf
// order. Every step is a pure function of the chunks' contents, so the complex is the same
// for any number of threads (and equal to the serial builder's).
#include <cstdint>
#include <functional>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/complex_builder.hpp"

namespace dualhex::detail {

/// Emits the cells of leaves [begin, end), in leaf order, into the builder, calling
/// leaf_done() after each leaf (called once per chunk, for several chunks at once; a range
/// lets the caller keep per-chunk state, e.g. a dense corner welder over the chunk's box).
using EmitRange = std::function<void(ComplexBuilder& builder, std::size_t begin, std::size_t end,
                                     const std::function<void()>& leaf_done)>;

/// The welded complex of leaves [0, n_leaves); leaf_cells gets n_leaves + 1 offsets
/// (cells of leaf n: [leaf_cells[n], leaf_cells[n + 1])).
[[nodiscard]] CellComplex weld_chunks(std::size_t n_leaves, std::size_t chunk_leaves, const EmitRange& emit,
                                      std::vector<std::uint32_t>& leaf_cells);

}  // namespace dualhex::detail
