#pragma once
// Part of stage "optimise": the hexes the optimiser left flat or inverted, freed by a local
// run that also chases flat hexes, and where that is not enough by releasing the feature
// roles that hold them.
//
// Why: a flat pad hex is mostly one whose boundary quad has three corners on one line, the
// middle one a Curve vertex between two of its curve neighbours (a feature path taking two
// edges of one quad) or a Corner: no move along the curve can take it off that line. The
// whole-mesh optimiser with bad_below = 1e-6 was measured slower and worse (optimise.hpp), so
// flat hexes are worked on here, on their region only.
//
// Input : the optimised mesh, its roles and curves, the surface's tree, the optimiser's
//         options (work_per_vertex per region vertex), the quality state, the check's
//         threshold `flat` (kFlatScaledJacobian).
// Output: the mesh, roles (released vertices become Surface, where they are) and quality
//         state; the figures. Steps: (1) optimise_region on the hexes <= flat with
//         bad_below = flat; (2) the same after the Curve vertices at their corners <= flat
//         are released; (3) after all their Curve vertices are; (4) after their Corner
//         vertices are released too. After each run every place it moved is judged alone
//         (place_guard.hpp): one with more inverted hexes, more <= flat or a lower minimum
//         is put back, and a released vertex that did not move keeps its role; the step is
//         then kept only if it leaves fewer hexes <= flat and no more inverted ones (else
//         points and roles are put back).
// Contract: no place has more inverted hexes, more hexes <= flat or a lower minimum than
//         in the input (so neither has the whole mesh); deterministic.
#include <cstddef>

#include "dualhex/mesher/optimise.hpp"

namespace dualhex::mesher {

struct ReleaseResult {
    std::size_t bad_before = 0, bad_after = 0;  ///< hexes <= flat
    std::size_t curves_released = 0, corners_released = 0;  ///< vertices whose role became Surface
    std::size_t work = 0;                        ///< vertex visits of the region runs
    std::size_t places_restored = 0;             ///< places a run left worse, put back (place_guard.hpp)
};

ReleaseResult release_stuck_hexes(geometry::HexMesh& mesh, VertexConstraints& constraints,
                                  const geometry::AabbTree& tree, const FeatureCurves& curves,
                                  const OptimiseOptions& options, QualityState& state, double flat);

}  // namespace dualhex::mesher
