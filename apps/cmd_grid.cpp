// dualhex grid {check,balance,pair}: leaf-file tools over the grid layer.
#include <iostream>
#include <memory>

#include "commands.hpp"

namespace dualhex::app {
namespace {

struct GridOptions {
    std::string input;
    std::string output;
    bool json = false;
    bool force = false;
    bool strong = false;
    bool weak = false;
};

[[noreturn]] void not_yet(const char* what) {
    throw NotYetAvailable(std::string(what) + " needs the grid layer's leaf-file API (grid/include/dualhex/grid/)");
}

void run_check(const GridOptions& opt) { (void)opt; not_yet("grid check"); }
void run_balance(const GridOptions& opt) {
    check_output(opt.output, opt.force);
    not_yet("grid balance");
}
void run_pair(const GridOptions& opt) {
    check_output(opt.output, opt.force);
    not_yet("grid pair");
}

}  // namespace

void register_grid(CLI::App& app) {
    auto* grid = app.add_subcommand("grid", "Leaf-file tools: check, balance, pair");
    grid->require_subcommand(1);

    {
        auto opt = std::make_shared<GridOptions>();
        auto* sub = grid->add_subcommand(
            "check", "Check a leaf file: tiling, paired, strongly/weakly balanced (exit 1 if not valid)");
        sub->add_option("FILE", opt->input, "Leaf file (.leaves)")->required()->check(CLI::ExistingFile);
        add_json_flag(*sub, opt->json);
        sub->callback([opt] { run_check(*opt); });
    }
    {
        auto opt = std::make_shared<GridOptions>();
        auto* sub = grid->add_subcommand("balance", "Refine a leaf file until it is strongly or weakly balanced");
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
        auto* sub = grid->add_subcommand("pair", "Refine a leaf file until it is paired (siblings come in 8s)");
        sub->add_option("FILE", opt->input, "Leaf file (.leaves)")->required()->check(CLI::ExistingFile);
        add_output_options(*sub, opt->output, opt->force);
        add_json_flag(*sub, opt->json);
        sub->callback([opt] { run_pair(*opt); });
    }
}

}  // namespace dualhex::app
