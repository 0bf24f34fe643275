// dualhex variants: every chain-crossing assignment (flat 2, concave edge 4, concave corner 8)
// built, installed on its region's torus and checked; classes by canonical form; ranking.
#include <iostream>
#include <string>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "variants_json.hpp"

namespace dualhex::app {

namespace {

nlohmann::json histogram_json(const std::map<int, std::size_t>& h) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, n] : h) j[std::to_string(k)] = n;
    return j;
}

}  // namespace

nlohmann::json variants_json(const variants::VariantsReport& report) {
    using namespace dualhex::variants;
    nlohmann::json out = nlohmann::json::object();
    for (const auto& r : report.regions) {
        nlohmann::json variants = nlohmann::json::array();
        for (const auto& v : r.variants)
            variants.push_back({{"assignment", v.assignment},
                                {"name", v.name},
                                {"valid", v.ok()},
                                {"element_valid", v.element_valid},
                                {"torus_ok", v.torus.ok()},
                                {"error", v.torus.error},
                                {"element_faces", histogram_json(v.element_faces)},
                                {"bend_faces", histogram_json(v.bend_faces)},
                                {"bend_face_size", v.bend_face_size},
                                {"dual_edge_valences", histogram_json(v.torus.dual_edge_valences)},
                                {"singular_edges", singular_edges(v.torus.dual_edge_valences)},
                                {"shipped", v.shipped.empty() ? nlohmann::json() : nlohmann::json(v.shipped)}});
        nlohmann::json ranking = nlohmann::json::array();
        for (const auto& c : r.classes) {
            const auto& v = r.variants[c.members.front()];
            nlohmann::json members = nlohmann::json::array();
            for (std::size_t m : c.members) members.push_back(r.variants[m].assignment);
            ranking.push_back({{"rank", c.rank},
                               {"members", members},
                               {"representative", v.name},
                               {"bend_face_size", v.bend_face_size},
                               {"bend_faces", histogram_json(v.bend_faces)},
                               {"element_faces", histogram_json(v.element_faces)},
                               {"dual_edge_valences", histogram_json(v.torus.dual_edge_valences)},
                               {"max_valence", c.ranking.front()},
                               {"singular_edges", singular_edges(v.torus.dual_edge_valences)},
                               {"ranking_key", c.ranking},
                               {"members_agree", c.histograms_agree},
                               {"shipped", v.shipped.empty() ? nlohmann::json() : nlohmann::json(v.shipped)}});
        }
        out[to_string(r.region)] = {{"mask", r.mask},
                                    {"region_element", region_element(r.region)},
                                    {"assignments", r.variants.size()},
                                    {"valid", r.valid},
                                    {"classes", r.classes.size()},
                                    {"variants", variants},
                                    {"ranking", ranking}};
    }
    if (report.combined) {
        nlohmann::json classes = nlohmann::json::array();
        for (const auto& c : report.combined->classes)
            classes.push_back({{"representative", c.representative},
                               {"fine_octants", c.fine},
                               {"free_crossings", c.free_crossings},
                               {"enumerated", c.enumerated},
                               {"componentwise", c.componentwise},
                               {"components", c.components},
                               {"assignments", c.assignments},
                               {"valid", c.valid},
                               {"strong_dual_edge_valences", histogram_json(c.strong_valences)},
                               {"best_dual_edge_valences", histogram_json(c.best_valences)},
                               {"better_than_strong", c.assignments_better},
                               {"equal_to_strong", c.assignments_equal}});
        out["combined"] = {{"max_free_crossings", report.combined->limit},
                           {"seconds", report.combined->seconds},
                           {"strong_optimal", report.combined->strong_optimal()},
                           {"classes", classes}};
    }
    out["ok"] = report.ok();
    return out;
}

void register_variants(CLI::App& app) {
    auto* sub = app.add_subcommand(
        "variants", "Chain-crossing variants: every over/under assignment built, installed and ranked");
    struct Options {
        bool json = false;
        bool combined = false;
        bool no_progress = false;
        std::size_t max_free = 12;
    };
    auto opt = std::make_shared<Options>();
    add_json_flag(*sub, opt->json);
    add_no_progress_flag(*sub, opt->no_progress);
    sub->add_flag("--combined", opt->combined,
                  "Also enumerate every assignment of the crossings touched by a bend in each of the 20 "
                  "transition classes (slow: minutes)");
    sub->add_option("--max-free", opt->max_free, "With --combined: skip classes with more free crossings (default 12)")
        ->check(CLI::Range(0, 24));
    sub->callback([opt] {
        ProgressBar bar = ProgressBar::for_stderr(opt->json, opt->no_progress);
        const auto report = variants::check_variants(opt->combined, opt->max_free, bar.callback());
        std::size_t assignments = 0;
        if (report.combined)
            for (const auto& c : report.combined->classes) assignments += c.assignments;
        bar.finish("variants: " + std::string(report.ok() ? "ok" : "FAILED") +
                   (report.combined ? ", " + with_commas(assignments) + " combined assignments ranked" : std::string()));
        if (opt->json)
            print_json(variants_json(report));
        else
            variants::print(std::cout, report);
        if (!report.ok()) throw Exit{kCheckFailed};
    });
}

}  // namespace dualhex::app
