// dualhex element: the atomic elements of the element library (schemes/), with their
// face-size histograms next to the paper's Table "topology".
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "histogram_format.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/paper_table.hpp"
#include "dualhex/topology/histograms.hpp"

namespace dualhex::app {
namespace {

struct ElementOptions {
    std::string name;
    bool list = false;
    bool json = false;
    std::string dir;
};

std::filesystem::path directory(const ElementOptions& opt) {
    return opt.dir.empty() ? default_elements_directory() : std::filesystem::path(opt.dir);
}

nlohmann::json paper_json(const std::optional<PaperRow>& row) {
    if (!row) return nullptr;
    nlohmann::json j = nlohmann::json::object();
    for (int s = kPaperMinFaceSize; s <= kPaperMaxFaceSize; ++s) j["F" + std::to_string(s)] = row->count(s);
    return j;
}

struct PaperStatus {
    std::optional<PaperRow> row;
    std::optional<PaperComparison> cmp;
    [[nodiscard]] bool matches() const { return cmp && cmp->matches(); }
};

PaperStatus paper_status(const Element& e, const std::map<int, std::size_t>& hist) {
    PaperStatus s;
    s.row = paper_row(e.name);
    if (s.row) s.cmp = compare_with_paper(hist, *s.row);
    return s;
}

void show_element(const Element& e, bool json) {
    const auto& cx = e.complex;
    const auto hist = face_size_histogram(cx);
    const auto paper = paper_status(e, hist);
    const auto labels = e.cell_labels();
    if (json) {
        nlohmann::json vertices = nlohmann::json::array(), faces = nlohmann::json::array(),
                       cells = nlohmann::json::array(), sides = nlohmann::json::array();
        for (const auto& p : cx.positions()) vertices.push_back({p.x, p.y, p.z});
        for (std::size_t f = 0; f < cx.n_faces(); ++f) {
            nlohmann::json loop = nlohmann::json::array();
            for (auto v : cx.face_vertices(FaceHandle(f))) loop.push_back(v.idx);
            faces.push_back(loop);
        }
        for (std::size_t c = 0; c < cx.n_cells(); ++c) {
            nlohmann::json fl = nlohmann::json::array(), sl = nlohmann::json::array();
            for (auto h : cx.cell_halffaces(CellHandle(c))) {
                fl.push_back(h.face().idx);
                sl.push_back(h.side());
            }
            cells.push_back(fl);
            sides.push_back(sl);
        }
        print_json({{"name", e.name},
                    {"file", e.file.string()},
                    {"leaf", e.leaf()},
                    {"vertices", vertices},
                    {"faces", faces},
                    {"cells", cells},
                    {"cell_sides", sides},
                    {"cell_labels", labels},
                    {"counts",
                     {{"vertices", cx.n_vertices()},
                      {"edges", cx.n_edges()},
                      {"faces", cx.n_faces()},
                      {"cells", cx.n_cells()}}},
                    {"valid", e.valid()},
                    {"face_histogram", histogram_json(hist)},
                    {"paper", paper_json(paper.row)},
                    {"matches_paper", paper.matches()}});
        return;
    }
    std::printf("element %s (%s), leaf [0,%lld]^3, %s\n", e.name.c_str(), e.file.string().c_str(),
                static_cast<long long>(e.leaf()), e.valid() ? "valid" : "INVALID");
    std::printf("vertices %zu, edges %zu, faces %zu, cells %zu\n", cx.n_vertices(), cx.n_edges(), cx.n_faces(),
                cx.n_cells());
    std::printf("cells (face sizes):\n");
    for (std::size_t c = 0; c < cx.n_cells(); ++c) {
        std::string sizes;
        for (auto h : cx.cell_halffaces(CellHandle(c)))
            sizes += " " + std::to_string(cx.face_vertices(h.face()).size());
        std::printf("  %-8s %2zu faces:%s\n", c < labels.size() ? labels[c].c_str() : "?",
                    cx.cell_halffaces(CellHandle(c)).size(), sizes.c_str());
    }
    if (!paper.row) {
        std::printf("face sizes:");
        for (const auto& [size, n] : hist) std::printf(" F%d=%zu", size, n);
        std::printf("\nno row for '%s' in the paper's table\n", e.name.c_str());
        return;
    }
    std::printf("face sizes  computed  paper\n");
    for (const auto& col : paper.cmp->columns)
        std::printf("  F%d        %6zu %6zu  %s\n", col.face_size, col.computed, col.paper,
                    col.equal() ? "=" : "differs");
    for (const auto& [size, n] : paper.cmp->outside_table)
        std::printf("  F%-2d       %6zu      -  differs (no column in the paper)\n", size, n);
    std::printf("%s the paper's row %s\n", paper.matches() ? "matches" : "DIFFERS from", e.name.c_str());
}

void list_elements(const std::filesystem::path& dir, bool json) {
    const auto scan = scan_elements(dir);
    bool all_valid = true;
    nlohmann::json arr = nlohmann::json::array();
    if (!json) std::printf("elements in %s\n%-8s %-8s %-26s %s\n", dir.string().c_str(), "name", "valid", "face sizes", "paper");
    for (const auto& s : scan) {
        if (!s.element) {
            all_valid = false;
            if (json)
                arr.push_back({{"file", s.file.string()}, {"valid", false}, {"error", s.error}});
            else
                std::printf("%-8s %-8s %s\n", s.file.stem().string().c_str(), "ERROR", s.error.c_str());
            continue;
        }
        const Element& e = *s.element;
        all_valid = all_valid && e.valid();
        const auto hist = face_size_histogram(e.complex);
        const auto paper = paper_status(e, hist);
        if (json) {
            nlohmann::json issues = nlohmann::json::array();
            for (const auto& i : e.check.issues) issues.push_back(std::string(to_string(i.kind)) + ": " + i.message);
            arr.push_back({{"name", e.name},
                           {"file", e.file.string()},
                           {"valid", e.valid()},
                           {"issues", issues},
                           {"face_histogram", histogram_json(hist)},
                           {"paper", paper_json(paper.row)},
                           {"matches_paper", paper.matches()}});
            continue;
        }
        std::string sizes;
        for (const auto& [size, n] : hist) sizes += "F" + std::to_string(size) + "=" + std::to_string(n) + " ";
        std::string vs = paper.row ? (paper.matches() ? "= paper" : "differs: " + paper.cmp->summary()) : "no paper row";
        std::printf("%-8s %-8s %-26s %s\n", e.name.c_str(), e.valid() ? "yes" : "NO", sizes.c_str(), vs.c_str());
        if (!e.valid())
            for (std::size_t k = 0; k < e.check.issues.size() && k < 5; ++k)
                std::printf("         %s: %s\n", to_string(e.check.issues[k].kind), e.check.issues[k].message.c_str());
    }
    if (json) print_json({{"directory", dir.string()}, {"elements", arr}});
    if (!all_valid) throw Exit{kCheckFailed};
}

void run_element(const ElementOptions& opt) {
    if (opt.list == !opt.name.empty()) throw UsageError("give either an element NAME or --list");
    try {
        if (opt.list) {
            list_elements(directory(opt), opt.json);
            return;
        }
        const auto lib = ElementLibrary::load(directory(opt));
        const Element* e = lib.find(opt.name);
        if (!e) {
            std::string known;
            for (const auto& n : lib.names()) known += (known.empty() ? "" : ", ") + n;
            std::cerr << "error: unknown element '" << opt.name << "'; known elements: " << known << '\n';
            throw Exit{kUsage};
        }
        show_element(*e, opt.json);
    } catch (const SchemeFormatError& err) {
        std::cerr << "error: " << err.what() << '\n';
        throw Exit{kInputError};
    }
}

}  // namespace

void register_element(CLI::App& app) {
    auto opt = std::make_shared<ElementOptions>();
    auto* sub = app.add_subcommand("element", "Show an atomic element of the element library, or list them (--list)");
    sub->add_option("name", opt->name, "Element name (e.g. F, C1)");
    sub->add_flag("--list", opt->list, "List every element with its validity and face sizes vs the paper");
    sub->add_option("--dir", opt->dir,
                    "Element directory (default: $DUALHEX_ELEMENTS, <exe>/../share/dualhex/elements, or the source tree)");
    add_json_flag(*sub, opt->json);
    sub->footer("Exit codes: 0 ok, 1 --list found an invalid element, 2 unknown element or bad arguments,\n"
                "3 an element file is malformed or invalid (error: <file>[:<line>]: <message>).");
    sub->callback([opt] { run_element(*opt); });
}

}  // namespace dualhex::app
