// dualhex verify --only proofs.weak_stars (proofs/README.md W9-W11, W14): the star run of
// weak balance at all 8 parities, every (vertex, configuration) pair's stars checked, the
// corner pair the search gives up on by W11 and its witness stars. On request: about 8 s of
// wall time on 2 cores, the same run `dualhex certify` certifies.
#include <sstream>

#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/cell_complex.hpp"
#include "verify_checks.hpp"

namespace dualhex::app {
namespace {

CheckOutcome check_weak_stars() {
    const auto library = ElementLibrary::load_default();
    WeakStarOptions options;
    options.corner_witness = [](const WeakCornerLabel&, const CellComplex&) {};  // checked; nothing kept
    const WeakStarCheck r = run_weak_stars(WeakRule(), library, weak_star_influence(WeakRule(), library), options);
    CheckOutcome out;
    out.status = r.all_passed() && r.corner_witnesses == r.corner_quadrant_tuples ? CheckStatus::kPass : CheckStatus::kFail;
    std::ostringstream summary, report;
    summary << r.passed << "/" << r.stars << " weak stars valid at " << r.pairs << " (vertex, configuration) pairs; "
            << r.corner_pairs << " corner pair(s) by W11 with " << r.corner_witnesses
            << " valid witness stars (certified: proofs/certificates/weak_stars, weak_corner_stars)";
    report << "  search nodes " << r.search_nodes << ", tuples with no cell at v " << r.empty << ", at most " << r.max_shared
           << " statuses shared by two leaves or tied to another leaf's by an implication (W9 (v)); W11: " << r.corner_pieces << " pieces, " << r.corner_quadrant_tuples << " quadrant tuples\n";
    for (const auto& f : r.failures) report << "  FAIL " << f << '\n';
    out.summary = summary.str();
    out.report = report.str();
    out.details = {{"pairs", r.pairs},         {"stars", r.stars},           {"passed", r.passed},
                   {"failed", r.failed},       {"empty", r.empty},           {"search_nodes", r.search_nodes},
                   {"corner_pairs", r.corner_pairs}, {"corner_witnesses", r.corner_witnesses}};
    return out;
}

}  // namespace

void add_weak_star_checks(CheckRegistry& registry) {
    registry.add({"proofs.weak_stars",
                  "weak balance, every vertex off the root surface: the stars of every (vertex, configuration) pair at the 8 "
                  "parities (W10), the corner pair by W11 and its witness stars (W14)",
                  check_weak_stars, true});
}

}  // namespace dualhex::app
