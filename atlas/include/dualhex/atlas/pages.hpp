#pragma once
// The pages of the atlas, as data: one per element, strong transition class, weak class
// and crossing variant. Everything shown is computed here from the library (elements),
// the rule installed in the cube window (transitions, weak classes) and the variants
// report; nothing is typed in.
//
// Page JSON: {"id", "kind", "title", "summary", "scene" (scene.hpp), "tables": [{"id",
// "title", "columns": [..], "rows": [[..],..]},..], "links": [{"href", "text"},..]}.
// Table rows are [key, value, ..] with numbers as numbers.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "dualhex/schemes/element_library.hpp"

namespace dualhex::atlas {

struct Page {
    std::string id;  ///< file stem: "element-F", "transition-3", "weak-...", "variant-edge-LU"
    nlohmann::json data;
};

[[nodiscard]] std::string element_page_id(const std::string& element);
[[nodiscard]] std::string transition_page_id(int representative);
[[nodiscard]] std::string variant_page_id(const std::string& variant);

/// The 13 elements (face sizes next to the paper's row, clipped-dual edge valences,
/// counts, cells by role).
[[nodiscard]] std::vector<Page> element_pages(const ElementLibrary& library);
/// The 20 strong transitions, each installed by StrongRule in its class representative's
/// cube window (checkers/cube_window.hpp) with its interior dual.
[[nodiscard]] std::vector<Page> transition_pages(const ElementLibrary& library);
/// The weak classes with three levels, each installed by WeakRule in its window.
[[nodiscard]] std::vector<Page> weak_pages(const ElementLibrary& library);
/// The 14 crossing variants (schemes/variants.hpp), with their torus report.
[[nodiscard]] std::vector<Page> variant_pages(const ElementLibrary& library);

/// A table: {"id", "title", "columns", "rows"}.
[[nodiscard]] nlohmann::json table(const std::string& id, const std::string& title, std::vector<std::string> columns,
                                   nlohmann::json rows);
/// A table row [key, value] (a JSON array even when the key is a string).
[[nodiscard]] nlohmann::json row(const nlohmann::json& key, const nlohmann::json& value);
/// Rows [[size, count],..] of a histogram.
[[nodiscard]] nlohmann::json histogram_rows(const std::map<int, std::size_t>& histogram);
/// Element names linked to their pages.
[[nodiscard]] nlohmann::json element_links(const std::map<std::string, std::size_t>& elements);

}  // namespace dualhex::atlas
