#pragma once
// The compositional argument (proofs/README.md, "Compositional argument"): a finite
// enumeration whose success proves that EVERY strongly balanced paired grid, any number of
// levels, installs with the strong rule to a complex in which every vertex off the root
// boundary has 6 edges and an octahedral link, every edge there 4 cells in one cycle, and
// every such vertex a cube as dual cell.
//
// Units: coarse-leaf units of a level m; octant cube o has min corner 2o (its 8 leaves of
// level m, or 64 of level m+1 when it is fine).
//
// 1. Reach. The strong rule reads 10 local octant cubes (TransitionRule::reach(); it masks
//    the rest off, so this holds by construction).
// 2. Lemma (checked here over every context it concerns): a leaf none of whose 7 octant
//    cubes around its application point P is fine gets no element. A leaf L' of level m+1
//    touching a leaf L of level m only meets level-m cells that contain P (L' is P + [0,1/2]^3
//    in level-m units), so L contains P and touches all of them; strong balance keeps them
//    free of level m+2, i.e. not fine for L': L' is a plain cube.
// 3. Reduction. Let v be a vertex, m the smallest level of the leaves containing v (they are
//    of level m or m+1). Those of level m+1 are plain (2). Those of level m see the octant
//    pattern p of level m-1 (octant cube fine iff it holds leaves finer than m), and any
//    pattern is that of the two-level grid G2(p) (coarse: 8 leaves, fine: 64 plain cubes).
//    So v's star is its star in G2(p): two levels suffice.
// 4. Windows. In G2(p), v is within 1/2 (max norm) of a point g of Z^3 and all leaves
//    containing v lie in the 2x2x2 leaves B(g) = [g-1, g+1]^3. B(g)'s complex depends only on
//    the octant cubes its coarse leaves read: R(t), t = g mod 2 (8 parity types). Every
//    assignment of R(t) is enumerated (shared octants exhaustively, each leaf's private ones
//    per leaf: the complex depends on the leaves' outcomes only); each distinct window is
//    built and all its vertices strictly inside B(g) are checked.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/topology/progress.hpp"

namespace dualhex {

/// One of the 8 window types: g = parity (coarse-leaf units; octant corners are even).
struct WindowTypeResult {
    std::array<int, 3> parity{};
    int read_octants = 0;    ///< |R(t)|: the octant cubes the 8 leaves of B(g) read
    int shared_octants = 0;  ///< read by more than one of them (enumerated jointly)
    std::size_t windows = 0; ///< distinct windows (distinct outcomes of the 8 leaves)
    std::size_t passed = 0;
    std::size_t checked_vertices = 0;  ///< over all windows: vertices strictly inside B(g)
};

/// One distinct window as built: its type, a witness assignment (bit i: R(t)[i] is fine)
/// and the complex, translated so that g is the origin (the box [-U, U]^3, U = unit).
struct CompositionalWindow {
    std::array<int, 3> parity{};
    std::size_t index = 0;  ///< among the type's windows
    std::vector<std::array<std::int64_t, 3>> reads;  ///< R(t)
    std::uint64_t pattern = 0;
    const ConfigurationComplex* built = nullptr;
    const ConfigurationReport* report = nullptr;
};

struct CompositionalResult {
    std::string rule;
    int reach_octants = 0;     ///< octant cubes the rule reads
    int lemma_contexts = 0;    ///< contexts with no fine octant at P (every value elsewhere)
    int lemma_plain = 0;       ///< of those, the ones the rule leaves plain
    std::vector<WindowTypeResult> types;  ///< the 8 parity types
    std::size_t windows = 0, passed = 0, failed = 0, checked_vertices = 0;
    std::vector<std::string> failures;  ///< summaries of the first 10 failing windows
    double seconds = 0;
    [[nodiscard]] bool lemma_holds() const { return lemma_contexts > 0 && lemma_plain == lemma_contexts; }
    [[nodiscard]] bool all_passed() const { return lemma_holds() && windows > 0 && passed == windows; }
};

struct CompositionalOptions {
    /// Optional: sees every distinct window after its check (certificates use it).
    std::function<void(const CompositionalWindow&)> on_window;
    /// Stop after this many failing windows (0: never; the counts are then partial).
    std::size_t stop_after_failures = 0;
    /// Optional: stage "windows", the distinct windows checked of all of them.
    Progress progress;
};

/// Runs the enumeration. Rule errors (UnknownPatternError, a missing element) become
/// failing windows.
[[nodiscard]] CompositionalResult run_compositional(const TransitionRule& rule, const ElementLibrary& library,
                                                    const CompositionalOptions& options = {});

/// "g=(1,0,0) fine octants {(0,-1,0) (1,0,0)}": the window's type and witness pattern.
[[nodiscard]] std::string describe_window(const CompositionalWindow& window);

}  // namespace dualhex
