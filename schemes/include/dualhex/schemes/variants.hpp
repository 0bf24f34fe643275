#pragma once
// Chain-crossing variants (issue 4; docs/scheme-derivation.md, "Crossing variants").
//
// A crossing region is the part of a transition where chains cross: flat (one interface
// face, one crossing, 2 choices), concave edge (two interface faces, the chain turning around
// the edge crosses two chains: 4 choices), concave corner (three interface faces, three
// turning chains crossing pairwise: 8 choices). Each choice is built here as one leaf's
// complex from the same parts the prototype uses (schemes/derivation/elems.py: the lower
// chain's prisms at a crossing, the upper chain's cell over them, and the turning chain's
// bend cell in its four forms), all on the integer lattice of the canonical leaf [0,12]^3
// with the application point at the origin (kLeaf = 12, kLow = 3, kHalf = 6).
//
// The lid is the complement of the other cells (autolid.py's with_lid): every vertex lying
// inside an edge of another face is inserted into that face (T-junctions); the lid's faces
// are the other cells' faces used once that are not on the leaf boundary, plus, on every
// leaf face, the boundary loops of the region the other cells do not cover. Each cell's
// faces are then oriented consistently (BFS over shared edges) and outward (sign of the
// exact signed volume) and the complex is built by ComplexBuilder.
//
// Frames (those of the shipped elements):
//   flat           interface y = 0; chains over the mid-planes x = 12 (runs along z) and
//                  z = 12 (runs along x) cross at (12,0,12). Choice: the axis the lower
//                  chain runs along ('x' = F as shipped, 'z' = its mirror).
//   concave edge   interfaces y = 0 and z = 0; the chain over x = 12 turns around the x-edge
//                  and crosses the chain over z = 12 at (12,0,12) (face y = 0) and the chain
//                  over y = 12 at (12,12,0) (face z = 0). Choice "<sy><sz>": the turning chain
//                  passes below ('L') or above ('U') at each. LL = E, LU = VS.
//   concave corner interfaces x = 0, y = 0, z = 0; three turning chains (over x = 12, y = 12,
//                  z = 12; named X, Y, Z). Choice "<ly><lz><lx>": which chain passes below
//                  on face y = 0 (X or Z), on face z = 0 (X or Y), on face x = 0 (Y or Z).
//                  XYZ = VC (cyclic), ZXY its mirror; the other six are not cyclic.
#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dualhex/schemes/element.hpp"
#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/cube_symmetry.hpp"
#include "dualhex/topology/lattice.hpp"

namespace dualhex::variants {

inline constexpr std::int64_t kLeaf = 12;  ///< U: the leaf is [0,12]^3
inline constexpr std::int64_t kHalf = 6;   ///< H = U/2: mid-planes, standard apex height
inline constexpr std::int64_t kLow = 3;    ///< L = U/4: the low apex at a crossing

enum class Region { Flat, ConcaveEdge, ConcaveCorner };
[[nodiscard]] const char* to_string(Region region);        ///< "flat", "concave_edge", "concave_corner"
[[nodiscard]] std::size_t assignment_count(Region region);  ///< 2, 4, 8

/// A face as a loop of lattice points; a cell as a labelled list of faces.
using Loop = std::vector<LatticePoint>;
struct PartCell {
    std::string label;
    std::vector<Loop> faces;
};

/// Thrown when the parts do not close into cells (an edge in != 2 faces of a cell, a cell
/// whose faces are disconnected or of zero volume, a non-simple uncovered region).
class VariantConstructionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The cells plus the lid by complement (the lid is labelled `lid_label`), T-junctions
/// inserted in every face; loops not yet oriented.
[[nodiscard]] std::vector<PartCell> with_lid(std::vector<PartCell> cells, const std::string& lid_label = "lid");

/// Orients every cell outward and builds the complex (cell k = cells[k]).
[[nodiscard]] CellComplex build_complex(const std::vector<PartCell>& cells);

/// One over/under assignment of a region, built.
struct Variant {
    Region region = Region::Flat;
    std::string assignment;  ///< "x"/"z", "LL".."UU", "XYZ".. (see the header comment)
    std::string name;        ///< element name: "flat-x", "edge-LU", "corner-XYZ"
    std::vector<PartCell> cells;  ///< oriented outward, lid last
    std::vector<std::string> labels;
    std::vector<int> bend_cells;  ///< indices of the turning chains' bend cells (none if flat)
    CellComplex complex;

    /// element_from_complex(name, kLeaf, complex, labels).
    [[nodiscard]] ElementData element_data() const;
};

/// Builds one assignment; throws std::invalid_argument for an unknown assignment string.
[[nodiscard]] Variant build_variant(Region region, const std::string& assignment);
/// The assignments of a region in a fixed order ("x","z" / "LL","LU","UL","UU" /
/// "XXY","XXZ","XYY","XYZ","ZXY","ZXZ","ZYY","ZYZ").
[[nodiscard]] std::vector<std::string> assignments(Region region);
/// Every assignment of a region, built.
[[nodiscard]] std::vector<Variant> region_variants(Region region);

/// The shipped element equal to an assignment, if any: flat x -> F, edge LL -> E,
/// edge LU -> VS, corner XYZ -> VC (the others are mirrors or not shipped): "" otherwise.
[[nodiscard]] std::string shipped_counterpart(Region region, const std::string& assignment);

// ---- canonical forms -----------------------------------------------------------------

/// A complex as lattice data: each cell as the sorted list of its faces, each face as its
/// cyclic loop of positions rotated to start at the smallest point, in the smaller of its two
/// directions; cells sorted. Two complexes with equal forms are equal up to relabelling.
using ComplexForm = std::vector<std::vector<std::vector<LatticePoint>>>;
[[nodiscard]] ComplexForm complex_form(const CellComplex& complex, const CubeSymmetry& symmetry = {});

/// The 6 axis permutations: the symmetries that fix the origin (the application point) and
/// the leaf [0,U]^3.
[[nodiscard]] const std::array<CubeSymmetry, 6>& leaf_symmetries();

/// The lexicographically smallest complex_form over leaf_symmetries(): an exact
/// isomorphism invariant of an element in its leaf under those symmetries.
[[nodiscard]] ComplexForm canonical_form(const CellComplex& complex);

/// The symmetries s among leaf_symmetries() with complex_form(b, s) == complex_form(a).
[[nodiscard]] std::vector<CubeSymmetry> symmetries_mapping(const CellComplex& a, const CellComplex& b);

// ---- face statistics -------------------------------------------------------------------

/// size -> count over the distinct faces of the given cells.
[[nodiscard]] std::map<int, std::size_t> cells_face_histogram(const CellComplex& complex, const std::vector<int>& cells);

}  // namespace dualhex::variants
