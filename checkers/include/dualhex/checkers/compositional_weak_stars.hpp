#pragma once
// Weak balance, step W7 (proofs/README.md "Weak balance"): which context bits the star of
// a vertex depends on, computed over the weak rule's whole visible domain.
//
// Leaf frame: the leaf [0, U]^3 (U = the library's common unit) with its application point
// P at the origin and direction (+1, +1, +1); every leaf's element is this local element
// moved by the leaf's frame (install emits it so), so what holds here holds for every leaf.
// A visible context is an index 0..4095: bits 0..8 the 9 reach octant cubes other than the
// own one (in neighbourhood-bit order), bits 9..11 the edge bits of the x, y, z inner edges.
//
// The *piece* of a context at a point q is the set of cells of the leaf's element (a plain
// cube when the rule places nothing) that have q as a vertex, each cell by its oriented
// faces, or "q is not a vertex". A bit is *relevant at q* if flipping it changes the piece
// at q in some context; the piece at q is then a function of the relevant bits alone (any
// two contexts that agree on them are joined by flips of irrelevant bits).
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "dualhex/schemes/placement.hpp"
#include "dualhex/topology/lattice.hpp"

namespace dualhex {

class ElementLibrary;

/// What a piece at q holds: the whole cells at q, or only their faces through q (each
/// face whole, grouped by cell): what v's edges, faces, link, edge cycles and dual cell are
/// made of.
enum class StarPiece { Cells, Faces };

struct StarPositionInfluence {
    LatticePoint position;  ///< in the leaf frame [0, U]^3
    int vertex_contexts = 0;  ///< contexts whose element has a vertex at q
    std::uint16_t relevant = 0;  ///< bit i: context bit i is relevant at q
    int pieces = 0;  ///< distinct pieces at q over the 4,096 contexts ("not a vertex" counts)
};

struct WeakStarInfluence {
    std::string rule;
    StarPiece kind = StarPiece::Cells;
    std::int64_t unit = 0;
    std::array<std::array<int, 3>, 9> octant_bits{};  ///< local octant of context bits 0..8
    int contexts = 0, refused = 0;  ///< contexts tried (4,096), refused by the rule
    std::vector<StarPositionInfluence> positions;  ///< every point that is a vertex in some context
    /// Per leaf position q and context: the interned piece (-1: not a vertex). [q][context].
    std::vector<std::vector<int>> piece;
    int distinct_pieces = 0;  ///< over all positions
    std::map<int, int> relevant_histogram;  ///< number of relevant bits -> positions
    [[nodiscard]] int max_relevant() const;
};

/// The influence table of a rule over its visible domain (4,096 contexts; a refused
/// context counts as a piece of its own at every position).
[[nodiscard]] WeakStarInfluence weak_star_influence(const TransitionRule& rule, const ElementLibrary& library,
                                                    StarPiece kind = StarPiece::Cells);

/// The joint reads of the star of a vertex v near a lattice point g (W7, relevant bits
/// only): every cell of levels m, m+1, m+2 whose closure holds v is taken as a possible
/// leaf at v (an over-approximation: in a grid some are not leaves); each reads, through
/// its context, the statuses f (proofs/README.md "Statuses") of the cells its relevant
/// bits at v name, plus those that decide whether it is a leaf (its parent's, and for
/// levels m+1, m+2 its grandparent's; a level-m cell's grandparent is subdivided by the
/// choice of m). Counted per parity t = g mod 2 over every v of the level-(m+2) vertex
/// lattice of the leaves' elements within 1/2 of g (max norm, level-m units).
struct WeakStarReads {
    std::array<int, 3> parity{};
    int vertices = 0;        ///< positions v considered (a vertex of some possible leaf's element)
    int max_statuses = 0;    ///< max over v: distinct cell statuses read by the leaves at v
    int max_shared = 0;      ///< max over v: of those, read by two or more leaves at v
    int max_leaves = 0;      ///< max over v: possible leaves at v
    LatticePoint worst;      ///< a v attaining max_shared (units: a level-(m+2) leaf is U)
    std::map<int, int> shared_histogram;  ///< shared statuses -> vertices
};
[[nodiscard]] std::vector<WeakStarReads> weak_star_reads(const WeakStarInfluence& influence);

}  // namespace dualhex
