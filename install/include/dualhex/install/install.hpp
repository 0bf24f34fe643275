#pragma once
// Installing elements into a real grid: every leaf of every level becomes either the
// rule's placed element or a plain hexahedron, all welded into one CellComplex.
//
// Per leaf (L, i, j, k): its application point P (per axis the even one of i, i+1) and
// direction d, in level-L units; its context's octant cubes are the level L-1 cells
// around P, fine iff covered by leaves of level > L (with pairing: iff their children
// are subdivided). Cubes outside the root are coarse (OutsideRoot::Coarse, the default)
// or mirror the cube reflected across the root face (OutsideRoot::Mirror: a transition
// that meets the root boundary then looks as if it continued symmetrically; e.g. a flat
// interface reaching a side wall stays a flat pattern there).
//
// Lattice: the finest level's leaf is U units (U = the library's common resolution);
// a level-l leaf spans U * 2^(maxlevel - l), its element is scaled by 2^(maxlevel - l).
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"
#include "dualhex/schemes/placement.hpp"
#include "dualhex/topology/cell_complex.hpp"

namespace dualhex {

class ElementLibrary;  // dualhex/install/library.hpp loads one

enum class OutsideRoot { Coarse, Mirror };

struct InstallOptions {
    OutsideRoot outside_root = OutsideRoot::Coarse;
    /// The balance the grid must have (with pairing). Weak (default, as `dualhex install`):
    /// accepts weakly, hence also strongly, balanced grids (a weak grid needs the WeakRule);
    /// Strong: only the 8 strong elements' domain.
    Balance balance = Balance::Weak;
};

/// A grid that cannot be installed (not paired / not balanced) or a leaf the rule or the
/// library refuses. what() names the leaves ("L i j k (line N)").
class InstallError : public std::runtime_error {
public:
    InstallError(const std::string& message, std::optional<std::size_t> first = {},
                 std::optional<std::size_t> second = {})
        : std::runtime_error(message), first_(first), second_(second) {}
    /// Offending leaf indices (into the grid), when there are such.
    [[nodiscard]] std::optional<std::size_t> first() const { return first_; }
    [[nodiscard]] std::optional<std::size_t> second() const { return second_; }

private:
    std::optional<std::size_t> first_, second_;
};

struct InstallResult {
    CellComplex complex;
    std::int64_t unit = 0;  ///< lattice units of a finest-level leaf
    int max_level = 0;
    /// Cells of leaf n: [leaf_cells[n], leaf_cells[n+1]).
    std::vector<std::uint32_t> leaf_cells;
    /// Per leaf: index into element_names, -1 for a plain hexahedron.
    std::vector<std::int16_t> leaf_element;
    /// Per leaf: world symmetry index (CubeSymmetry::from_index) of its placement, 0 for hexes.
    std::vector<std::int8_t> leaf_symmetry;
    std::vector<std::string> element_names;

    /// Leaves per element name ("hex" for plain hexahedra).
    [[nodiscard]] std::map<std::string, std::size_t> elements_used() const;
};

/// Refuses (InstallError) a grid that is not paired or not balanced, naming the leaves;
/// a rule exception or an unknown element becomes an InstallError naming the leaf.
[[nodiscard]] InstallResult install(const LeafGrid& grid, const TransitionRule& rule, const ElementLibrary& library,
                                    const InstallOptions& options = {});

/// Installs only `leaves` (any subset of a paired, balanced grid whose finest level is
/// `max_level`), leaf n with the caller's contexts[n] (leaf_contexts.hpp: leaf_context with
/// a SubdividedQuery), welded by lattice keys in the same lattice as install() on the
/// whole grid. Nothing is checked about the grid (the caller holds only part of it); the
/// rule's refusals are InstallErrors naming the leaf. The cells of a leaf are those
/// install() gives it, in the same order.
[[nodiscard]] InstallResult install_leaves(const std::vector<Leaf>& leaves, const std::vector<LeafContext>& contexts,
                                           int max_level, const TransitionRule& rule, const ElementLibrary& library);

/// The paired + balanced check install() applies (ok() = installable).
struct InstallCheck {
    bool ok = true;
    std::string message;
    std::optional<std::size_t> first, second;
};
[[nodiscard]] InstallCheck check_installable(const LeafGrid& grid, Balance balance = Balance::Strong);

}  // namespace dualhex
