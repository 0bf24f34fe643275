#pragma once
// Internal: exact loop tools shared by the variant assembly, the lid and the canonical forms.
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "dualhex/schemes/variants.hpp"

namespace dualhex::variants::detail {

using Faces = std::vector<Loop>;
using UEdge = std::pair<LatticePoint, LatticePoint>;  ///< an undirected edge, smaller point first

[[nodiscard]] LatticePoint cross(const LatticePoint& a, const LatticePoint& b);
[[nodiscard]] std::int64_t dot(const LatticePoint& a, const LatticePoint& b);
/// p strictly inside the segment ab (exact).
[[nodiscard]] bool on_segment(const LatticePoint& p, const LatticePoint& a, const LatticePoint& b);
/// The loop with every point of `verts` lying strictly inside one of its edges inserted.
[[nodiscard]] Loop insert_tjunctions(const Loop& loop, const std::set<LatticePoint>& verts);
/// cx.canon_face: the loop rotated to its smallest point, in the smaller direction.
[[nodiscard]] Loop canonical_loop(const Loop& loop);
/// (axis, value) of the leaf face containing the loop, or axis -1.
[[nodiscard]] std::pair<int, std::int64_t> leaf_face_of(const Loop& f);
[[nodiscard]] UEdge uedge(const LatticePoint& a, const LatticePoint& b);
[[nodiscard]] std::string point_string(const LatticePoint& p);
/// cx.orient_cell: consistent by BFS over shared edges, outward by the signed volume.
/// Throws VariantConstructionError naming `label`.
[[nodiscard]] Faces orient_cell(Faces faces, const std::string& label);

}  // namespace dualhex::variants::detail
