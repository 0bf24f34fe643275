// dualhex grid {check,balance,pair}: leaf-file tools over the grid layer.
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"

#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"

namespace dualhex::app {
namespace {

struct GridOptions {
    std::string input;
    std::string output;
    bool json = false;
    bool force = false;
    bool strong = false;
    bool weak = false;
    std::vector<std::string> require;
};

Balance mode_of(const GridOptions& opt) { return opt.strong ? Balance::Strong : Balance::Weak; }
const char* mode_name(const GridOptions& opt) { return opt.strong ? "strong" : "weak"; }

nlohmann::json per_level(const LeafGrid& g) {
    nlohmann::json a = nlohmann::json::array();
    for (auto n : g.counts_per_level()) a.push_back(n);
    return a;
}

nlohmann::json to_json(const LeafGrid& g, const GridCheck& c) {
    nlohmann::json leaves = nlohmann::json::array();
    if (c.first) leaves.push_back(g.describe(*c.first));
    if (c.second) leaves.push_back(g.describe(*c.second));
    return {{"ok", c.ok}, {"message", c.message}, {"leaves", leaves}};
}

void run_check(const GridOptions& opt) {
    const LeafGrid g = read_leaf_file(opt.input);  // InputError (exit 3) unless a valid tiling
    const GridCheck paired = is_paired(g);
    const GridCheck strong = is_strongly_balanced(g);
    const GridCheck weak = is_weakly_balanced(g);
    bool ok = true;
    for (const auto& r : opt.require) {
        if (r == "paired") ok = ok && paired.ok;
        if (r == "strong") ok = ok && strong.ok;
        if (r == "weak") ok = ok && weak.ok;
    }
    if (opt.json) {
        print_json({{"file", opt.input},
                    {"tiling", true},
                    {"leaves", g.size()},
                    {"min_level", g.min_level()},
                    {"max_level", g.max_level()},
                    {"leaves_per_level", per_level(g)},
                    {"paired", to_json(g, paired)},
                    {"strongly_balanced", to_json(g, strong)},
                    {"weakly_balanced", to_json(g, weak)},
                    {"required", opt.require},
                    {"ok", ok}});
    } else {
        std::printf("%s: valid tiling, %zu leaves, levels %d..%d\n", opt.input.c_str(), g.size(), g.min_level(),
                    g.max_level());
        const auto counts = g.counts_per_level();
        for (std::size_t level = 0; level < counts.size(); ++level)
            if (counts[level] != 0) std::printf("  level %2zu: %zu leaves\n", level, counts[level]);
        auto line = [](const char* what, const GridCheck& c) {
            std::printf("%-18s %s%s%s\n", what, c.ok ? "yes" : "no", c.ok ? "" : ": ", c.message.c_str());
        };
        line("paired:", paired);
        line("strongly balanced:", strong);
        line("weakly balanced:", weak);
        if (!opt.require.empty()) std::printf("%s\n", ok ? "required properties hold" : "REQUIRED PROPERTY FAILS");
    }
    if (!ok) throw Exit{kCheckFailed};
}

void report_refinement(const GridOptions& opt, const char* op, const LeafGrid& in, const LeafGrid& out) {
    if (opt.json) {
        print_json({{"input", opt.input},
                    {"output", opt.output},
                    {"operation", op},
                    {"leaves_in", in.size()},
                    {"leaves_out", out.size()},
                    {"max_level", out.max_level()},
                    {"leaves_per_level", per_level(out)}});
    } else {
        std::printf("%s: %zu leaves -> %zu leaves, written to %s\n", op, in.size(), out.size(), opt.output.c_str());
    }
}

void run_balance(const GridOptions& opt) {
    check_output(opt.output, opt.force);
    const LeafGrid in = read_leaf_file(opt.input);
    const LeafGrid out = balance(in, mode_of(opt));
    const std::string op = std::string(mode_name(opt)) + " balance";
    write_leaf_file(out, opt.output, "dualhex grid balance --" + std::string(mode_name(opt)) + " " + opt.input);
    report_refinement(opt, op.c_str(), in, out);
}

void run_pair(const GridOptions& opt) {
    check_output(opt.output, opt.force);
    const LeafGrid in = read_leaf_file(opt.input);
    const bool balanced = opt.strong || opt.weak;
    const LeafGrid out = balanced ? pair(in, mode_of(opt)) : pair_only(in);
    const std::string op = balanced ? std::string("pair + ") + mode_name(opt) + " balance" : std::string("pair");
    write_leaf_file(out, opt.output,
                    "dualhex grid pair" + (balanced ? " --" + std::string(mode_name(opt)) : std::string()) + " " +
                        opt.input);
    report_refinement(opt, op.c_str(), in, out);
}


}  // namespace

void register_grid(CLI::App& app) {
    auto* grid = app.add_subcommand("grid", "Leaf-file tools: check, balance, pair");
    grid->require_subcommand(1);

    {
        auto opt = std::make_shared<GridOptions>();
        auto* sub = grid->add_subcommand(
            "check", "Check a leaf file: valid tiling (else exit 3), leaves per level, paired, strongly/weakly "
                     "balanced (naming offending leaves)");
        sub->add_option("FILE", opt->input, "Leaf file (.leaves)")->required()->check(CLI::ExistingFile);
        sub->add_option("--require", opt->require, "Exit 1 unless this property holds (repeatable)")
            ->check(CLI::IsMember({"paired", "strong", "weak"}));
        add_json_flag(*sub, opt->json);
        sub->callback([opt] { run_check(*opt); });
    }
    {
        auto opt = std::make_shared<GridOptions>();
        auto* sub = grid->add_subcommand("balance", "Least refinement of a leaf file that is strongly or weakly balanced");
        sub->add_option("FILE", opt->input, "Leaf file (.leaves)")->required()->check(CLI::ExistingFile);
        auto* strong = sub->add_flag("--strong", opt->strong, "Strong balance (vertex, edge and face neighbours)");
        auto* weak = sub->add_flag("--weak", opt->weak, "Weak balance (face neighbours only)");
        strong->excludes(weak);
        add_output_options(*sub, opt->output, opt->force);
        add_json_flag(*sub, opt->json);
        sub->callback([opt] {
            if (!opt->strong && !opt->weak) throw UsageError("grid balance: give --strong or --weak");
            run_balance(*opt);
        });
    }
    {
        auto opt = std::make_shared<GridOptions>();
        auto* sub = grid->add_subcommand(
            "pair", "Least refinement of a leaf file that is paired (with --strong/--weak: paired and balanced)");
        sub->add_option("FILE", opt->input, "Leaf file (.leaves)")->required()->check(CLI::ExistingFile);
        auto* strong = sub->add_flag("--strong", opt->strong, "Also strongly balanced (alternate until both hold)");
        auto* weak = sub->add_flag("--weak", opt->weak, "Also weakly balanced (alternate until both hold)");
        strong->excludes(weak);
        add_output_options(*sub, opt->output, opt->force);
        add_json_flag(*sub, opt->json);
        sub->callback([opt] { run_pair(*opt); });
    }
}

}  // namespace dualhex::app
