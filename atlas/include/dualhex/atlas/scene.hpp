#pragma once
// Scene data of one atlas page: a complex as JSON for the page's three.js code.
//
// {"vertices": [[x,y,z],..] (lattice, integers), "faces": [[v0,v1,..],..] (stored loops),
//  "cells": [{"faces": [[f, side],..], "role", "element", "label"},..],
//  "dual": {"points": [[sx,sy,sz,d],..] (exact: the point is (sx,sy,sz)/d),
//           "hexes": [[p0..p7],..] (VTK_HEXAHEDRON order)}}
// Roles come from the cell labels of the .element files (see role_of_label).
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/topology/cell_complex.hpp"

namespace dualhex::atlas {

/// What a cell is, for colouring: "chain" (the prisms of a chain and the cells over a
/// crossing), "bend" (a turning chain's bend cell, a convex-edge tetrahedron), "lid" (the
/// cell above the chains), "corner" (the MR corner cuts), "rest" (the C elements' rest of
/// the leaf), "hex" (a plain coarse leaf), "fine" (a fine hex).
[[nodiscard]] std::string role_of_label(const std::string& label);

struct SceneCell {
    std::string element, label, role;
};

/// One SceneCell per cell of the element (its labels, in file order).
[[nodiscard]] std::vector<SceneCell> element_cells(const Element& element);

/// One SceneCell per cell of an installed configuration: a cell belongs to the coarse leaf
/// containing its vertex centroid (strictly inside exactly one leaf); the cells of a leaf,
/// in index order, are its element's cells in file order (the builder keeps the order in
/// which the leaf was emitted). Cells outside every coarse leaf are fine hexes.
/// `leaf_box` gives a placed leaf's min corner and size in lattice units (the builders
/// store PlacedLeaf::leaf in different units).
struct LeafBox {
    LatticePoint lo;
    std::int64_t size = 0;
};
[[nodiscard]] std::vector<SceneCell> configuration_cells(const ConfigurationComplex& configuration,
                                                         const ElementLibrary& library,
                                                         const std::function<LeafBox(const PlacedLeaf&)>& leaf_box);

enum class DualKind { Interior, Clipped };

/// The scene of a complex (cells.size() == complex.n_cells()). Interior: the hexes of the
/// interior vertices (dual points = cell centroids); Clipped: the clipped dual (one hex per
/// vertex, boundary vertices included).
[[nodiscard]] nlohmann::json scene_json(const CellComplex& complex, const std::vector<SceneCell>& cells, DualKind dual);

/// {"3": n, ..} from a histogram.
[[nodiscard]] nlohmann::json histogram_json(const std::map<int, std::size_t>& histogram);

}  // namespace dualhex::atlas
