// Scheme checks for `dualhex verify`: the 8 strongly balanced elements against the
// paper's table, and the exhaustive check of all 256 configurations under StrongRule.
#include <algorithm>
#include <sstream>

#include "dualhex/checkers/exhaustive.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/paper_table.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/histograms.hpp"
#include "verify_checks.hpp"

namespace dualhex::app {
namespace {

CheckOutcome check_strong_elements() {
    const auto library = ElementLibrary::load_default();
    CheckOutcome out;
    out.details = nlohmann::json::object();
    std::ostringstream report;
    int equal = 0, total = 0;
    for (const auto& e : strong_elements()) {
        ++total;
        const auto& element = library.at(e.name);
        const auto histogram = face_size_histogram(element.complex);
        const auto row = paper_row(e.name);
        const bool same = row && element.valid() && compare_with_paper(histogram, *row).matches();
        if (same) ++equal;
        out.details[e.name] = {{"computed", face_size_columns(histogram)},
                               {"paper", row ? nlohmann::json(row->counts) : nlohmann::json()},
                               {"cells", element.complex.n_cells()},
                               {"valid", element.valid()},
                               {"equal", same}};
        report << "  " << e.name << ": " << format_histogram(histogram) << "  paper "
               << (row ? compare_with_paper(histogram, *row).summary() : std::string("missing")) << '\n';
    }
    out.status = equal == total ? CheckStatus::kPass : CheckStatus::kFail;
    out.summary = std::to_string(equal) + "/" + std::to_string(total) +
                  " elements valid and equal to the paper's Table \"topology\" rows";
    out.report = report.str();
    return out;
}

CheckOutcome check_strong_exhaustive() {
    const auto library = ElementLibrary::load_default();
    const StrongRule rule;
    const ExhaustiveResult r = run_exhaustive(rule, library);
    int max_valence = 0, nontrivial = 0;
    std::set<std::string> used;
    for (const auto& c : r.classes) {
        if (c.fine != 0 && c.fine != 8) ++nontrivial;
        if (!c.dual_edge_valences.empty()) max_valence = std::max(max_valence, c.dual_edge_valences.rbegin()->first);
        used.insert(c.elements.begin(), c.elements.end());
    }
    const int passed = static_cast<int>(std::count_if(r.periodic.begin(), r.periodic.end(), [&](const auto& p) {
        return p.ok() && r.window[p.mask].ok();
    }));
    CheckOutcome out;
    out.status = r.all_passed() && max_valence <= 6 ? CheckStatus::kPass : CheckStatus::kFail;
    out.summary = std::to_string(passed) + "/256 configurations pass (torus " + std::to_string(r.periodic_passed) +
                  ", window " + std::to_string(r.window_passed) + "), " + std::to_string(nontrivial) +
                  " transition classes, max interior dual edge valence " + std::to_string(max_valence);
    nlohmann::json classes = nlohmann::json::array();
    for (const auto& c : r.classes)
        classes.push_back({{"representative", c.representative},
                           {"fine_octants", c.fine},
                           {"configurations", c.configurations},
                           {"passed", c.passed()},
                           {"cells", c.cells},
                           {"hexes", c.hexes},
                           {"elements", c.elements},
                           {"dual_edge_valences", c.dual_edge_valences}});
    out.details = {{"configurations", 256},
                   {"passed", passed},
                   {"classes", nontrivial},
                   {"max_dual_edge_valence", max_valence},
                   {"elements_used", used},
                   {"per_class", classes}};
    std::ostringstream report;
    print(report, r);
    out.report = report.str();
    return out;
}

}  // namespace

nlohmann::json face_size_columns(const std::map<int, std::size_t>& histogram) {
    nlohmann::json j = nlohmann::json::object();
    for (int k = 3; k <= 7; ++k) {
        std::string key = "F";  // built piecewise: `"F" + std::to_string(k)` trips GCC 12's -Wrestrict
        key += std::to_string(k);
        const auto it = histogram.find(k);
        j[key] = it == histogram.end() ? 0 : it->second;
    }
    return j;
}

void add_scheme_checks(CheckRegistry& registry) {
    registry.add({"schemes.strong-elements", "the 8 strongly balanced elements are valid and equal the paper's rows",
                  check_strong_elements});
    registry.add({"schemes.strong-exhaustive",
                  "all 256 configurations installed with the strong rule: valences 6/4, all-hex dual (torus and window)",
                  check_strong_exhaustive});
}

}  // namespace dualhex::app
