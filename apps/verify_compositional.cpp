// The compositional argument for `dualhex verify` (checkers/compositional.hpp): the reduction
// lemma and every window of every parity type under the strong rule.
#include <sstream>

#include "dualhex/checkers/compositional.hpp"
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

}  // namespace

void add_compositional_checks(CheckRegistry& registry) {
    registry.add({"proofs.compositional",
                  "every strongly balanced paired grid: the reduction lemma and every 2x2x2-leaf window (strong rule)",
                  check_compositional});
}

}  // namespace dualhex::app
