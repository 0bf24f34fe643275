#include "dualhex/checkers/exhaustive.hpp"

#include <chrono>
#include <ostream>

#include <tbb/enumerable_thread_specific.h>

#include "dualhex/checkers/cube_window.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/grid/configurations.hpp"
#include "dualhex/install/element_templates.hpp"
#include "congruence_check.hpp"
#include "window_check.hpp"

namespace dualhex {

namespace {

std::string failure_text(const ConfigurationReport& r, const char* where) {
    std::string s = format_mask(r.mask) + " (" + where + "): ";
    if (!r.built) return s + r.error;
    s += std::to_string(r.validation.violations.size()) + " violations";
    for (std::size_t k = 0; k < kViolationKinds; ++k)
        if (r.validation.per_kind[k] > 0)
            s += std::string(", ") + to_string(static_cast<ViolationKind>(k)) + " " + std::to_string(r.validation.per_kind[k]);
    if (r.open_faces) s += ", " + std::to_string(r.open_faces) + " open faces";
    if (r.hexes != r.checked_vertices)
        s += ", " + std::to_string(r.checked_vertices - r.hexes) + " non-cube dual cells";
    return s;
}

// A torus motion moves octant cube b to apply_octant(b), mask bits likewise; a symmetry
// about the application point moves the window's octant b (on the + side of axis a iff
// bit a) to the octant of its image.
std::uint8_t torus_image(std::uint8_t mask, const TorusMotion& m) {
    unsigned out = 0;
    for (int b = 0; b < 8; ++b) out |= ((mask >> b) & 1U) << m.apply_octant(b);
    return static_cast<std::uint8_t>(out);
}
std::uint8_t window_image(std::uint8_t mask, const CubeSymmetry& s) {
    unsigned out = 0;
    for (int b = 0; b < 8; ++b) {
        const LatticePoint img = s.apply({b & 1 ? 1 : -1, b & 2 ? 1 : -1, b & 4 ? 1 : -1});
        out |= ((mask >> b) & 1U) << ((img.x > 0) | (img.y > 0) << 1 | (img.z > 0) << 2);
    }
    return static_cast<std::uint8_t>(out);
}

}  // namespace

ExhaustiveResult run_exhaustive(const TransitionRule& rule, const ElementLibrary& library) {
    const auto start = std::chrono::steady_clock::now();
    ExhaustiveResult res;
    res.rule = rule.name();
    const ConfigurationSpace space(SymmetryGroup::Full);
    for (const ConfigurationClass& c : space.classes()) {
        ClassSummary s;
        s.representative = c.representative;
        s.fine = c.fine;
        res.classes.push_back(s);
    }
    // The 256 tori (classes under the torus's 384 motions) and cube windows (under the 48
    // symmetries about the application point), class by class in parallel
    // (congruence_check.hpp), tallied in mask order.
    std::vector<std::uint8_t> masks(kConfigurationCount);
    for (int m = 0; m < kConfigurationCount; ++m) masks[static_cast<std::size_t>(m)] = static_cast<std::uint8_t>(m);
    const std::int64_t U = detail::common_unit(library);
    // One template cache per thread for every build (the templates do not depend on who
    // placed them first), not one per configuration.
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    res.periodic = detail::check_by_congruence(
        detail::congruence(masks, torus_motions(), torus_image),
        [&](std::size_t m, ConfigurationComplex& built) {
            return detail::check(masks[m], [&] {
                                     return built = detail::complete(detail::periodic_configuration_parts(masks[m], rule, caches.local()));
                                 },
                                 [](const LatticePoint&) { return true; },
                                 [](const CellComplex&, std::span<const VertexHandle>) { return false; });
        },
        [&](std::size_t m) { return detail::periodic_configuration_parts(masks[m], rule, caches.local()); },
        [&](const detail::FormArrays& k, const TorusMotion& motion) { return detail::torus_form(k, motion, 2 * U); });
    res.window = detail::check_by_congruence(
        detail::congruence(masks, detail::all_symmetries(), window_image),
        [&](std::size_t m, ConfigurationComplex& built) {
            return detail::check_window(masks[m], 2 * U, [&] {
                return built = detail::complete(detail::cube_window_parts(masks[m], rule, caches.local()));
            });
        },
        [&](std::size_t m) { return detail::cube_window_parts(masks[m], rule, caches.local()); }, detail::symmetric_form);
    for (int m = 0; m < kConfigurationCount; ++m) {
        const auto mask = static_cast<std::uint8_t>(m);
        const ConfigurationReport& p = res.periodic[static_cast<std::size_t>(m)];
        const ConfigurationReport& w = res.window[static_cast<std::size_t>(m)];
        ClassSummary& s = res.classes[static_cast<std::size_t>(space.class_of(mask))];
        ++s.configurations;
        if (p.ok()) ++s.periodic_passed, ++res.periodic_passed;
        if (w.ok()) ++s.window_passed, ++res.window_passed;
        for (const auto* r : {&p, &w})
            for (const auto& [name, n] : r->elements)
                if (name != "fine") s.elements.insert(name);
        if (s.first_error.empty() && !p.ok()) s.first_error = failure_text(p, "torus");
        if (s.first_error.empty() && !w.ok()) s.first_error = failure_text(w, "window");
        // Statistics of the representative, or of the first member whose torus was built.
        if (p.built && (mask == s.representative || s.cells == 0)) {
            s.shown = mask;
            s.cells = p.cells;
            s.hexes = p.hexes;
            s.checked_vertices = p.checked_vertices;
            s.face_sizes = p.face_sizes;
            s.dual_edge_valences = p.dual_edge_valences;
        }
    }
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
}

void print(std::ostream& os, const ExhaustiveResult& r) {
    os << "rule " << r.rule << ": 256 configurations, " << r.classes.size() << " classes (48 symmetries)\n";
    os << "class  repr        fine  members  torus  window  cells  hexes  F-sizes / dual valences  elements\n";
    for (std::size_t n = 0; n < r.classes.size(); ++n) {
        const ClassSummary& s = r.classes[n];
        os << (n < 10 ? "  " : " ") << n << "   " << format_mask(s.representative) << "  " << s.fine << "     "
           << s.configurations << (s.configurations < 10 ? "        " : "       ") << s.periodic_passed << "/"
           << s.configurations << "  " << s.window_passed << "/" << s.configurations << "  ";
        if (s.cells) {
            if (s.shown != s.representative) os << "[" << format_mask(s.shown) << "] ";
            os << s.cells << "  " << s.hexes << "  " << format_histogram(s.face_sizes) << " / "
               << format_histogram(s.dual_edge_valences);
        } else {
            os << "-  -  -";
        }
        os << "  {";
        bool first = true;
        for (const auto& e : s.elements) os << (first ? "" : ",") << e, first = false;
        os << "}" << (s.passed() ? "  PASS" : "  FAIL") << '\n';
        if (!s.first_error.empty()) os << "        first problem: " << s.first_error << '\n';
    }
    os << "torus " << r.periodic_passed << "/256, window " << r.window_passed << "/256, "
       << (r.all_passed() ? "all passed" : "NOT all passed") << " (" << r.seconds << " s)\n";
}

}  // namespace dualhex
