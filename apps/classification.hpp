#pragma once
// The configuration classification as the CLI reports it: a thin adapter over
// grid/include/dualhex/grid/configurations.hpp, so `classify` and `verify` share one
// wiring point.
#include <vector>

namespace dualhex::app {

/// Numbers stated by the paper (section "20cases"): 22 classes under the 48 cube
/// symmetries, 20 without the all-coarse and all-fine ones. Under the 24 rotations alone
/// Burnside's lemma gives 23 (DESIGN.md section 2).
inline constexpr int kPaperClassesFullGroup = 22;
inline constexpr int kPaperNontrivialClasses = 20;
inline constexpr int kExpectedClassesRotations = 23;

struct ClassRow {
    int representative = 0;  ///< canonical 8-bit mask (bit o set = octant o fine)
    int size = 0;            ///< number of masks in the class (orbit size, full group)
    int fine_octants = 0;    ///< popcount of the representative
};

struct Classification {
    int configurations = 0;       ///< 256
    int classes_full_group = 0;   ///< orbits under the 48 symmetries
    int classes_rotations = 0;    ///< orbits under the 24 rotations
    int nontrivial_classes = 0;   ///< full-group classes without all-coarse / all-fine
    std::vector<ClassRow> classes;  ///< full-group classes, by representative
};

/// Computes the classification with the grid layer's code (grid/configurations.hpp).
Classification compute_classification();

}  // namespace dualhex::app
