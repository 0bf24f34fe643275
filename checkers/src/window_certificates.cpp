// Certificates of the compositional windows (compositional.hpp): one per congruence class.
//
// Classes are found from the windows' leaf placements (window_classes.hpp). The key only
// groups: every member is then checked to BE the image of its representative (exact lattice
// forms, variants::complex_form), or nothing is written.
#include <algorithm>
#include <array>
#include <map>
#include <sstream>
#include <stdexcept>

#include "dualhex/checkers/window_certificates.hpp"
#include "dualhex/schemes/variants.hpp"
#include "window_classes.hpp"

namespace dualhex {
namespace {

using detail::PlacementCodes;
using detail::WindowKey;

struct WindowClass {
    std::string witness;
    variants::ComplexForm form;  // complex_form(representative, symmetry giving the key)
    CellComplex complex;
    std::int64_t unit = 0;
    std::vector<std::int64_t> members;
};

}  // namespace

CertificateSet certify_windows(const TransitionRule& rule, const ElementLibrary& library, const std::filesystem::path& dir,
                               std::size_t per_file, const Progress& progress) {
    PlacementCodes codes(library);
    std::map<WindowKey, std::size_t> class_of;
    std::vector<WindowClass> classes;
    std::int64_t label = 0;
    CompositionalOptions options;
    options.progress = progress;
    options.on_window = [&](const CompositionalWindow& w) {
        if (!w.report->ok()) throw std::runtime_error("certify_windows: window " + describe_window(w) + " fails: " + w.report->summary());
        const auto [best, best_s] = detail::window_class_key(w.parity, w.built->coarse_leaves, codes);
        const auto [it, fresh] = class_of.emplace(best, classes.size());
        if (fresh) {
            WindowClass c;
            c.witness = describe_window(w);
            c.form = variants::complex_form(w.built->complex, best_s);
            c.complex = w.built->complex;
            c.unit = w.built->unit;
            classes.push_back(std::move(c));
        } else if (variants::complex_form(w.built->complex, best_s) != classes[it->second].form) {
            throw std::runtime_error("certify_windows: window " + describe_window(w) + " has the key of class " +
                                     std::to_string(it->second) + " but is not its image");
        }
        classes[it->second].members.push_back(label++);
    };
    const CompositionalResult result = run_compositional(rule, library, options);
    if (!result.all_passed()) throw std::runtime_error("certify_windows: the enumeration does not pass");

    CertificateSet set(dir, label);
    const auto certificate = [&](std::size_t k) {
        const WindowClass& c = classes[k];
        CertificateSpec spec;
        spec.name = "window-" + std::to_string(k);
        spec.kind = CertificateKind::Installation;
        spec.domain = CertificateDomain::box({-c.unit, -c.unit, -c.unit}, {c.unit, c.unit, c.unit});
        spec.comments = {"window B(g) = the 2x2x2 leaves around g, moved to the origin (proofs/README.md)",
                         "representative: " + c.witness,
                         "covers: the " + std::to_string(c.members.size()) +
                             " enumerated windows that are its images under the 48 symmetries about g"};
        spec.covers = c.members;
        return certificate_to_string(c.complex, spec);
    };
    set.add_ranges({.prefix = "windows", .digits = 4, .max_count = per_file}, classes.size(),
                   CertificateKind::Installation, certificate, [](std::size_t k) { return k; });
    set.write_manifest();
    return set;
}

}  // namespace dualhex
