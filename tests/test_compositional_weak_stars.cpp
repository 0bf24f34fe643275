// W7 of proofs/README.md, relevant bits only (checkers/compositional_weak_stars.hpp): which
// visible context bits change a weak leaf's cells at each point of the leaf, and how many
// cell statuses the possible leaves at a vertex read jointly.
#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <map>

#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

const WeakStarInfluence& weak_influence(StarPiece kind = StarPiece::Cells) {
    static const WeakStarInfluence cells = weak_star_influence(WeakRule(), library(), StarPiece::Cells);
    static const WeakStarInfluence faces = weak_star_influence(WeakRule(), library(), StarPiece::Faces);
    return kind == StarPiece::Cells ? cells : faces;
}

TEST(WeakStars, InfluenceOverTheVisibleDomain) {
  for (StarPiece kind : {StarPiece::Cells, StarPiece::Faces}) {
    const WeakStarInfluence& r = weak_influence(kind);
    EXPECT_EQ(r.contexts, 4096);
    EXPECT_EQ(r.refused, 0);
    std::printf("unit %lld, %zu positions, %d distinct pieces, max relevant %d\n", static_cast<long long>(r.unit),
                r.positions.size(), r.distinct_pieces, r.max_relevant());
    for (const auto& [k, n] : r.relevant_histogram) std::printf("  %d relevant bits: %d positions\n", k, n);
    for (const auto& p : r.positions) {
        const bool corner = (p.position.x % r.unit == 0) && (p.position.y % r.unit == 0) && (p.position.z % r.unit == 0);
        if (corner)
            std::printf("  corner (%lld,%lld,%lld): relevant 0x%03x (%d), %d pieces, vertex in %d\n",
                        static_cast<long long>(p.position.x), static_cast<long long>(p.position.y),
                        static_cast<long long>(p.position.z), p.relevant, std::popcount(p.relevant), p.pieces,
                        p.vertex_contexts);
    }
  }
}

TEST(WeakStars, JointReads) {
  for (StarPiece kind : {StarPiece::Cells, StarPiece::Faces})
    for (const WeakStarReads& w : weak_star_reads(weak_influence(kind))) {
        std::printf("g=%d%d%d: %d vertices, max leaves %d, max statuses %d, max shared %d at (%lld,%lld,%lld)\n",
                    w.parity[0], w.parity[1], w.parity[2], w.vertices, w.max_leaves, w.max_statuses, w.max_shared,
                    static_cast<long long>(w.worst.x), static_cast<long long>(w.worst.y), static_cast<long long>(w.worst.z));
        for (const auto& [k, n] : w.shared_histogram) std::printf("   shared %d: %d\n", k, n);
    }
}

}  // namespace
}  // namespace dualhex
