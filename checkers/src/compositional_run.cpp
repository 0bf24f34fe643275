// run_compositional (compositional.hpp): the lemma, then every distinct window of the 8
// parity types, checked in parallel (oneTBB) and tallied in window order, so the result is
// that of a serial run for any number of threads.
//
// Without an on_window observer the windows are checked class by class (class_check.hpp, keys
// from window_classes.hpp): one representative per congruence class gets the full check; every other window is built
// and proved to be the exact image of its representative under a cube symmetry about g
// (oriented_form.hpp: its vertices and oriented cells, point by point). The check is
// invariant under those symmetries (the window box and its interior are), so the member's
// outcome is its representative's. A member that is not such an image, or whose
// representative fails, gets the full check itself: the coverage is that of checking every
// window.
#include <algorithm>
#include <chrono>
#include <map>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "compositional_windows.hpp"
#include "class_check.hpp"
#include "oriented_form.hpp"
#include "window_check.hpp"
#include "window_classes.hpp"

namespace dualhex {
namespace {

using namespace compositional_detail;
using Caches = tbb::enumerable_thread_specific<detail::TemplateCache>;

// What the tally needs of one window's check.
struct Outcome {
    bool ok = false;
    std::size_t checked_vertices = 0;
    std::string summary;
};

Outcome outcome_of(const ConfigurationReport& r) { return {r.ok(), r.checked_vertices, r.ok() ? "" : r.summary()}; }

using detail::OrientedForm;

OrientedForm window_form(const detail::FormArrays& k, const CubeSymmetry& s) {
    return detail::oriented_form(k, [&](const LatticePoint& p) { return s.apply(p); }, !s.is_rotation());
}

struct Window {
    const WindowType* type = nullptr;
    std::size_t index = 0;  // among its type's windows
    std::uint64_t pattern = 0;
};

// Every window's outcome, class by class (class_check.hpp).
std::vector<Outcome> check_by_class(const std::vector<Window>& windows, const TransitionRule& rule,
                                    const ElementLibrary& library, Caches& caches, const Progress& progress) {
    const detail::PlacementCodes codes(library);
    // Work units: each window's key, each representative's full check or member's comparison.
    ProgressCounter counter(progress, "windows", 2 * windows.size());
    // A member is built as parts (no edges): its form is all it needs unless it is no image.
    const auto build = [&](std::size_t i) { return window_parts(*windows[i].type, windows[i].pattern, rule, caches.local()); };
    const auto check_built = [&](std::size_t, detail::ConfigurationParts built) {
        return outcome_of(detail::check_window(0, caches.local().unit(), [&] { return detail::complete(std::move(built)); }));
    };
    return detail::check_by_class<detail::WindowKey, detail::ConfigurationParts, Outcome, ConfigurationComplex>(
        windows.size(),
        [&](std::size_t i) -> std::optional<std::pair<detail::WindowKey, CubeSymmetry>> {
            counter.add();
            try {
                return detail::window_class_key(windows[i].type->parity, coarse_placements(*windows[i].type, windows[i].pattern, rule), codes);
            } catch (const std::exception&) {
                return std::nullopt;  // the rule threw: the full check reports it
            }
        },
        [&](std::size_t i, ConfigurationComplex* keep) {
            counter.add();
            ConfigurationComplex built;
            const Outcome o = outcome_of(detail::check_window(0, caches.local().unit(), [&] {
                return built = build_window(*windows[i].type, windows[i].pattern, rule, caches.local());
            }));
            if (keep) *keep = std::move(built);
            return o;
        },
        [&](std::size_t i) {
            counter.add();
            return build(i);
        },
        check_built, [](const auto& b, const CubeSymmetry& s) { return window_form(detail::form_source(b), s); },
        [](const Outcome& o) { return o.ok; });
}

// Every window checked in chunks, each chunk's windows in parallel, then handed to the
// observer in window order (it sees each built complex and its report) until the failures
// reach options.stop_after_failures, as in a serial run.
void check_observed(const std::vector<Window>& windows, const TransitionRule& rule, Caches& caches,
                    const CompositionalOptions& options, std::vector<Outcome>& out) {
    constexpr std::size_t kChunk = 512;
    std::size_t failed = 0;
    const auto stop = [&] { return options.stop_after_failures && failed >= options.stop_after_failures; };
    std::vector<ConfigurationComplex> built(std::min(kChunk, windows.size()));
    std::vector<ConfigurationReport> reports(built.size());
    ProgressCounter counter(options.progress, "windows", windows.size());
    for (std::size_t begin = 0; begin < windows.size() && !stop(); begin += kChunk) {
        const std::size_t n = std::min(kChunk, windows.size() - begin);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
            detail::TemplateCache& cache = caches.local();
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                const Window& w = windows[begin + i];
                reports[i] = detail::check_window(0, cache.unit(), [&] { return built[i] = build_window(*w.type, w.pattern, rule, cache); });
            }
        });
        for (std::size_t i = 0; i < n && !stop(); ++i) {
            const Window& w = windows[begin + i];
            out[begin + i] = outcome_of(reports[i]);
            failed += out[begin + i].ok ? 0 : 1;
            options.on_window({w.type->parity, w.index, w.type->reads, w.pattern, &built[i], &reports[i]});
        }
        counter.add(n);
    }
}

}  // namespace

CompositionalResult run_compositional(const TransitionRule& rule, const ElementLibrary& library,
                                      const CompositionalOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    CompositionalResult result;
    result.rule = rule.name();
    result.reach_octants = static_cast<int>(reach_bits(rule).size());
    check_lemma(rule, result);
    report_progress(options.progress, "window types", 0, 0);  // the enumeration's size is not known yet
    // The 8 types' enumerations are independent: in parallel, each into its own slot.
    std::vector<WindowType> types(8);
    std::vector<WindowTypeResult> type_results(8);
    std::vector<std::vector<std::uint64_t>> patterns(8);
    tbb::parallel_for(0, 8, [&](int p) {
        const auto i = static_cast<std::size_t>(p);
        types[i] = window_type({p & 1, (p >> 1) & 1, (p >> 2) & 1}, rule);
        type_results[i].parity = types[i].parity;
        type_results[i].read_octants = static_cast<int>(types[i].reads.size());
        patterns[i] = distinct_windows(types[i], rule, type_results[i].shared_octants);
    });
    std::vector<Window> windows;
    for (std::size_t p = 0; p < types.size(); ++p)
        for (std::size_t w = 0; w < patterns[p].size(); ++w) windows.push_back({&types[p], w, patterns[p][w]});

    Caches caches([&] { return detail::TemplateCache(library); });
    std::vector<Outcome> outcomes(windows.size());
    if (options.on_window)
        check_observed(windows, rule, caches, options, outcomes);
    else
        outcomes = check_by_class(windows, rule, library, caches, options.progress);

    // The tally of a serial run, window by window (stopping as it would).
    const auto stop = [&] { return options.stop_after_failures && result.failed >= options.stop_after_failures; };
    for (std::size_t p = 0, i = 0; p < types.size(); ++p) {
        WindowTypeResult& tr = type_results[p];
        for (std::size_t w = 0; w < patterns[p].size(); ++w, ++i) {
            if (stop()) continue;
            const Outcome& o = outcomes[i];
            ++tr.windows;
            tr.checked_vertices += o.checked_vertices;
            if (o.ok) {
                ++tr.passed;
            } else if (++result.failed <= 10) {
                result.failures.push_back(describe(tr.parity, types[p].reads, patterns[p][w]) + ": " + o.summary);
            }
        }
        result.windows += tr.windows;
        result.passed += tr.passed;
        result.checked_vertices += tr.checked_vertices;
        result.types.push_back(tr);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace dualhex
