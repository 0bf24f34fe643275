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
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "dualhex/schemes/placement.hpp"
#include "dualhex/topology/lattice.hpp"

namespace dualhex {

class CellComplex;
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

/// `ctx` (its frame kept) with the local bits of visible context `index` set.
[[nodiscard]] LeafContext set_visible_context(LeafContext ctx, int index, const std::array<std::array<int, 3>, 9>& bits);

/// The influence table of a rule over its visible domain (4,096 contexts; a refused
/// context counts as a piece of its own at every position).
[[nodiscard]] WeakStarInfluence weak_star_influence(const TransitionRule& rule, const ElementLibrary& library,
                                                    StarPiece kind = StarPiece::Cells);

/// The joint reads of the star of a vertex v near a lattice point g (W7, relevant bits
/// only). For every candidate v within 1/2 of g (max norm, level-m units: every element
/// vertex of a level-m..m+2 cell near g, every corner of a level-(m+3) cell) and every
/// possible configuration of the leaves at v (a level m..m+3 per sign octant: min m,
/// pairing, weak balance across faces), the statuses f (proofs/README.md "Statuses") that
/// the leaves' relevant bits at v name, less those the configuration forces; "shared": read
/// by two or more of the leaves. A joint enumeration in the manner of the strong windows
/// would run over 2^shared assignments per (v, configuration), each leaf's private ones as
/// a product. Units: a level-(m+3) cell is U.
struct WeakStarReads {
    std::array<int, 3> parity{};
    int vertices = 0;         ///< candidate positions v
    long configurations = 0;  ///< (v, configuration) pairs
    int max_free = 0;         ///< max over pairs: free statuses read
    int max_shared = 0;       ///< max over pairs: of those, read by two or more leaves
    int max_leaves = 0;       ///< max over pairs: distinct leaves at v
    double joint = 0;         ///< sum over pairs of 2^shared
    LatticePoint worst;       ///< a v attaining max_shared (relative to g)
    std::array<int, 8> worst_levels{};  ///< and its configuration (level - m per sign octant)
    std::map<int, long> shared_histogram;  ///< shared statuses -> pairs
};
[[nodiscard]] std::vector<WeakStarReads> weak_star_reads(const WeakStarInfluence& influence);

/// The star enumeration of W7 (relevant bits only): for every (v, configuration) of
/// weak_star_reads, every distinct tuple of the leaves' pieces over the assignments of the
/// free statuses satisfying the implications, found by a search over partial assignments
/// (W9 (vii)) or, with reference_product, as every assignment of the statuses read by two
/// or more leaves times per leaf every distinct piece over its private ones; each tuple
/// (a star: the whole cells at v of the leaves at v) is built and v is checked by dualhex's
/// validator (6 edges, octahedral link, edges of 4 cells in one cycle, faces of two cells
/// with opposite sides, a cube as dual cell). A tuple with no cell at v (v is not a vertex)
/// is skipped. Computed by dualhex: no certificate stands for it.
struct WeakStarCheck {
    std::string rule;
    long pairs = 0;        ///< (v, configuration) pairs
    long assignments = 0;  ///< joint assignments of shared statuses enumerated (reference product)
    long search_nodes = 0;  ///< search nodes fixing a leaf's piece (the search, W9 (vii))
    long stars = 0;        ///< distinct stars built and checked (per pair)
    long empty = 0;        ///< tuples with no cell at v
    long passed = 0, failed = 0;
    /// Sum over pairs of 2^(shared statuses, those tied by implications included): the
    /// joint loop's size before the implications prune it; and the largest exponent.
    double joint_bound = 0;
    int max_shared = 0;
    /// Corner pairs (8 leaves, each with v as a corner) passed by W11's check instead of
    /// star by star (WeakStarOptions::corner_pairs); the pieces (P1) and quadrant tuples
    /// (P2) it checked. A corner pair that fails counts in `failed`.
    long corner_pairs = 0, corner_pieces = 0, corner_quadrant_tuples = 0;
    long corner_witnesses = 0;  ///< W14 (f)'s witness stars checked (one per quadrant tuple)
    std::vector<std::string> failures;  ///< the first few, described
    [[nodiscard]] bool all_passed() const { return (stars > 0 || corner_pairs > 0) && failed == 0 && passed == stars; }
};

/// Where a corner pair (8 leaves, each with v as a corner of its cube) is checked leaf by
/// leaf and quadrant by quadrant (proofs/README.md W11) instead of star by star.
enum class CornerPairs {
    WhenSearchGivesUp,  ///< only where the star search exceeds search_limit
    Always,             ///< every corner pair
    Never,              ///< none: a search that gives up is a failure
    /// Every corner pair, by W14 (f)'s witness stars alone (Lemma S6) instead of W11 (S4):
    /// for the comparisons.
    AlwaysByWitnesses,
};

/// What names one star of the run; labels sort by parity, then v, configuration, pieces.
struct WeakStarLabel {
    int parity = 0;               ///< t: g = (t&1, t>>1&1, t>>2&1) level-m units
    LatticePoint v;               ///< relative to g
    std::array<int, 8> levels{};  ///< level - m per sign octant
    std::vector<int> pieces;      ///< per distinct leaf at v (-1: no cell at v)
    auto operator<=>(const WeakStarLabel&) const = default;
};

/// What names one quadrant tuple of a corner pair checked by W11: the pair (parity, v - g,
/// configuration), the two octants across the quadrant (bit a: +a; octant < other) and the
/// two leaves' pieces.
struct WeakCornerLabel {
    int parity = 0;
    LatticePoint v;
    std::array<int, 8> levels{};
    int octant = 0, other = 0;
    std::vector<int> pieces;
    auto operator<=>(const WeakCornerLabel&) const = default;
};

struct WeakStarOptions {
    unsigned parities = 0xFF;  ///< bit t: run parity t (g = (t&1, t>>1&1, t>>2&1))
    /// Optional: only the candidate vertices v (relative to g) it accepts (a partial run).
    std::function<bool(const LatticePoint&)> vertex;
    long stop_after = 0;  ///< stop once this many stars failed (0: never; counts then partial)
    bool count_only = false;  ///< only the pairs, joint_bound and max_shared (no stars)
    /// The reference enumeration (every joint assignment of the shared statuses, times each
    /// leaf's private ones; W9 (vi)) instead of the search (W9 (vii)); out of reach at 111.
    bool reference_product = false;
    /// The search's nodes at one (vertex, configuration) pair beyond which it gives up on
    /// the pair, counted as a failure (so a run that gives up never passes).
    long search_limit = 5'000'000;
    /// Optional: told every distinct star (v relative to g, the piece per leaf; -1: no cell
    /// at v) before it is checked. Called from several threads at once.
    std::function<void(const LatticePoint&, const std::vector<int>&)> stars;
    bool build_stars = true;  ///< false: only enumerate and count them (stars, empty; none checked)
    CornerPairs corner_pairs = CornerPairs::WhenSearchGivesUp;
    /// Optional: told each pair's verdict (v relative to g, level - m per sign octant, true
    /// iff nothing failed at it) once it is checked. Called from several threads at once.
    std::function<void(const LatticePoint&, const std::array<int, 8>&, bool)> verdicts;
    /// Optional: told every star that passes, with its label and its complex (the whole
    /// cells at v, v moved to the origin). Called from several threads at once.
    std::function<void(const WeakStarLabel&, const CellComplex&)> passed;
    /// Optional: for every corner pair W11 passes, every quadrant tuple with one star of the
    /// pair that has it (corner_witness_stars, W14 (f)), checked like a star first (one that
    /// fails fails the pair). Called from several threads at once.
    std::function<void(const WeakCornerLabel&, const CellComplex&)> corner_witness;
};

/// Runs it (oneTBB over the candidate vertices).
[[nodiscard]] WeakStarCheck run_weak_stars(const TransitionRule& rule, const ElementLibrary& library,
                                           const WeakStarInfluence& influence, const WeakStarOptions& options = {});

}  // namespace dualhex
