#pragma once
// Internal: checking a family of windows class by class under the 48 symmetries about g
// (the compositional windows, compositional_run.cpp; the root-boundary half windows,
// compositional_boundary.cpp).
//
// Each window has a class key and a symmetry s taking it to the key (window_classes.hpp;
// none when the rule throws). The first window with a key is its class's representative
// and gets the full check. Every other member is built and proved to be the exact image of
// the representative: form(member, s_m) == form(representative, s_r) (oriented_form.hpp:
// every moved point and oriented face), so member = s_m^-1 s_r (representative). The
// callers' checks are invariant under those symmetries, so the member's outcome is its
// representative's. A member without a key, not proved such an image, whose build throws,
// or whose representative fails, gets the full check itself: the coverage is that of
// checking every window, whatever the keys say (they only group). Parallel (oneTBB); each
// outcome lands in its window's slot, so the result does not depend on the threads.
#include <cstddef>
#include <exception>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "dualhex/topology/cube_symmetry.hpp"
#include "oriented_form.hpp"

namespace dualhex::detail {

/// What check_by_class needs of a family of n windows.
///   key(i)            -> std::optional<std::pair<Key, CubeSymmetry>> (nullopt: no key)
///   check(i, keep)    -> Outcome: the full check, building the window itself; if keep is not
///                        null and the window was built, its complex is moved into *keep (a Kept)
///   build(i)          -> Built (may throw): a member, built only as far as its form needs
///   check_built(i, b) -> Outcome: the full check of a built window
///   form(b, s)        -> OrientedForm of b (a Built or a Kept) moved by s (empty: no form,
///                        members checked)
///   ok(outcome)       -> bool
template <class Key, class Built, class Outcome, class Kept = Built, class KeyOf, class Check, class Build,
          class CheckBuilt, class Form, class Ok>
std::vector<Outcome> check_by_class(std::size_t n, KeyOf&& key, Check&& check, Build&& build, CheckBuilt&& check_built,
                                    Form&& form, Ok&& ok) {
    std::vector<std::optional<std::pair<Key, CubeSymmetry>>> keys(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { keys[i] = key(i); });
    std::map<Key, std::size_t> class_of;  // classes in window order
    std::vector<std::size_t> representative, class_index(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!keys[i]) continue;
        const auto [it, fresh] = class_of.emplace(keys[i]->first, representative.size());
        if (fresh) representative.push_back(i);
        class_index[i] = it->second;
    }
    std::vector<Outcome> out(n);
    std::vector<OrientedForm> forms(representative.size());
    tbb::parallel_for(std::size_t{0}, representative.size(), [&](std::size_t c) {
        const std::size_t i = representative[c];
        Kept kept{};
        out[i] = check(i, &kept);
        if (ok(out[i])) forms[c] = form(kept, keys[i]->second);  // empty: members get full checks
    });
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (!keys[i]) return void(out[i] = check(i, nullptr));
        const std::size_t rep = representative[class_index[i]];
        if (rep == i) return;
        const OrientedForm& rep_form = forms[class_index[i]];
        if (!ok(out[rep]) || rep_form.empty()) return void(out[i] = check(i, nullptr));
        Built b;
        try {
            b = build(i);
        } catch (const std::exception&) {
            return void(out[i] = check(i, nullptr));  // reports it
        }
        out[i] = form(b, keys[i]->second) == rep_form ? out[rep] : check_built(i, std::move(b));
    });
    return out;
}

}  // namespace dualhex::detail
