// Element and crossing-variant pages.
#include "dualhex/atlas/pages.hpp"

#include <algorithm>
#include <stdexcept>

#include "dualhex/atlas/scene.hpp"
#include "dualhex/checkers/variants_report.hpp"
#include "dualhex/schemes/paper_table.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/histograms.hpp"

namespace dualhex::atlas {

std::string element_page_id(const std::string& element) { return "element-" + element; }
std::string transition_page_id(int representative) { return "transition-" + std::to_string(representative); }
std::string variant_page_id(const std::string& variant) { return "variant-" + variant; }

nlohmann::json table(const std::string& id, const std::string& title, std::vector<std::string> columns,
                     nlohmann::json rows) {
    return {{"id", id}, {"title", title}, {"columns", columns}, {"rows", rows}};
}

nlohmann::json row(const nlohmann::json& key, const nlohmann::json& value) { return nlohmann::json::array({key, value}); }

nlohmann::json histogram_rows(const std::map<int, std::size_t>& histogram) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& [k, n] : histogram) rows.push_back(row(k, n));
    return rows;
}

nlohmann::json element_links(const std::map<std::string, std::size_t>& elements) {
    nlohmann::json links = nlohmann::json::array();
    for (const auto& [name, n] : elements)
        if (name != "hex" && name != "fine") links.push_back({{"href", element_page_id(name) + ".html"}, {"text", name}});
    return links;
}

namespace {

nlohmann::json counts_table(const CellComplex& complex) {
    return table("counts", "Counts", {"entity", "count"},
                 nlohmann::json::array({row("vertices", complex.n_vertices()), row("edges", complex.n_edges()),
                                        row("faces", complex.n_faces()), row("cells", complex.n_cells())}));
}

nlohmann::json roles_table(const std::vector<SceneCell>& cells) {
    std::map<std::string, std::size_t> roles;
    for (const auto& c : cells) ++roles[c.role];
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& [role, n] : roles) rows.push_back(row(role, n));
    return table("roles", "Cells by role", {"role", "cells"}, rows);
}

/// Face sizes with the paper's column beside (null where the element has no paper row).
nlohmann::json face_size_table(const std::string& name, const std::map<int, std::size_t>& faces) {
    const auto paper = paper_row(name);
    nlohmann::json rows = nlohmann::json::array();
    std::map<int, std::size_t> sizes = faces;
    if (paper)
        for (int k = kPaperMinFaceSize; k <= kPaperMaxFaceSize; ++k) sizes.try_emplace(k, 0);
    for (const auto& [k, n] : sizes)
        rows.push_back(nlohmann::json::array({k, n, paper ? nlohmann::json(paper->count(k)) : nlohmann::json()}));
    return table("face_sizes", "Face sizes (paper's Table \"topology\" beside)", {"size", "faces", "paper"}, rows);
}

/// " (= the paper's row)", " (the paper: F3 .. != ..)" or "" without a row.
std::string paper_note(const std::string& name, const std::map<int, std::size_t>& faces) {
    const auto row = paper_row(name);
    if (!row) return "";
    const auto comparison = compare_with_paper(faces, *row);
    return comparison.matches() ? " (= the paper's row)" : " (the paper: " + comparison.summary() + ")";
}

Page element_page(const Element& e) {
    const auto cells = element_cells(e);
    const auto faces = face_size_histogram(e.complex);
    const ClippedDual dual = clipped_dual(e.complex);
    nlohmann::json data = {
        {"id", element_page_id(e.name)}, {"kind", "element"}, {"title", "Element " + e.name},
        {"summary", std::string(e.valid() ? "valid" : "INVALID") + " subdivision of the leaf [0," +
                        std::to_string(e.leaf()) + "]^3, " + std::to_string(e.complex.n_cells()) + " cells, faces " +
                        format_histogram(faces) + paper_note(e.name, faces) +
                        "; the dual shown is the clipped dual (one hex per vertex)"},
        {"scene", scene_json(e.complex, cells, DualKind::Clipped)},
        {"tables", nlohmann::json::array({counts_table(e.complex), face_size_table(e.name, faces),
                    table("dual_valences", "Clipped dual: interior dual edge valences", {"valence", "edges"},
                          histogram_rows(clipped_dual_edge_valences(dual))),
                    roles_table(cells)})},
        {"links", nlohmann::json::array()}};
    return {element_page_id(e.name), data};
}

Page variant_page(const variants::Variant& v, const variants::RegionReport& region, std::size_t index) {
    const auto& r = region.variants[index];
    if (r.name != v.name) throw std::logic_error("atlas: variant report order differs from region_variants");
    std::vector<SceneCell> cells;
    for (std::size_t c = 0; c < v.labels.size(); ++c) {
        const bool bend = std::find(v.bend_cells.begin(), v.bend_cells.end(), int(c)) != v.bend_cells.end();
        cells.push_back({v.name, v.labels[c], bend ? "bend" : role_of_label(v.labels[c])});
    }
    int rank = 0;
    for (const auto& cls : region.classes)
        if (std::find(cls.members.begin(), cls.members.end(), index) != cls.members.end()) rank = cls.rank;
    nlohmann::json links = nlohmann::json::array();
    if (!r.shipped.empty()) links.push_back({{"href", element_page_id(r.shipped) + ".html"}, {"text", "shipped: " + r.shipped}});
    for (const auto& other : region.variants)
        if (other.name != v.name) links.push_back({{"href", variant_page_id(other.name) + ".html"}, {"text", other.name}});
    nlohmann::json data = {
        {"id", variant_page_id(v.name)}, {"kind", "variant"}, {"title", "Crossing variant " + v.name},
        {"summary", std::string(variants::to_string(v.region)) + " region, assignment " + v.assignment + ", rank " +
                        std::to_string(rank) + " of its region; " + (r.ok() ? "valid" : "INVALID") +
                        " on its torus (mask " + format_mask(region.mask) + ")"},
        {"scene", scene_json(v.complex, cells, DualKind::Clipped)},
        {"tables", nlohmann::json::array({counts_table(v.complex), table("face_sizes", "Face sizes of the element", {"size", "faces"},
                                                   histogram_rows(r.element_faces)),
                    table("bend_faces", "Faces of the bend cells", {"size", "faces"}, histogram_rows(r.bend_faces)),
                    table("dual_valences", "Torus: interior dual edge valences", {"valence", "edges"},
                          histogram_rows(r.torus.dual_edge_valences)),
                    roles_table(cells)})},
        {"links", links}};
    return {variant_page_id(v.name), data};
}

}  // namespace

std::vector<Page> element_pages(const ElementLibrary& library) {
    std::vector<Page> pages;
    for (const auto& e : library.elements()) pages.push_back(element_page(e));
    return pages;
}

std::vector<Page> variant_pages(const ElementLibrary& library) {
    std::vector<Page> pages;
    for (auto region : {variants::Region::Flat, variants::Region::ConcaveEdge, variants::Region::ConcaveCorner}) {
        const auto report = variants::check_region(region, library);
        const auto built = variants::region_variants(region);
        for (std::size_t i = 0; i < built.size(); ++i) pages.push_back(variant_page(built[i], report, i));
    }
    return pages;
}

}  // namespace dualhex::atlas
