#pragma once
// All 256 configurations for one rule: each on the 3-torus and in its cube window, and a
// per-class summary (grid's ConfigurationSpace, 48 symmetries: 22 classes).
#include <iosfwd>
#include <set>
#include <string>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex {

struct ClassSummary {
    std::uint8_t representative = 0;  ///< smallest mask of the class
    int fine = 0;                     ///< fine octants of every member
    int configurations = 0;           ///< members (orbit size)
    int periodic_passed = 0, window_passed = 0;
    // The torus of `shown` (the representative, or the first member whose torus could
    // be built, if the representative's could not):
    std::uint8_t shown = 0;
    std::size_t cells = 0;
    std::size_t hexes = 0;  ///< interior vertices with a cube dual cell
    std::size_t checked_vertices = 0;
    std::map<int, std::size_t> face_sizes, dual_edge_valences;
    std::set<std::string> elements;  ///< placed over all members, torus and window
    std::string first_error;         ///< first rule/library error or failing check among members
    [[nodiscard]] bool passed() const { return periodic_passed == configurations && window_passed == configurations; }
};

struct ExhaustiveResult {
    std::string rule;
    std::vector<ConfigurationReport> periodic, window;  ///< indexed by mask (256 each)
    std::vector<ClassSummary> classes;                  ///< by representative
    int periodic_passed = 0, window_passed = 0;
    double seconds = 0;
    [[nodiscard]] bool all_passed() const { return periodic_passed == 256 && window_passed == 256; }
};

[[nodiscard]] ExhaustiveResult run_exhaustive(const TransitionRule& rule, const ElementLibrary& library);

/// A table, one row per class: representative, fine count, members, passed (torus/window),
/// cells, hexes, F histogram, dual valence histogram, elements, first error; then totals.
void print(std::ostream& os, const ExhaustiveResult& result);

}  // namespace dualhex
