#pragma once
// Rules that are the strong rule except for one wrong choice: the compositional and the
// root-boundary enumerations must see each (tests/test_compositional*.cpp).
#include <optional>

#include "dualhex/schemes/signature_rule.hpp"

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

}  // namespace dualhex::test
