// dualhex verify: runs every registered check, prints a PASS/FAIL table (or JSON).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <filesystem>
#include <memory>

#include <sys/resource.h>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "threads_option.hpp"
#include "verify_checks.hpp"

namespace dualhex::app {
namespace {

struct VerifyOptions {
    bool json = false;
    bool list = false;
    bool force = false;
    bool no_progress = false;
    int threads = 0;  ///< 0: every core
    std::string certify;  ///< directory for certificates ("" = none)
    std::vector<std::string> only;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time (user + system) of the whole process, every thread: the checks run one after the
// other, so the difference across one check is that check's CPU however many threads it used.
double process_cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const auto sec = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return sec(u.ru_utime) + sec(u.ru_stime);
}

void run_verify(const VerifyOptions& opt) {
    const ThreadLimit limit(opt.threads);
    const CheckRegistry registry = default_checks();
    const bool any = std::any_of(registry.checks().begin(), registry.checks().end(),
                                 [&](const Check& c) { return is_selected(c, opt.only); });
    if (!any) throw UsageError("verify: no check matches --only (see dualhex verify --list)");
    if (opt.list) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& c : registry.checks()) {
            if (!opt.only.empty() && !is_selected(c, opt.only)) continue;  // the list shows those on request too
            if (opt.json)
                list.push_back({{"name", c.name}, {"description", c.description}, {"on_request", c.on_request}});
            else
                std::cout << c.name << "  " << c.description << (c.on_request ? " [on request: --only NAME]" : "") << '\n';
        }
        if (opt.json) print_json({{"checks", list}});
        return;
    }

    if (!opt.certify.empty()) check_output_directory(opt.certify, opt.force);  // as dualhex certify
    const auto t_all = std::chrono::steady_clock::now();
    const double cpu_all = process_cpu_seconds();
    // The bar counts the checks run of those selected; the table rows print over it.
    ProgressBar bar = ProgressBar::for_stderr(opt.json, opt.no_progress);
    const auto n_selected = static_cast<std::size_t>(std::count_if(
        registry.checks().begin(), registry.checks().end(), [&](const Check& c) { return is_selected(c, opt.only); }));
    std::size_t n_run = 0;
    nlohmann::json checks = nlohmann::json::array();
    int passed = 0, failed = 0, skipped = 0;
    // Summary blocks "strong" and "weak" from the scheme checks' details.
    nlohmann::json blocks = {{"strong", nlohmann::json::object()}, {"weak", nlohmann::json::object()}};
    for (const auto& c : registry.checks()) {
        if (!is_selected(c, opt.only)) continue;
        bar.update(c.name, n_run++, n_selected);
        const auto t0 = std::chrono::steady_clock::now();
        const double cpu0 = process_cpu_seconds();
        CheckOutcome out;
        try {
            out = c.run();
        } catch (const std::exception& e) {
            out.status = CheckStatus::kFail;
            out.summary = std::string("exception: ") + e.what();
        }
        const double dt = seconds_since(t0);
        const double cpu = process_cpu_seconds() - cpu0;
        for (const char* block : {"strong", "weak"}) {
            if (!out.details.is_object()) break;
            if (c.name == std::string("schemes.") + block + "-exhaustive")
                for (const char* key : {"configurations", "passed", "classes", "max_dual_edge_valence"})
                    if (out.details.contains(key)) blocks[block][key] = out.details[key];
            if (c.name == std::string("schemes.") + block + "-elements") {
                nlohmann::json elements = nlohmann::json::object();
                for (const auto& [name, e] : out.details.items()) elements[name] = e["computed"];
                blocks[block]["elements"] = elements;
            }
        }
        switch (out.status) {
            case CheckStatus::kPass: ++passed; break;
            case CheckStatus::kFail: ++failed; break;
            case CheckStatus::kSkip: ++skipped; break;
        }
        checks.push_back({{"name", c.name},
                          {"description", c.description},
                          {"status", to_string(out.status)},
                          {"ok", out.status != CheckStatus::kFail},
                          {"summary", out.summary},
                          {"seconds", dt},
                          {"cpu_seconds", cpu},
                          {"details", out.details}});
        if (!opt.json) {
            bar.clear();
            std::printf("%-4s  %-28s %7.3f s %7.3f s CPU  %s\n", to_string(out.status), c.name.c_str(), dt, cpu,
                        out.summary.c_str());
            if (!out.report.empty()) std::fputs(out.report.c_str(), stdout);
            std::fflush(stdout);
        }
    }
    const double total = seconds_since(t_all);
    const double cpu_total = process_cpu_seconds() - cpu_all;
    bar.clear();
    const bool ok = failed == 0;
    if (opt.json) {
        print_json({{"ok", ok},
                    {"passed", passed},
                    {"failed", failed},
                    {"skipped", skipped},
                    {"seconds", total},
                    {"cpu_seconds", cpu_total},
                    {"strong", blocks["strong"]},
                    {"weak", blocks["weak"]},
                    {"checks", checks}});
    } else {
        std::printf("%s: %d passed, %d failed, %d skipped in %.3f s (%.3f s CPU)\n", ok ? "OK" : "FAILED", passed, failed,
                    skipped, total, cpu_total);
    }
    if (!ok) throw Exit{kCheckFailed};
    if (!opt.certify.empty()) {
        // The checks passed: write what they established as certificates (elements, the strong
        // and weak configurations, the crossing variants) for the independent checker.
        const CertifyResult result =
            certify_library(ElementLibrary::load_default(), std::filesystem::path(opt.certify), bar.callback());
        bar.clear();
        if (!opt.json)
            std::printf("certified: %zu certificates in %s (dualhex-proof-checker on %s/manifest, weak/manifest, "
                        "variants/manifest)\n",
                        result.certificates(), opt.certify.c_str(), opt.certify.c_str());
    }
}

}  // namespace

void register_verify(CLI::App& app) {
    auto opt = std::make_shared<VerifyOptions>();
    auto* sub = app.add_subcommand("verify", "Run every verification check (exit 1 if any fails)");
    add_json_flag(*sub, opt->json);
    sub->add_flag("--list", opt->list, "List the checks instead of running them");
    sub->add_option("--only", opt->only, "Run only checks whose name contains this text (repeatable); the long checks marked "
                    "'on request' in --list run only when it is their exact name");
    sub->add_option("--certify", opt->certify,
                    "After a passing run, write certificates (as `dualhex certify`) into DIR and DIR/{weak,variants,windows,boundary,weak_spread}");
    sub->add_flag("--force", opt->force, "With --certify: write into DIR even if it is not empty");
    add_threads_option(*sub, opt->threads);
    add_no_progress_flag(*sub, opt->no_progress);
    sub->callback([opt] { run_verify(*opt); });
}

}  // namespace dualhex::app
