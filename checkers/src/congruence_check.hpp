#pragma once
// Internal: checking a family of configurations class by class (the weak tori and windows,
// the strong tori and cube windows). Each class (an orbit of the configurations under the
// domain's motions) has its first member as representative, which gets the full check;
// every other member is built and proved to be the exact image of the representative's
// complex (oriented_form.hpp: moved back by the inverse motion, it is the representative's
// complex cell by cell, oriented face by oriented face). The motions taking the
// representative's configuration to a member's are a coset m0 Stab (Stab: the motions that
// fix the representative's configuration); the rule need not be equivariant, so the member
// may be the image under m0 s only, s in Stab: a member whose m0-form differs is compared
// with the representative's forms under each s in Stab (computed once per class, only for
// the classes that need them). The check is invariant under the domain's motions, so the
// member's report is its representative's, except what depends on the placements
// themselves (the elements used, read from the member's own build) and its mask. A member
// no motion of the coset proves congruent, or whose representative fails, is checked
// itself: the coverage is that of checking every configuration. Parallel over members;
// every report lands in its configuration's own slot, so the result does not depend on
// threads.
#include <algorithm>
#include <map>
#include <type_traits>
#include <vector>

#include <tbb/parallel_for.h>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/checkers/torus_classes.hpp"
#include "configuration_parts.hpp"
#include "oriented_form.hpp"

namespace dualhex::detail {

inline TorusMotion inverse_of(const TorusMotion& m) { return m.inverse(); }
inline CubeSymmetry inverse_of(const CubeSymmetry& s) { return s.inverse(); }

/// Per configuration: its class's representative and a motion taking the representative's
/// configuration to it (`moved(config, motion)`: the configuration the motion makes of it);
/// per representative its stabilizer (the motions fixing its configuration, identity
/// included; empty for the other configurations).
template <class Motion>
struct Congruence {
    std::vector<std::size_t> representative;
    std::vector<Motion> motion;
    std::vector<std::vector<Motion>> stabilizer;
};

template <class Config, class Motion, class Moved>
Congruence<Motion> congruence(const std::vector<Config>& all, const std::vector<Motion>& motions, Moved&& moved) {
    Congruence<Motion> out;
    std::map<Config, std::size_t> first;  // orbit key (smallest image) -> representative
    for (std::size_t i = 0; i < all.size(); ++i) {
        Config key = all[i];
        for (const Motion& m : motions) key = std::min(key, moved(all[i], m));
        const std::size_t rep = first.emplace(key, i).first->second;
        out.representative.push_back(rep);
        out.motion.push_back(*std::find_if(motions.begin(), motions.end(),
                                           [&](const Motion& m) { return moved(all[rep], m) == all[i]; }));
        out.stabilizer.emplace_back();
        if (rep == i)
            for (const Motion& m : motions)
                if (moved(all[i], m) == all[i]) out.stabilizer.back().push_back(m);
    }
    return out;
}

// The placements only (not the complex): a member's ConfigurationParts header serves.
inline std::map<std::string, std::size_t> elements_of(const ConfigurationComplex& built) {
    std::map<std::string, std::size_t> out;
    for (const PlacedLeaf& leaf : built.coarse_leaves) ++out[leaf.placement ? leaf.placement->element : "hex"];
    if (built.fine_hexes) out["fine"] = built.fine_hexes;
    return out;
}

/// The representative's forms under its stabilizer, sorted and distinct.
template <class Motion, class Form>
std::vector<OrientedForm> stabilizer_forms(const CellComplex& k, const std::vector<Motion>& stabilizer, Form&& form) {
    std::vector<OrientedForm> out;
    for (const Motion& s : stabilizer) out.push_back(form(k, s));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

/// Every configuration's report: `check(i, built)` checks configuration i keeping its
/// complex in `built`, `build(i)` only builds it (may throw; a ConfigurationComplex, or its
/// ConfigurationParts, which members need no more of), `form(arrays, motion)` is the
/// complex's oriented form moved by the motion.
template <class Motion, class Check, class Build, class Form>
std::vector<ConfigurationReport> check_by_congruence(const Congruence<Motion>& classes, Check&& check, Build&& build,
                                                     Form&& form) {
    const std::size_t n = classes.representative.size();
    std::vector<ConfigurationReport> out(n);
    std::vector<ConfigurationComplex> kept(n);  // the representatives' complexes
    std::vector<OrientedForm> forms(n);         // a representative's form; a member's moved back by m0
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (classes.representative[i] != i) return;
        out[i] = check(i, kept[i]);
        if (out[i].ok()) forms[i] = form(kept[i].complex, Motion{});  // empty: members get full checks
    });
    // A proved member: its representative's report, with its own mask and placements.
    const auto carry = [&](std::size_t i, const auto& built) {
        out[i] = out[classes.representative[i]];
        out[i].mask = header_of(built).mask;
        out[i].elements = elements_of(header_of(built));
    };
    using Built = std::decay_t<decltype(build(std::size_t{0}))>;
    std::vector<Built> pending(n);  // members whose m0-form differs
    std::vector<char> needs_stabilizer(n, 0);      // per representative
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        const std::size_t rep = classes.representative[i];
        if (rep == i) return;
        if (out[rep].ok() && !forms[rep].empty()) {
            try {
                Built built = build(i);
                OrientedForm f = form(form_source(built), inverse_of(classes.motion[i]));
                if (f == forms[rep]) return carry(i, built);
                if (!f.empty() && classes.stabilizer[rep].size() > 1) {
                    forms[i] = std::move(f);
                    pending[i] = std::move(built);
                    needs_stabilizer[rep] = 1;  // every writer writes 1
                    return;
                }
            } catch (const std::exception&) {  // the full check below reports it
            }
        }
        ConfigurationComplex built;
        out[i] = check(i, built);
    });
    std::vector<std::vector<OrientedForm>> under_stabilizer(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (needs_stabilizer[i]) under_stabilizer[i] = stabilizer_forms(kept[i].complex, classes.stabilizer[i], form);
    });
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (forms[i].empty() || classes.representative[i] == i) return;
        const auto& images = under_stabilizer[classes.representative[i]];
        if (std::binary_search(images.begin(), images.end(), forms[i])) return carry(i, pending[i]);
        ConfigurationComplex built;
        out[i] = check(i, built);
    });
    return out;
}

/// The oriented form moved by a torus motion (positions reduced modulo the period) or by a
/// symmetry about the origin.
inline OrientedForm torus_form(const FormArrays& k, const TorusMotion& m, std::int64_t octant) {
    return oriented_form(k, [&](const LatticePoint& p) { return m.apply(p, octant); }, m.symmetry.determinant() < 0);
}
inline OrientedForm symmetric_form(const FormArrays& k, const CubeSymmetry& s) {
    return oriented_form(k, [&](const LatticePoint& p) { return s.apply(p); }, !s.is_rotation());
}

/// The 48 symmetries (identity first).
inline std::vector<CubeSymmetry> all_symmetries() {
    std::vector<CubeSymmetry> out;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) out.push_back(CubeSymmetry::from_index(i));
    return out;
}

/// The smallest oriented form over the 48 symmetries about the origin (empty if the complex
/// has no form): equal keys mean that one complex is exactly the other moved by one of them.
inline OrientedForm congruence_key(const FormArrays& k) {
    OrientedForm best;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        OrientedForm f = symmetric_form(k, CubeSymmetry::from_index(i));
        if (f.empty()) return {};
        if (best.empty() || f < best) best = std::move(f);
    }
    return best;
}

}  // namespace dualhex::detail
