#pragma once
// Internal: congruence keys of the compositional windows (compositional.hpp), shared by the
// window check (which checks one window per class and proves every other one its image) and
// the window certificates (one certificate per class).
//
// A window is its 8 leaves, each fine, a plain hex or an element e placed by a world
// symmetry W (the complex depends on W only up to e's own symmetries, so W is taken modulo
// e's stabiliser). A symmetry s about g moves the leaf at box b to s(b) and W to s.W. The
// class key is the smallest such image over the 48 symmetries. The key only groups: a
// member is the image of its class's representative only if their exact lattice forms say
// so (variants::complex_form).
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex::detail {

using WindowKey = std::array<int, 8>;

// A placed element's code: its element (index in the library) and its world symmetry W
// taken modulo the element's own symmetries (the smallest index among W.S, S in its
// stabiliser). Read-only after construction, so threads may share one.
class PlacementCodes {
public:
    explicit PlacementCodes(const ElementLibrary& library);
    [[nodiscard]] int code(const std::string& element, const CubeSymmetry& W) const {
        return code(element_index(element), W.index());
    }
    /// The element's index in the library (throws std::out_of_range for an unknown name).
    [[nodiscard]] int element_index(const std::string& element) const { return index_.at(element); }
    /// code() by element index and W's index: a table (the class keys ask 48 times a leaf).
    [[nodiscard]] int code(int element, int W) const {
        return codes_[static_cast<std::size_t>(element * CubeSymmetry::kOrder + W)];
    }

private:
    std::map<std::string, int> index_;
    std::vector<int> codes_;  // [element * 48 + W]
};

/// The key of the window with these coarse leaves (min corners in coarse-leaf units, the
/// window B(g) around g = parity) under symmetry s about g.
[[nodiscard]] WindowKey window_image_key(const std::array<int, 3>& parity, const std::vector<PlacedLeaf>& coarse,
                                         const CubeSymmetry& s, const PlacementCodes& codes);

/// The class key (smallest image key) and the first symmetry giving it.
[[nodiscard]] std::pair<WindowKey, CubeSymmetry> window_class_key(const std::array<int, 3>& parity,
                                                                  const std::vector<PlacedLeaf>& coarse,
                                                                  const PlacementCodes& codes);

/// A root-boundary half window's key: the image of its root sides (a vector, +-1 on each
/// root axis) and of its inside coarse leaves (positions outside the root hold kFine, as
/// fine ones do; the sides tell them apart).
using BoundaryWindowKey = std::pair<std::array<std::int64_t, 3>, WindowKey>;
[[nodiscard]] std::pair<BoundaryWindowKey, CubeSymmetry> boundary_class_key(const std::array<int, 3>& parity,
                                                                            const std::array<int, 3>& sides,
                                                                            const std::vector<PlacedLeaf>& coarse,
                                                                            const PlacementCodes& codes);

}  // namespace dualhex::detail
