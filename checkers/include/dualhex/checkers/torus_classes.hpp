#pragma once
// Classes of periodic configurations under the motions of their torus (used by the
// certificate producer, proofs/README.md "Translation and symmetry classes").
//
// A configuration torus is 2x2x2 octant cubes of side `octant` lattice units (period
// 2 * octant). A motion is a cube symmetry about the origin (a corner of every octant cube)
// followed by a shift by whole octant cubes, modulo the period: it maps octant cubes onto
// octant cubes, octant b (bit a set: the upper cube along axis a) to apply_octant(b). There
// are 48 * 8 = 384 of them. A reflection (determinant -1) reverses every face loop, so a
// moved cell's faces still run counter-clockwise seen from outside.
//
// torus_classes groups labelled configurations: a label's class is its orbit under the given
// motions (moving its octant data), and for every member the torus AS BUILT must literally be
// the image of the representative's (same cells, same oriented faces, same positions modulo
// the period) under some motion mapping the representative to it. Nothing is assumed about
// the rule's equivariance: a member no motion reproduces is an error.
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/cube_symmetry.hpp"
#include "dualhex/topology/progress.hpp"

namespace dualhex {

struct TorusMotion {
    CubeSymmetry symmetry;  ///< about the origin
    int shift = 0;          ///< bit a set: then shifted by one octant cube along axis a

    /// The image of p, reduced modulo the period 2 * octant.
    [[nodiscard]] LatticePoint apply(const LatticePoint& p, std::int64_t octant) const;
    /// The image of octant cube b (0..7).
    [[nodiscard]] int apply_octant(int b) const;
    [[nodiscard]] TorusMotion inverse() const;
    /// "(x,y,z)->(-y,x,z) + shift (1,0,0) octants".
    [[nodiscard]] std::string to_string() const;
};

/// The 8 shifts (identity first).
[[nodiscard]] std::vector<TorusMotion> torus_translations();
/// All 384 motions: symmetry index major, shift minor (identity first).
[[nodiscard]] std::vector<TorusMotion> torus_motions();

/// The complex's cells moved by `motion`, each as the sorted list of its oriented faces, each
/// face its loop of positions rotated to start at its smallest point: two complexes have equal
/// sets iff they are the same up to numbering.
using CanonicalCells = std::set<std::vector<std::vector<LatticePoint>>>;
[[nodiscard]] CanonicalCells canonical_cells(const CellComplex& complex, const TorusMotion& motion,
                                             std::int64_t octant);

/// std::runtime_error naming `what` unless every vertex lies in [0, 2 * octant)^3 and the
/// complex is closed (every vertex interior): a torus as the certificates state it.
void require_closed_torus(const CellComplex& complex, std::int64_t octant, const std::string& what);

struct TorusClass {
    std::size_t representative = 0;  ///< the smallest label of the class
    /// Every member (the representative first, with the identity) and a motion taking the
    /// representative's torus onto the member's.
    std::vector<std::pair<std::size_t, TorusMotion>> members;
};

/// Labels 0..n-1 grouped into classes, in order of their representatives. `image(label,
/// motion)` is the label of the moved configuration, `build(label)` its torus as built.
/// std::runtime_error naming the label if a member's torus is not the image of the
/// representative's under any motion of `motions` mapping one label to the other.
/// `progress` (optional) sees `stage` as the labels classified of n.
[[nodiscard]] std::vector<TorusClass> torus_classes(std::size_t n,
                                                    const std::function<std::size_t(std::size_t, const TorusMotion&)>& image,
                                                    const std::function<CellComplex(std::size_t)>& build,
                                                    const std::vector<TorusMotion>& motions, std::int64_t octant,
                                                    const Progress& progress = {}, std::string_view stage = {});

}  // namespace dualhex
