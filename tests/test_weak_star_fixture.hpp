#pragma once
// The weak rule's default library and influence table, built once per test program
// (tests of the weak star enumerations: test_compositional_weak_stars, test_weak_root_stars).
#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex::test {

inline const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

inline const WeakStarInfluence& weak_influence() {
    static const WeakStarInfluence r = weak_star_influence(WeakRule(), library());
    return r;
}

}  // namespace dualhex::test
