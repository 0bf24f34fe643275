// Certificates of the compositional windows (compositional.hpp): one per congruence class.
//
// Classes are found from the windows' leaf placements: a window is its 8 leaves, each fine,
// a plain hex or an element e placed by a world symmetry W (the complex depends on W only up
// to e's own symmetries, so W is taken modulo e's stabiliser). A symmetry s about g moves
// the leaf at box b to s(b) and W to s.W. The class key is the smallest such image over the
// 48 symmetries. The key only groups: every member is then checked to BE the image of its
// representative (exact lattice forms, variants::complex_form), or nothing is written.
#include <algorithm>
#include <array>
#include <map>
#include <sstream>
#include <stdexcept>

#include "dualhex/checkers/window_certificates.hpp"
#include "dualhex/schemes/variants.hpp"

namespace dualhex {
namespace {

constexpr int kFine = -1, kHex = -2;
using Key = std::array<int, 8>;

// Position index of the leaf box with min corner m (window coordinates, leaf units, m in {-1,0}^3).
int position(const std::array<std::int64_t, 3>& m) {
    return static_cast<int>((m[0] + 1) | (m[1] + 1) << 1 | (m[2] + 1) << 2);
}

// A placed element's code: its element and its world symmetry W taken modulo the element's
// own symmetries (the smallest index among W.S, S in its stabiliser).
class PlacementCodes {
public:
    explicit PlacementCodes(const ElementLibrary& library) : library_(&library) {}
    int code(const std::string& element, const CubeSymmetry& W) {
        auto it = stabiliser_.find(element);
        if (it == stabiliser_.end()) {
            const CellComplex& e = library_->at(element).complex;
            it = stabiliser_.emplace(element, variants::symmetries_mapping(e, e)).first;
            names_.emplace(element, static_cast<int>(names_.size()));
        }
        int best = CubeSymmetry::kOrder;
        for (const CubeSymmetry& S : it->second) best = std::min(best, W.compose(S).index());
        return names_.at(element) * CubeSymmetry::kOrder + best;
    }

private:
    const ElementLibrary* library_;
    std::map<std::string, std::vector<CubeSymmetry>> stabiliser_;
    std::map<std::string, int> names_;
};

// The window's key under symmetry s about g (s = identity: as built).
Key image_key(const CompositionalWindow& w, const CubeSymmetry& s, PlacementCodes& codes) {
    const LatticePoint g{w.parity[0], w.parity[1], w.parity[2]};
    Key key;
    key.fill(kFine);  // positions without a coarse leaf hold 8 fine hexes
    for (const PlacedLeaf& leaf : w.built->coarse_leaves) {
        std::array<std::int64_t, 3> lo{1, 1, 1};  // the image box's min corner (the window is [-1, 1]^3)
        for (int c = 0; c < 8; ++c) {
            const LatticePoint img = s.apply(leaf.leaf - g + LatticePoint{c & 1, (c >> 1) & 1, (c >> 2) & 1});
            for (int a = 0; a < 3; ++a) lo[static_cast<std::size_t>(a)] = std::min(lo[static_cast<std::size_t>(a)], img[a]);
        }
        key[static_cast<std::size_t>(position(lo))] =
            leaf.placement ? codes.code(leaf.placement->element, s.compose(world_symmetry(leaf.context, *leaf.placement)))
                           : kHex;
    }
    return key;
}

struct WindowClass {
    std::string witness;
    variants::ComplexForm form;  // complex_form(representative, symmetry giving the key)
    CellComplex complex;
    std::int64_t unit = 0;
    std::vector<std::int64_t> members;
};

}  // namespace

CertificateSet certify_windows(const TransitionRule& rule, const ElementLibrary& library, const std::filesystem::path& dir,
                               std::size_t per_file) {
    PlacementCodes codes(library);
    std::map<Key, std::size_t> class_of;
    std::vector<WindowClass> classes;
    std::int64_t label = 0;
    CompositionalOptions options;
    options.on_window = [&](const CompositionalWindow& w) {
        if (!w.report->ok()) throw std::runtime_error("certify_windows: window " + describe_window(w) + " fails: " + w.report->summary());
        Key best;
        CubeSymmetry best_s;
        for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
            const CubeSymmetry s = CubeSymmetry::from_index(i);
            const Key k = image_key(w, s, codes);
            if (i == 0 || k < best) best = k, best_s = s;
        }
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
