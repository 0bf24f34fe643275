#pragma once
// Validation of an atomic element (one leaf's subdivision). An element is valid iff
//   (a) as a complex it passes DESIGN.md section 4 items 1-2 (topology `validate` with the
//       interior checks off reports nothing), and
//   (b) it exactly fills its leaf box, in exact integer arithmetic:
//       - every vertex lies in the box;
//       - every boundary face (in exactly one cell) lies in one of the six leaf-face planes;
//       - no interior face (in two or more cells) lies entirely in a leaf-face plane;
//       - each boundary face's twice-area vector (fan from the loop's first vertex, in the
//         orientation its cell uses) points out of the leaf, and on each of the six leaf
//         faces these twice-areas sum to 2 * leaf^2 (the boundary faces tile it);
//       - every cell has positive signed volume (x6: sum of the fan-triangle triple
//         products over its outward half-faces) and the cells' volumes sum to 6 * leaf^3.
// Every failure is reported, naming the cell/face and why.
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {

/// The leaf box [min, min + size]^3 (for an element file: min = origin, size = leaf).
struct ElementBox {
    LatticePoint min;
    std::int64_t size = 0;
};

enum class ElementIssueKind : int {
    Topology,                // a `validate` violation (see `violation`)
    VertexOutsideLeaf,       // a vertex outside the leaf box
    BoundaryFaceOffLeaf,     // a boundary face not contained in any leaf-face plane
    BoundaryFaceInward,      // a boundary face whose area vector does not point outward (or is 0)
    InteriorFaceOnLeafFace,  // a face shared by cells lying entirely in a leaf-face plane
    LeafFaceNotTiled,        // the boundary faces on one leaf face do not sum to leaf^2
    CellNonPositiveVolume,   // a cell with signed volume <= 0
    LeafUnderfilled,         // cell volumes sum to less than leaf^3
    LeafOverfilled,          // cell volumes sum to more than leaf^3
    Count
};
inline constexpr std::size_t kElementIssueKinds = static_cast<std::size_t>(ElementIssueKind::Count);

[[nodiscard]] const char* to_string(ElementIssueKind kind);

struct ElementIssue {
    ElementIssueKind kind{};
    ViolationKind violation{};  // meaningful iff kind == Topology
    FaceHandle face;            // invalid if not about one face
    CellHandle cell;            // invalid if not about one cell
    int leaf_face = -1;         // 0..5 = -x,+x,-y,+y,-z,+z, or -1
    std::string message;
};

struct ElementCheckReport {
    ValidationReport topology;
    std::vector<ElementIssue> issues;  // topology violations included (kind Topology)
    std::int64_t volume6 = 0;          // 6 x sum of cell volumes
    std::int64_t expected_volume6 = 0;

    [[nodiscard]] bool ok() const { return issues.empty(); }
    [[nodiscard]] std::size_t count(ElementIssueKind k) const;
    [[nodiscard]] bool has(ElementIssueKind k) const { return count(k) > 0; }
    /// True iff `validate` reported a violation of this kind.
    [[nodiscard]] bool has(ViolationKind k) const { return topology.count(k) > 0; }
    /// One line per issue ("<kind>: <message>"), at most `max_listed`.
    void print(std::ostream& os, std::size_t max_listed = 50) const;
};

/// Names of leaf faces: "-x", "+x", "-y", "+y", "-z", "+z".
[[nodiscard]] const char* leaf_face_name(int leaf_face);

/// Checks `complex` as a subdivision of `box`; `cell_labels` (optional, by cell index)
/// are used in messages.
[[nodiscard]] ElementCheckReport check_element(const CellComplex& complex, const ElementBox& box,
                                               const std::vector<std::string>& cell_labels = {});

struct ElementData;
/// Convenience: to_complex + check_element with box [0, leaf]^3 and the cell labels.
[[nodiscard]] ElementCheckReport check_element(const ElementData& element);

}  // namespace dualhex
