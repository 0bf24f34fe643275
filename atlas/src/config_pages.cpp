// Transition and weak-class pages: a configuration installed by the rule in the window
// around its application point (checkers/cube_window.hpp, periodic_configuration.hpp).
#include <set>

#include "dualhex/atlas/pages.hpp"
#include "dualhex/atlas/scene.hpp"
#include "dualhex/checkers/cube_window.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/weak_exhaustive.hpp"
#include "dualhex/grid/configurations.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex::atlas {
namespace {

std::string position_name(const LatticePoint& leaf) {  // leaf min corner: < 0 or 0 per axis
    std::string s;
    for (int a = 0; a < 3; ++a) s += std::string(leaf[a] < 0 ? "-" : "+") + "xyz"[a];
    return s;
}

/// The coarse (non-fine) leaves with a corner at the application point (the origin): position, element.
nlohmann::json leaves_at_p(const ConfigurationComplex& configuration,
                           const std::function<LeafBox(const PlacedLeaf&)>& leaf_box) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& leaf : configuration.coarse_leaves) {
        const LeafBox box = leaf_box(leaf);
        bool at_p = true;
        for (int a = 0; a < 3; ++a) at_p = at_p && (box.lo[a] == -box.size || box.lo[a] == 0);
        if (!at_p) continue;
        rows.push_back(nlohmann::json::array({position_name(box.lo), leaf.placement ? leaf.placement->element : "hex",
                                              leaf.placement ? leaf.placement->symmetry.to_string() : ""}));
    }
    return table("leaves_at_p", "Coarse leaves at the application point", {"position", "element", "symmetry"}, rows);
}

nlohmann::json report_tables(const ConfigurationReport& report) {
    nlohmann::json elements = nlohmann::json::array();
    for (const auto& [name, n] : report.elements) elements.push_back(row(name, n));
    return nlohmann::json::array({table("counts", "Counts", {"entity", "count"},
                  nlohmann::json::array({row("vertices", report.vertices), row("edges", report.edges),
                                         row("faces", report.faces), row("cells", report.cells),
                                         row("checked interior vertices", report.checked_vertices),
                                         row("dual hexes", report.hexes)})),
            table("face_sizes", "Face sizes", {"size", "faces"}, histogram_rows(report.face_sizes)),
            table("dual_valences", "Interior dual edge valences", {"valence", "edges"},
                  histogram_rows(report.dual_edge_valences)),
            table("elements", "Placements", {"element", "leaves"}, elements)});
}

nlohmann::json configuration_page(const std::string& id, const std::string& kind, const std::string& title,
                                  const std::string& summary, const ConfigurationComplex& built,
                                  const ConfigurationReport& report, const ElementLibrary& library,
                                  const std::function<LeafBox(const PlacedLeaf&)>& leaf_box) {
    nlohmann::json tables = report_tables(report);
    tables.insert(tables.begin() + 1, leaves_at_p(built, leaf_box));
    return {{"id", id}, {"kind", kind}, {"title", title},
            {"summary", summary + (report.ok() ? "; the check passes" : "; THE CHECK FAILS: " + report.summary())},
            {"scene", scene_json(built.complex, configuration_cells(built, library, leaf_box), DualKind::Interior)},
            {"tables", tables}, {"links", element_links(report.elements)}};
}

std::string levels_name(const LevelAssignment& levels) {
    std::string s;
    for (auto l : levels) s += char('0' + l);
    return s;
}

}  // namespace

std::vector<Page> transition_pages(const ElementLibrary& library) {
    const ConfigurationSpace space(SymmetryGroup::Full);
    const StrongRule rule;
    std::vector<Page> pages;
    for (const auto& cls : space.classes()) {
        if (cls.fine == 0 || cls.fine == 8) continue;
        const auto built = build_cube_window(cls.representative, rule, library);
        const auto report = check_cube_window(cls.representative, rule, library);
        const std::string id = transition_page_id(cls.representative);
        pages.push_back({id, configuration_page(id, "transition",
                                                "Transition " + format_mask(cls.representative),
                                                std::to_string(cls.fine) + " fine octants, " + std::to_string(cls.size) +
                                                    " configurations in the class; the rule " + rule.name() +
                                                    " installed in the 4x4x4-leaf window around P",
                                                built, report, library, [&](const PlacedLeaf& leaf) {
                                                    return LeafBox{leaf.leaf * built.unit, built.unit};
                                                })});
    }
    return pages;
}

std::vector<Page> weak_pages(const ElementLibrary& library) {
    const WeakRule rule;
    std::set<LevelAssignment> classes;  // canonical forms of the three-level assignments
    std::map<LevelAssignment, int> members;
    for (const auto& levels : weak_configurations()) {
        if (*std::max_element(levels.begin(), levels.end()) < 2) continue;
        const auto c = canonical(levels);
        classes.insert(c);
        ++members[c];
    }
    std::vector<Page> pages;
    for (const auto& levels : classes) {
        std::array<int, 8> as_int{};
        for (int b = 0; b < 8; ++b) as_int[b] = levels[b];
        const auto built = build_window_levels(as_int, rule, library);
        const auto report = check_window_levels(as_int, rule, library);
        const std::string id = "weak-" + levels_name(levels);
        pages.push_back({id, configuration_page(id, "weak", "Weak class " + levels_name(levels),
                                                "octant levels " + levels_name(levels) + " (octant b = bit order), " +
                                                    std::to_string(members[levels]) +
                                                    " configurations in the class; the weak rule in the window",
                                                built, report, library, [&](const PlacedLeaf& leaf) {
                                                    // leaf.leaf is in lattice units; its size from its octant's level
                                                    int b = 0;
                                                    for (int a = 0; a < 3; ++a) b |= leaf.leaf[a] >= 0 ? 1 << a : 0;
                                                    return LeafBox{leaf.leaf, (2 * built.unit) >> as_int[b]};
                                                })});
    }
    return pages;
}

}  // namespace dualhex::atlas
