#pragma once
// How well a hex mesh's boundary keeps the sharp features of its input: the measurement
// behind the features stage's tests and `dualhex mesh`'s report.
//
// In : a hex mesh (VTK order), the input surface, its FeatureSet, the crease angle (the
//      features' angle; a hex boundary edge is a crease iff the normals of its two
//      boundary quads deviate by more than half of it) and a tolerance as a fraction of
//      the surface's bounding-box diagonal.
// Out: CreaseMeasure. Sharp-edge samples: every input feature edge sampled at spacing
//      <= tolerance / 2 (both ends included); a sample is kept iff some crease edge lies
//      within the tolerance. A crease edge is spurious iff its midpoint is farther than the
//      tolerance from every input feature edge.
// A boundary edge shared by other than two boundary quads (non-manifold boundary) counts
// as a crease. Quad normal: cross product of the diagonals (defined for non-planar quads).
#include <cstddef>

#include "dualhex/geometry/feature_curves.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::mesher {

struct CreaseMeasure {
    std::size_t samples = 0;         ///< sharp-edge samples
    std::size_t samples_kept = 0;    ///< within the tolerance of a crease edge
    std::size_t crease_edges = 0;    ///< hex boundary crease edges
    std::size_t spurious_creases = 0;
    [[nodiscard]] double kept_share() const {
        return samples == 0 ? 1.0 : static_cast<double>(samples_kept) / static_cast<double>(samples);
    }
};

/// Throws std::invalid_argument for a tolerance <= 0 or an angle outside (0, 180).
[[nodiscard]] CreaseMeasure measure_creases(const geometry::HexMesh& mesh, const geometry::TriangleSurface& surface,
                                            const geometry::FeatureSet& features, double angle_degrees,
                                            double tolerance = 0.005);

}  // namespace dualhex::mesher
