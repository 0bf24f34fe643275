// The compositional argument for `dualhex verify` (checkers/compositional.hpp): the reduction
// lemma and every window of every parity type under the strong rule.
#include <sstream>

#include "dualhex/checkers/compositional.hpp"
#include "dualhex/checkers/compositional_boundary.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "verify_checks.hpp"

namespace dualhex::app {
namespace {

CheckOutcome check_compositional() {
    const auto library = ElementLibrary::load_default();
    const CompositionalResult r = run_compositional(StrongRule(), library);
    CheckOutcome out;
    out.status = r.all_passed() ? CheckStatus::kPass : CheckStatus::kFail;
    out.summary = "lemma " + std::to_string(r.lemma_plain) + "/" + std::to_string(r.lemma_contexts) +
                  " contexts plain; " + std::to_string(r.passed) + "/" + std::to_string(r.windows) +
                  " windows of 8 types pass (" + std::to_string(r.checked_vertices) +
                  " vertices checked): every strongly balanced paired grid, any number of levels";
    nlohmann::json types = nlohmann::json::array();
    std::ostringstream report;
    for (const auto& t : r.types) {
        const std::string g = std::to_string(t.parity[0]) + std::to_string(t.parity[1]) + std::to_string(t.parity[2]);
        types.push_back({{"g", g}, {"read_octants", t.read_octants}, {"shared_octants", t.shared_octants},
                         {"windows", t.windows}, {"passed", t.passed}, {"checked_vertices", t.checked_vertices}});
        report << "  g=" << g << ": reads " << t.read_octants << " octants (" << t.shared_octants << " shared), "
               << t.passed << "/" << t.windows << " windows pass\n";
    }
    for (const auto& f : r.failures) report << "  FAIL " << f << '\n';
    out.details = {{"reach_octants", r.reach_octants}, {"lemma_contexts", r.lemma_contexts},
                   {"lemma_plain", r.lemma_plain}, {"windows", r.windows}, {"passed", r.passed},
                   {"checked_vertices", r.checked_vertices}, {"types", types}, {"seconds", r.seconds}};
    out.report = report.str();
    return out;
}

// The root boundary (compositional_boundary.hpp): the strong rule's boundary windows under
// install's two policies and under every outside status at once (which covers both).
CheckOutcome check_root_boundary() {
    const auto library = ElementLibrary::load_default();
    CheckOutcome out;
    out.status = CheckStatus::kPass;
    nlohmann::json policies = nlohmann::json::array();
    std::ostringstream report, summary;
    double seconds = 0;
    for (BoundaryPolicy policy : {BoundaryPolicy::Coarse, BoundaryPolicy::Mirror, BoundaryPolicy::AnyOutside}) {
        const BoundaryResult r = run_compositional_boundary(StrongRule(), library, policy);
        if (!r.all_passed()) out.status = CheckStatus::kFail;
        seconds += r.seconds;
        summary << (policy == BoundaryPolicy::Coarse ? "" : "; ") << r.policy << " " << r.passed << "/" << r.windows;
        policies.push_back({{"policy", r.policy}, {"windows", r.windows}, {"passed", r.passed},
                            {"face_vertices", r.checked_vertices[0]}, {"edge_vertices", r.checked_vertices[1]},
                            {"corner_vertices", r.checked_vertices[2]}, {"seconds", r.seconds}});
        report << "  " << r.policy << ": " << r.passed << "/" << r.windows << " windows of 56 types pass; vertices checked on "
               << "root faces " << r.checked_vertices[0] << ", edges " << r.checked_vertices[1] << ", corners "
               << r.checked_vertices[2] << '\n';
        for (const auto& f : r.failures) report << "  FAIL " << r.policy << ": " << f << '\n';
    }
    out.summary = summary.str() + " boundary windows pass: every root-boundary vertex of every strongly balanced "
                  "paired grid, clipped dual cells positively oriented hexahedra";
    out.details = {{"policies", policies}, {"seconds", seconds}};
    out.report = report.str();
    return out;
}

}  // namespace

void add_compositional_checks(CheckRegistry& registry) {
    registry.add({"proofs.compositional",
                  "every strongly balanced paired grid: the reduction lemma and every 2x2x2-leaf window (strong rule)",
                  check_compositional});
    registry.add({"proofs.root_boundary",
                  "every strongly balanced paired grid at the root boundary: every boundary window, both root policies "
                  "and any outside status (strong rule)",
                  check_root_boundary});
}

}  // namespace dualhex::app
