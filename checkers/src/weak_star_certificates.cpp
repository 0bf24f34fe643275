// Certificates of the weak star runs (weak_star_certificates.hpp). The runs are parallel and
// tell their stars in any order; everything written is a function of the labels, so the
// files are the same on every run.
#include "dualhex/checkers/weak_star_certificates.hpp"

#include <algorithm>
#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <stdexcept>

#include "congruence_check.hpp"
#include "dualhex/checkers/boundary_certificates.hpp"
#include "dualhex/checkers/compositional_weak_root_stars.hpp"
#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "weak_star_pair.hpp"
#include "window_check.hpp"

namespace dualhex {
namespace {

// A root-surface star's label: policy (0 Coarse, 1 Mirror), type, v - g, configuration, pieces.
struct RootStarLabel {
    int policy = 0;
    RootSides sides{};
    std::array<int, 3> parity{};
    LatticePoint v;
    std::array<int, 8> levels{};
    std::vector<int> pieces;
    auto operator<=>(const RootStarLabel&) const = default;
};

std::string numbers(const auto& xs) {
    std::string out;
    for (auto x : xs) out += " " + std::to_string(x);
    return out;
}
std::string at(const LatticePoint& v) {
    return "v - g = (" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}
std::string text(const WeakStarLabel& l) {
    return "parity " + std::to_string(l.parity) + ", " + at(l.v) + ", levels - m" + numbers(l.levels) + ", pieces" +
           numbers(l.pieces);
}
std::string text(const WeakCornerLabel& l) {
    return "parity " + std::to_string(l.parity) + ", " + at(l.v) + ", levels - m" + numbers(l.levels) + ", octants " +
           std::to_string(l.octant) + " and " + std::to_string(l.other) + ", their pieces" + numbers(l.pieces);
}
std::string text(const RootStarLabel& l) {
    return std::string(l.policy == 0 ? "coarse" : "mirror") + ", sides" + numbers(l.sides) + ", parity" +
           numbers(l.parity) + ", " + at(l.v) + ", levels - m (outside -1)" + numbers(l.levels) + ", pieces" +
           numbers(l.pieces);
}
std::string text(const WeakNearRootStarLabel& l) {
    std::string planes;
    for (int a = 0; a < 3; ++a)
        for (const auto& p : {l.below[static_cast<std::size_t>(a)], l.above[static_cast<std::size_t>(a)]})
            planes += p ? " " + std::to_string(*p) : " -";
    return "parity " + std::to_string(l.parity) + ", " + at(l.v) + ", levels - m" + numbers(l.levels) + ", sides" +
           numbers(l.sides) + ", further planes (below, above per axis)" + planes + ", pieces" + numbers(l.pieces);
}

// A star on root planes (the inside leaves' cells at v) reflected across them into a whole
// star at v; checked by dualhex at v and proved its own image under each reflection first.
CellComplex doubled_star(const CellComplex& half, const RootSides& sides, const std::string& what) {
    CellComplex doubled = double_half_window(half, sides);
    ConfigurationComplex built;
    built.complex = doubled;
    const ConfigurationReport r = detail::analyse(std::move(built), weak_stars::at_v, weak_stars::away_from_v);
    if (!r.ok() || r.checked_vertices != 1) throw std::runtime_error("the doubled star " + what + " fails: " + r.summary());
    if (!symmetric_across_root_planes(doubled, sides)) throw std::runtime_error("the doubled star " + what + " is not symmetric");
    return doubled;
}

// The stars told by a run, grouped into congruence classes (thread-safe `add`).
template <class Label>
class StarClasses {
public:
    // Many stars are the same complex: its key is computed once (48 forms), from its own form.
    void add(const Label& label, const CellComplex& star) {
        detail::OrientedForm self = detail::symmetric_form(star, CubeSymmetry{});
        if (self.empty()) throw std::runtime_error("star certificates: a star beyond the oriented form's reach");
        std::unique_lock guard(lock_);
        auto known = class_of_.find(self);
        if (known == class_of_.end()) {
            guard.unlock();
            detail::OrientedForm key = detail::congruence_key(star);
            guard.lock();
            const auto it = classes_.try_emplace(std::move(key), Class{label, star, {}}).first;
            known = class_of_.emplace(std::move(self), &it->second).first;
        }
        Class& c = *known->second;
        if (label < c.first) c.first = label, c.complex = star;
        c.members.push_back(label);
    }

    // One star certificate per class, by representative; a star's label number is its
    // place among all labels. `stars`: how many the run checked (each must be told once).
    CertificateSet write(const std::filesystem::path& dir, long stars, std::size_t per_file, const std::string& what) const {
        std::vector<Label> labels;
        for (const auto& [key, c] : classes_) labels.insert(labels.end(), c.members.begin(), c.members.end());
        std::sort(labels.begin(), labels.end());
        if (static_cast<long>(labels.size()) != stars || std::adjacent_find(labels.begin(), labels.end()) != labels.end())
            throw std::runtime_error("star certificates: the stars told are not the run's stars, once each");
        std::vector<const Class*> ordered;
        for (const auto& [key, c] : classes_) ordered.push_back(&c);
        std::sort(ordered.begin(), ordered.end(), [](const Class* a, const Class* b) { return a->first < b->first; });
        CertificateSet set(dir, static_cast<std::int64_t>(labels.size()));
        const auto certificate = [&](std::size_t k) {
            const Class& c = *ordered[k];
            CertificateSpec spec;
            spec.name = "star-" + std::to_string(k);
            spec.kind = CertificateKind::Star;
            spec.domain = CertificateDomain::point({0, 0, 0});
            spec.comments = {what + " (proofs/README.md W14)", "representative: " + text(c.first),
                             "covers: the " + std::to_string(c.members.size()) +
                                 " enumerated stars that are its images under the 48 symmetries about v"};
            for (const Label& m : c.members) spec.covers.push_back(std::lower_bound(labels.begin(), labels.end(), m) - labels.begin());
            std::sort(spec.covers.begin(), spec.covers.end());
            return certificate_to_string(c.complex, spec);
        };
        set.add_ranges({.prefix = "stars", .digits = 4, .max_count = per_file}, ordered.size(), CertificateKind::Star,
                       certificate, [](std::size_t k) { return k; });
        set.write_manifest();
        return set;
    }

private:
    struct Class {
        Label first;  // the smallest label told; its complex represents the class
        CellComplex complex;
        std::vector<Label> members;
    };
    std::mutex lock_;
    std::map<detail::OrientedForm, Class> classes_;            // by key; map nodes do not move
    std::map<detail::OrientedForm, Class*> class_of_;          // a star's own form -> its class
};

}  // namespace

WeakStarCertificates certify_weak_stars(const ElementLibrary& library, const std::filesystem::path& dir,
                                        const std::filesystem::path& corner_dir, std::size_t per_file) {
    const WeakRule rule;
    StarClasses<WeakStarLabel> classes;
    StarClasses<WeakCornerLabel> corner;
    std::atomic<long> witnesses{0};
    WeakStarOptions options;
    options.passed = [&](const WeakStarLabel& label, const CellComplex& star) { classes.add(label, star); };
    options.corner_witness = [&](const WeakCornerLabel& label, const CellComplex& star) {
        corner.add(label, star);
        ++witnesses;
    };
    const WeakStarCheck run = run_weak_stars(rule, library, weak_star_influence(rule, library), options);
    if (!run.all_passed()) throw std::runtime_error("certify_weak_stars: the star run does not pass");
    return {classes.write(dir, run.stars, per_file, "the whole cells at a vertex v of a weak-rule installation, v moved to the origin"),
            corner.write(corner_dir, witnesses.load(), per_file,
                         "a star of a corner pair checked by W11 that has the quadrant tuple of the label, v moved to the origin")};
}

CertificateSet certify_weak_root_stars(const ElementLibrary& library, const std::filesystem::path& dir, std::size_t per_file) {
    const WeakRule rule;
    const WeakStarInfluence influence = weak_star_influence(rule, library);
    StarClasses<RootStarLabel> classes;
    long stars = 0;
    for (const BoundaryPolicy policy : {BoundaryPolicy::Coarse, BoundaryPolicy::Mirror}) {
        WeakRootStarOptions options;
        options.stars = [&](const WeakRootStar& s) {
            if (!s.complex) return;  // no cell at v
            const RootStarLabel label{policy == BoundaryPolicy::Mirror, s.sides, s.parity, s.v, s.levels, s.pieces};
            classes.add(label, doubled_star(*s.complex, s.sides, text(label)));
        };
        const WeakRootStarCheck run = run_weak_root_stars(rule, library, influence, policy, options);
        if (!run.all_passed()) throw std::runtime_error("certify_weak_root_stars: the root-surface run does not pass");
        stars += run.total(run.stars);
    }
    return classes.write(dir, stars, per_file,
                         "the cells at a vertex v on the root surface under the weak rule, reflected across its root planes "
                         "into a whole star at v, v moved to the origin");
}

CertificateSet certify_weak_near_root_stars(const ElementLibrary& library, const std::filesystem::path& dir, std::size_t per_file) {
    const WeakRule rule;
    StarClasses<WeakNearRootStarLabel> classes;
    WeakNearRootStarOptions options;
    options.passed = [&](const WeakNearRootStarLabel& label, const CellComplex& star) {
        if (label.sides == RootSides{}) classes.add(label, star);
        else classes.add(label, doubled_star(star, label.sides, text(label)));
    };
    const WeakNearRootStarCheck run = run_weak_near_root_stars(rule, library, weak_star_influence(rule, library), options);
    if (!run.all_passed()) throw std::runtime_error("certify_weak_near_root_stars: the near-surface run does not pass");
    return classes.write(dir, run.stars, per_file,
                         "the cells at a vertex v near the root surface under Coarse (reflected across the root planes "
                         "through v, if any, into a whole star at v), v moved to the origin");
}

}  // namespace dualhex
