#pragma once
// Writing the atlas: every page as a self-contained HTML file (its JSON embedded in a
// <script type="application/json"> block, since fetch() of local files fails under
// file://), the page template's JS/CSS and three.js copied into DIR/assets, an index, and
// DIR/atlas.json (every page's tables, for tests and scripts).
//
// The template (page.html, atlas.js, atlas.css) is found at $DUALHEX_ATLAS_SITE if set,
// else <exe>/../share/dualhex/atlas, else this source tree's atlas/site. three.js (the
// global-namespace build three.min.js) at $DUALHEX_THREE_JS if set, else Debian's
// libjs-three (/usr/share/javascript/three/three.min.js).
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "dualhex/atlas/pages.hpp"

namespace dualhex::atlas {

/// Something the site needs is missing (template, three.js), or the output is refused.
struct SiteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Every page, cross-linked: elements <-> the transitions, weak classes and variants using them.
[[nodiscard]] std::vector<Page> all_pages(const ElementLibrary& library);

/// Throws SiteError unless `dir` does not exist, is an empty directory, or `force`
/// (a non-directory is refused even with --force).
void check_output_directory(const std::filesystem::path& dir, bool force);

[[nodiscard]] std::filesystem::path site_template_directory();
[[nodiscard]] std::filesystem::path three_js_file();

/// Writes the site; returns the atlas.json document.
nlohmann::json write_site(const std::vector<Page>& pages, const std::filesystem::path& dir, bool force);

}  // namespace dualhex::atlas
