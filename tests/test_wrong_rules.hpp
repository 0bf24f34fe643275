#pragma once
// Rules that are the strong rule except for one wrong choice: the compositional and the
// root-boundary enumerations must see each (tests/test_compositional*.cpp).
#include <optional>

#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex::test {

enum class WrongChoiceMode {
    MisorientedE,  ///< E placed with a reflected symmetry
    MissingVC,     ///< no centre element where the strong rule places VC
    MissingF,      ///< no element where the strong rule places F
    AgainstLemma,  ///< C1 in a leaf with no fine octant at its application point (the lemma's case)
};

class WrongChoice : public TransitionRule {
public:
    explicit WrongChoice(WrongChoiceMode mode) : mode_(mode) {}
    std::optional<Placement> place(const LeafContext& ctx) const override {
        auto p = StrongRule().place(ctx);
        using M = WrongChoiceMode;
        if (mode_ == M::MisorientedE && p && p->element == "E")
            p->symmetry = CubeSymmetry({2, 1, 0}, {1, 1, 1}).compose(p->symmetry);
        if (mode_ == M::MissingVC && p && p->element == "VC") return std::nullopt;
        if (mode_ == M::MissingF && p && p->element == "F") return std::nullopt;
        if (mode_ == M::AgainstLemma && !p && ctx.fine(1, 0, 0)) return Placement{"C1", {}};
        return p;
    }
    std::uint64_t reach() const override { return strong_reach(); }

private:
    WrongChoiceMode mode_;
};

// A weak rule with one MR element mis-oriented (E-MR reflected across x = y after its
// placement: its truncated edge and one interface swap axes; swapping its two interface axes
// would be a symmetry of E-MR) or missing (VC3-MR refused): the spread grid's installation
// (test_compositional_weak.cpp) and the star enumeration (test_compositional_weak_stars.cpp)
// must see each.
class WeakMutant : public TransitionRule {
public:
    explicit WeakMutant(bool missing) : missing_(missing) {}
    std::optional<Placement> place(const LeafContext& ctx) const override {
        auto p = WeakRule().place(ctx);
        if (!missing_ && p && p->element == "E-MR") p->symmetry = p->symmetry.compose(CubeSymmetry({1, 0, 2}, {1, 1, 1}));
        if (missing_ && p && p->element == "VC3-MR") throw UnknownPatternError("no VC3-MR");
        return p;
    }
    std::uint64_t reach() const override { return strong_reach(); }

private:
    bool missing_;
};

}  // namespace dualhex::test
