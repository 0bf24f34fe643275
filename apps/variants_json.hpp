#pragma once
// JSON form of the crossing-variant report (dualhex variants --json, dualhex verify).
#include <nlohmann/json.hpp>

#include "dualhex/checkers/variants_report.hpp"

namespace dualhex::app {

/// {"flat": {...}, "concave_edge": {...}, "concave_corner": {...}, ["combined": {...}], "ok"}:
/// per region "mask", "assignments", "valid", "classes", "variants" [...], "ranking" [per class
/// by rank: "rank", "members", "bend_face_size", "bend_faces", "element_faces",
/// "dual_edge_valences", "max_valence", "singular_edges", "shipped"].
[[nodiscard]] nlohmann::json variants_json(const variants::VariantsReport& report);

}  // namespace dualhex::app
