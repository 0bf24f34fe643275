// The compositional argument for `dualhex verify` (checkers/compositional.hpp): the reduction
// lemma and every window of every parity type under the strong rule.
#include <array>
#include <optional>
#include <sstream>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "dualhex/checkers/compositional.hpp"
#include "dualhex/checkers/compositional_boundary.hpp"
#include "dualhex/checkers/compositional_weak.hpp"
#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/install/install.hpp"
#include "dualhex/install/verify_installation.hpp"
#include "dualhex/schemes/weak_rule.hpp"
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

// Weak balance (compositional_weak.hpp, proofs/README.md "Weak balance"): the weak rule's
// computed reduction facts (reach, lemma, visible domain), the grid with four levels at a
// point installed and verified (tested, not proved), and what a box window would read.
// The grid with levels m..m+3 at one point, for each of the 8 corners it can point to,
// installed with the weak rule and verified: the corners in parallel, tallied in corner order.
struct SpreadOutcome {
    std::vector<int> at;  // the levels at the point (of the last corner)
    int valid = 0;
    std::string failure;  // the first corner's that failed
};

SpreadOutcome check_spread_grids(const ElementLibrary& library) {
    std::array<std::vector<int>, 8> at;
    std::array<std::optional<InstallVerification>, 8> verified;
    tbb::parallel_for(0, 8, [&](int corner) {
        const LeafGrid spread = spread_three_grid(2, corner);
        at[static_cast<std::size_t>(corner)] = levels_at(spread, {2, 2, 2}, 2);
        verified[static_cast<std::size_t>(corner)] = verify_installation(install(spread, WeakRule(), library));
    });
    SpreadOutcome out;
    for (std::size_t corner = 0; corner < 8; ++corner) {
        const InstallVerification& v = *verified[corner];
        if (v.ok() && at[corner].front() + 3 == at[corner].back()) ++out.valid;
        else if (out.failure.empty()) out.failure = "corner " + std::to_string(corner) + ": " + v.summary();
    }
    out.at = at.back();
    return out;
}

// W11: the one pair the star search cannot finish (parity 111, v = g, the 8 leaves of level
// m) is a corner pair, checked leaf by leaf and quadrant by quadrant, and (W14 (f)) by a
// valid witness star for each of its quadrant tuples.
WeakStarOptions odd_corner_pair() {
    WeakStarOptions odd;
    odd.parities = 0x80;
    odd.vertex = [](const LatticePoint& v) { return v == LatticePoint{}; };
    odd.corner_pairs = CornerPairs::Always;
    odd.corner_witness = [](const WeakCornerLabel&, const CellComplex&) {};  // checked; nothing kept
    return odd;
}

CheckOutcome check_compositional_weak() {
    const auto library = ElementLibrary::load_default();
    // Three independent computations, each short and mostly serial: side by side.
    WeakLemmaResult r;
    SpreadOutcome spread;
    WeakStarInfluence influence;
    std::vector<WeakStarReads> star_reads;
    WeakStarCheck corner;
    tbb::parallel_invoke([&] { r = check_weak_lemmas(WeakRule()); }, [&] { spread = check_spread_grids(library); },
                         [&] {
                             influence = weak_star_influence(WeakRule(), library);
                             star_reads = weak_star_reads(influence);
                             corner = run_weak_stars(WeakRule(), library, influence, odd_corner_pair());
                         });
    const std::vector<int>& at = spread.at;
    const int spread_valid = spread.valid;
    const std::string& spread_failure = spread.failure;
    const bool corner_ok = corner.pairs == 1 && corner.corner_pairs == 1 && corner.all_passed() &&
                           corner.corner_witnesses == corner.corner_quadrant_tuples;
    CheckOutcome out;
    out.status = r.all_passed() && spread_valid == 8 && corner_ok ? CheckStatus::kPass : CheckStatus::kFail;
    out.summary = "weak lemma " + std::to_string(r.lemma_plain) + "/" + std::to_string(r.lemma_contexts) +
                  " contexts plain; visible domain " + std::to_string(r.visible_contexts) + " contexts (" +
                  std::to_string(r.placed) + " placed, " + std::to_string(r.plain) + " plain, " +
                  std::to_string(r.refused) + " refused); edge bits off concave edges ignored " +
                  std::to_string(r.nonconcave_ignored) + "/" + std::to_string(r.nonconcave_contexts) +
                  "; levels " + std::to_string(at.front()) + ".." + std::to_string(at.back()) +
                  " at one point, 8 orientations installed: " + std::to_string(spread_valid) + "/8 valid" +
                  " (W7: the star enumeration is a separate run, its counts below; proofs/README.md)" +
                  (corner_ok ? "; W11: the odd corner pair passes" : "; W11: the odd corner pair FAILS");
    std::ostringstream report;
    report << "  elements over the visible domain:";
    for (const auto& [name, n] : r.elements) report << ' ' << name << ' ' << n;
    report << "\n  contexts where a concave edge's bit changes the element (MR): " << r.mr_contexts << '\n';
    nlohmann::json windows = nlohmann::json::array();
    for (const auto& w : weak_window_reads()) {
        const std::string g = std::to_string(w.parity[0]) + std::to_string(w.parity[1]) + std::to_string(w.parity[2]);
        windows.push_back({{"g", g}, {"octants", w.octants}, {"cells", w.cells}, {"shared_cells", w.shared_cells},
                           {"application_points", w.application_points}});
        report << "  g=" << g << ": a three-level box window reads " << w.octants << " octants and " << w.cells
               << " level-m cells (" << w.shared_cells << " shared), leaves at " << w.application_points
               << " application points\n";
    }
    if (!spread_failure.empty()) report << "  FAIL spread grid, " << spread_failure << '\n';
    // W7, relevant bits only: what each context bit changes at each point of a leaf, and
    // what the leaves at a vertex read jointly, per leaf configuration.
    report << "  W7 influence: " << influence.positions.size() << " vertex positions in a leaf, "
           << influence.distinct_pieces << " distinct pieces, relevant bits per position:";
    for (const auto& [k, n] : influence.relevant_histogram) report << ' ' << k << ':' << n;
    report << '\n';
    nlohmann::json stars = nlohmann::json::array();
    for (const auto& w : star_reads) {
        const std::string g = std::to_string(w.parity[0]) + std::to_string(w.parity[1]) + std::to_string(w.parity[2]);
        stars.push_back({{"g", g}, {"vertices", w.vertices}, {"configurations", w.configurations},
                         {"max_free", w.max_free}, {"max_shared", w.max_shared}, {"joint", w.joint}});
        report << "  W7 g=" << g << ": " << w.vertices << " candidate vertices, " << w.configurations
               << " (vertex, leaf configuration) pairs, at most " << w.max_free << " free statuses read, "
               << w.max_shared << " shared; joint assignments " << w.joint << '\n';
    }
    report << "  W11 g=111, v = g, 8 leaves of level m (the pair the star search does not finish): "
           << (corner_ok ? "passes" : "FAILS") << " leaf by leaf (" << corner.corner_pieces << " pieces) and quadrant by quadrant ("
           << corner.corner_quadrant_tuples << " tuples), one star whole; W14 (f): " << corner.corner_witnesses
           << " witness stars, one per quadrant tuple, valid\n";
    for (const auto& f : corner.failures) report << "  FAIL W11: " << f << '\n';
    out.details = {{"reach_octants", r.reach_octants}, {"lemma_contexts", r.lemma_contexts},
                   {"lemma_plain", r.lemma_plain}, {"visible_contexts", r.visible_contexts},
                   {"placed", r.placed}, {"plain", r.plain}, {"refused", r.refused},
                   {"nonconcave_contexts", r.nonconcave_contexts}, {"nonconcave_ignored", r.nonconcave_ignored},
                   {"mr_contexts", r.mr_contexts}, {"spread_levels", at}, {"spread_grids_valid", spread_valid},
                   {"windows", windows}, {"star_reads", stars},
                   {"star_positions", influence.positions.size()}, {"star_pieces", influence.distinct_pieces},
                   {"star_max_relevant", influence.max_relevant()}, {"odd_corner_pair_passed", corner_ok},
                   {"odd_corner_pair_pieces", corner.corner_pieces}, {"odd_corner_pair_quadrant_tuples", corner.corner_quadrant_tuples},
                   {"odd_corner_pair_witness_stars", corner.corner_witnesses}};
    out.report = report.str();
    return out;
}

}  // namespace

void add_compositional_checks(CheckRegistry& registry) {
    registry.add({"proofs.weak_balance",
                  "weak balance: the weak rule's reach, lemma and visible domain; four levels at a point (tested); "
                  "what a box window would read; W7's influence table and what the leaves at a vertex read",
                  check_compositional_weak});
    registry.add({"proofs.compositional",
                  "every strongly balanced paired grid: the reduction lemma and every 2x2x2-leaf window (strong rule)",
                  check_compositional});
    registry.add({"proofs.root_boundary",
                  "every strongly balanced paired grid at the root boundary: every boundary window, both root policies "
                  "and any outside status (strong rule)",
                  check_root_boundary});
}

}  // namespace dualhex::app
