#pragma once
// The checks of an installed grid, the production path's own post-condition: cheap
// enough (linear) to run after every install, and what `dualhex install` and the mesher
// refuse to go on without.
#include <cstddef>
#include <map>
#include <string>

#include "dualhex/install/install.hpp"
#include "dualhex/topology/progress.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {

/// The checks of an installed grid: validate (every interior check), plus open faces
/// (faces in one cell off the root cube's surface: holes where placed elements do not
/// match, which validate alone would take for boundary; their vertices and edges are
/// valence-checked and violations added to `validation`), the dual and the histograms.
struct InstallVerification {
    ValidationReport validation;
    std::size_t open_faces = 0;
    std::size_t interior_vertices = 0, hexes = 0;
    std::map<int, std::size_t> face_sizes, dual_edge_valences;
    [[nodiscard]] bool ok() const { return validation.ok() && open_faces == 0 && hexes == interior_vertices; }
    [[nodiscard]] std::string summary() const;
};
/// `progress` (optional): before each of its kVerifySteps steps ("validate", "open faces",
/// "interior dual", "valences"), the steps done of kVerifySteps.
[[nodiscard]] InstallVerification verify_installation(const InstallResult& installed, const Progress& progress = {});
inline constexpr std::size_t kVerifySteps = 4;

}  // namespace dualhex
