// dualhex verify --only proofs.weak_root_boundary (proofs/README.md W13): the weak stars of
// the vertices on the root surface under Mirror and Coarse, each inside star checked with
// the root-boundary conditions B1-B5; and on request proofs.weak_near_root_surface, Coarse
// near the surface (W13 (e): 1.1 M stars, about 40 s wall on 2 idle cores).
#include <sstream>

#include "dualhex/checkers/compositional_weak_root_stars.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "verify_checks.hpp"

namespace dualhex::app {
namespace {

CheckOutcome check_weak_root_boundary() {
    const auto library = ElementLibrary::load_default();
    const WeakStarInfluence influence = weak_star_influence(WeakRule(), library);
    CheckOutcome out;
    out.status = CheckStatus::kPass;
    std::ostringstream summary, report;
    nlohmann::json policies = nlohmann::json::array();
    for (const BoundaryPolicy policy : {BoundaryPolicy::Mirror, BoundaryPolicy::Coarse}) {
        const WeakRootStarCheck r = run_weak_root_stars(WeakRule(), library, influence, policy);
        if (!r.all_passed()) out.status = CheckStatus::kFail;
        summary << (summary.tellp() > 0 ? "; " : "") << r.policy << " " << r.total(r.passed) << "/" << r.total(r.stars);
        report << "  " << r.policy << ": face / edge / corner vertices: " << r.pairs[0] << " / " << r.pairs[1] << " / "
               << r.pairs[2] << " (vertex, configuration) pairs, " << r.stars[0] << " / " << r.stars[1] << " / " << r.stars[2]
               << " stars, " << r.total(r.failed) << " failed\n";
        for (const auto& f : r.failures) report << "  FAIL " << r.policy << ": " << f << '\n';
        policies.push_back({{"policy", r.policy}, {"pairs", r.pairs}, {"stars", r.stars}, {"passed", r.passed},
                            {"failed", r.failed}, {"search_nodes", r.search_nodes}});
    }
    out.summary = summary.str() +
                  " weak stars on the root surface pass B1-B5 (W13; certified: proofs/certificates/weak_root_stars)";
    out.details = {{"policies", policies}};
    out.report = report.str();
    return out;
}

CheckOutcome check_weak_near_root_surface() {
    const auto library = ElementLibrary::load_default();
    const WeakNearRootStarCheck r = run_weak_near_root_stars(WeakRule(), library, weak_star_influence(WeakRule(), library));
    CheckOutcome out;
    out.status = r.all_passed() ? CheckStatus::kPass : CheckStatus::kFail;
    std::ostringstream summary, report;
    summary << r.passed << "/" << r.stars << " weak stars near the root surface under Coarse pass (W13 (e); certified by "
            << "`dualhex certify --near-root-stars`)";
    report << "  plane sets with 0 / 1 / 2 / 3 planes through v: " << r.combinations[0] << " / " << r.combinations[1] << " / "
           << r.combinations[2] << " / " << r.combinations[3] << "; single planes that change nothing " << r.unchanged
           << "; tuples with no cell at v " << r.empty << "; corner pairs " << r.corner_pairs << "; planes at the reach's end "
           << r.hits_at_reach << '\n';
    for (const auto& f : r.failures) report << "  FAIL " << f << '\n';
    out.summary = summary.str();
    out.report = report.str();
    out.details = {{"combinations", r.combinations}, {"unchanged", r.unchanged}, {"stars", r.stars}, {"passed", r.passed},
                   {"failed", r.failed},             {"empty", r.empty},         {"corner_pairs", r.corner_pairs},
                   {"hits_at_reach", r.hits_at_reach}};
    return out;
}

}  // namespace

void add_weak_root_checks(CheckRegistry& registry) {
    registry.add({"proofs.weak_root_boundary",
                  "weak balance on the root surface: every star of a vertex on a root face, edge or corner under Mirror "
                  "and Coarse, its inside half checked with B1-B5 (W13)",
                  check_weak_root_boundary});
    registry.add({"proofs.weak_near_root_surface",
                  "weak balance near the root surface under Coarse: every star whose leaves name a cell beyond a root plane "
                  "not through v, every combination of such planes (W13 (e))",
                  check_weak_near_root_surface, true});
}

}  // namespace dualhex::app
