#pragma once
// A rank-independent summary of an installed complex and its clipped dual: counts,
// histograms and two multiset hashes (primal cells, dual hexes), every item keyed by
// exact lattice positions only, never by ids. So the serial `install` of a whole grid and
// the distributed install (each rank summarising the cells of its own leaves and the
// vertices it owns, then summing) give the same summary iff they built the same mesh,
// whatever the partition.
//
// Multiset hash: the sum mod 2^64 of each item's 64-bit hash (splitmix64 chain over its
// integer words), so partial sums from any number of ranks add up to the serial value.
// Not cryptographic; a test detector of any difference, not a proof of equality.
//
// This file and its library (`dualhex::canonical`) are part of the MIT-licensed core:
// they do not use p4est (distributed/README.md).
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "dualhex/install/install.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

struct CanonicalSummary {
    std::uint64_t leaves = 0, cells = 0, non_hex_cells = 0, vertices = 0, hexes = 0, non_cube_vertices = 0;
    std::map<int, std::uint64_t> face_sizes;             ///< each face once
    std::map<std::string, std::uint64_t> elements;       ///< leaves per element ("hex": plain)
    std::uint64_t cell_hash = 0;  ///< multiset hash of the cells (faces as lattice point sets)
    std::uint64_t hex_hash = 0;   ///< multiset hash of the hexes (primal vertex + 8 dual vertices, rotation-canonical)

    void add(const CanonicalSummary& other);
    bool operator==(const CanonicalSummary&) const = default;
};

/// Which part of `installed` this summary covers: the cells of leaves [leaf_begin,
/// leaf_end) and the vertices, faces (by their smallest vertex) and hexes (by their primal
/// vertex) for which owns(v) holds. The serial summary owns everything.
struct SummaryScope {
    std::size_t leaf_begin = 0, leaf_end = 0;
    std::function<bool(VertexHandle)> owns;
};

[[nodiscard]] CanonicalSummary summarize(const InstallResult& installed, const Incidence& incidence,
                                         const ClippedDual& dual, const SummaryScope& scope);
/// The whole complex (serial install): every leaf and vertex owned.
[[nodiscard]] CanonicalSummary summarize(const InstallResult& installed, const Incidence& incidence,
                                         const ClippedDual& dual);

/// The splitmix64 finaliser both hashes are built from (exposed for tests).
[[nodiscard]] std::uint64_t mix64(std::uint64_t v);

}  // namespace dualhex
