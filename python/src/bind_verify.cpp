// dualhex.verify(only=None), dualhex.list_checks(), dualhex.classify(): the checks of
// `dualhex verify` from the apps' own registry (apps/verify_checks.hpp, compiled into the
// module), and the configuration classification of `dualhex classify`.
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <variant>

#include "bindings.hpp"
#include "classification.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "convert.hpp"
#include "verify_checks.hpp"

namespace dualhex::python {
namespace {

struct Ran {
    const app::Check* check = nullptr;
    app::CheckOutcome outcome;
    double seconds = 0;
};

// Without the GIL: the checks are pure C++ (a throwing check is a FAIL, as in the CLI).
std::vector<Ran> run_checks(const app::CheckRegistry& registry, const std::vector<std::string>& only) {
    std::vector<Ran> ran;
    for (const auto& c : registry.checks()) {
        if (!app::is_selected(c, only)) continue;
        Ran r{&c, {}, 0};
        const auto t0 = std::chrono::steady_clock::now();
        try {
            r.outcome = c.run();
        } catch (const std::exception& e) {
            r.outcome.status = app::CheckStatus::kFail;
            r.outcome.summary = std::string("exception: ") + e.what();
        }
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ran.push_back(std::move(r));
    }
    return ran;
}

std::vector<std::string> only_list(const std::optional<std::variant<std::string, std::vector<std::string>>>& only) {
    if (!only) return {};
    if (const auto* s = std::get_if<std::string>(&*only)) return {*s};
    return std::get<std::vector<std::string>>(*only);
}

py::dict verify_py(const std::optional<std::variant<std::string, std::vector<std::string>>>& only_arg) {
    const std::vector<std::string> only = only_list(only_arg);
    const app::CheckRegistry registry = app::default_checks();
    bool any = false;
    for (const auto& c : registry.checks()) any = any || app::is_selected(c, only);
    if (!any) throw std::invalid_argument("verify: no check matches only= (see dualhex.list_checks())");
    std::vector<Ran> ran;
    const auto t0 = std::chrono::steady_clock::now();
    {
        py::gil_scoped_release release;
        ran = run_checks(registry, only);
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    py::list checks;
    int passed = 0, failed = 0, skipped = 0;
    for (const Ran& r : ran) {
        const app::CheckStatus s = r.outcome.status;
        (s == app::CheckStatus::kPass ? passed : s == app::CheckStatus::kFail ? failed : skipped) += 1;
        py::dict c;
        c["name"] = r.check->name;
        c["description"] = r.check->description;
        c["status"] = app::to_string(s);
        c["ok"] = s != app::CheckStatus::kFail;
        c["summary"] = r.outcome.summary;
        c["seconds"] = r.seconds;
        c["details"] = to_python(r.outcome.details);
        c["report"] = r.outcome.report;
        checks.append(c);
    }
    py::dict d;
    d["ok"] = failed == 0;
    d["passed"] = passed;
    d["failed"] = failed;
    d["skipped"] = skipped;
    d["seconds"] = total;
    d["checks"] = checks;
    return d;
}

py::list list_checks() {
    py::list l;
    const app::CheckRegistry registry = app::default_checks();  // (a temporary would die before the loop)
    for (const auto& c : registry.checks()) {
        py::dict d;
        d["name"] = c.name;
        d["description"] = c.description;
        d["on_request"] = c.on_request;
        l.append(d);
    }
    return l;
}

py::dict classify_py() {
    app::Classification c;
    {
        py::gil_scoped_release release;
        c = app::compute_classification();
    }
    py::list classes;
    for (const auto& row : c.classes) {
        py::dict r;
        r["representative"] = row.representative;
        r["size"] = row.size;
        r["fine_octants"] = row.fine_octants;
        classes.append(r);
    }
    py::dict paper;
    paper["classes_full_group"] = app::kPaperClassesFullGroup;
    paper["nontrivial_classes"] = app::kPaperNontrivialClasses;
    paper["classes_rotations_expected"] = app::kExpectedClassesRotations;
    py::dict d;
    d["configurations"] = c.configurations;
    d["classes_full_group"] = c.classes_full_group;
    d["classes_rotations"] = c.classes_rotations;
    d["nontrivial_classes"] = c.nontrivial_classes;
    d["paper"] = paper;
    d["matches_paper"] = c.classes_full_group == app::kPaperClassesFullGroup &&
                         c.nontrivial_classes == app::kPaperNontrivialClasses &&
                         c.classes_rotations == app::kExpectedClassesRotations;
    d["classes"] = classes;
    return d;
}

}  // namespace

void bind_verify(py::module_& m) {
    m.def("verify", &verify_py, py::arg("only") = py::none(),
          "Runs the checks of `dualhex verify` (only: a name substring or a list of them) and returns the report "
          "as a dict: ok, passed, failed, skipped, seconds, checks [{name, description, status, ok, summary, "
          "seconds, details, report}].");
    m.def("list_checks", &list_checks, "The registered checks: [{name, description, on_request}] (on request: run only when only= gives their exact name).");
    m.def(
        "elements_directory",
        []() -> py::object {
            const auto dir = find_elements_directory();
            return dir.empty() ? py::object(py::none()) : py::object(py::str(dir.string()));
        },
        "The element files on disk (DUALHEX_ELEMENTS, the installed share/dualhex/elements, or the source "
        "tree), None if none is found; install() and mesh() use the copy compiled into the module.");
    m.def("classify", &classify_py,
          "The 256 configurations around an application point classified under the 48 cube symmetries and the 24 "
          "rotations (as `dualhex classify --json`).");
}

}  // namespace dualhex::python
