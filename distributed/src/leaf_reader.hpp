#pragma once
// The distributed leaf-file reader: no rank reads the whole file. Rank r parses the
// lines that start in its byte range [r S / np, (r+1) S / np) of the file (S bytes),
// numbering them from the lines before it (an MPI_Exscan of line counts), so every error
// is located (file:line) whichever rank finds it. The leaves are then sorted over the
// ranks by Morton position (a sample sort: np regular samples per rank, np - 1
// splitters, one MPI_Alltoallv), so each rank holds one contiguous run of the curve, and
// the tiling is checked on the sorted run (consecutive leaves must abut: an overlap is a
// later leaf starting inside an earlier one, a gap a position no leaf starts at) with
// the neighbouring ranks' first and last leaves. Errors are agreed on over the ranks
// (first_error.hpp) and thrown on every rank as InputError, in DESIGN.md's words
// (grid/leaf_file.hpp), though for a file with several faults perhaps not the same
// fault the serial reader names first.
#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dualhex::dist {

/// A parsed leaf with its line: 16 bytes on the wire.
struct SortedLeaf {
    std::uint64_t position = 0;  ///< morton_position
    std::int32_t line = 0;
    std::int32_t level = 0;
};

struct DistributedLeaves {
    std::string source;
    std::vector<SortedLeaf> leaves;  ///< this rank's run of the curve, sorted by position
    std::int64_t global_count = 0;
    int min_level = 0, max_level = 0;  ///< over all ranks
    std::uint64_t bytes_read = 0;      ///< by this rank (its range, plus the ends of its lines)
    std::uint64_t lines_parsed = 0, leaves_parsed = 0;  ///< by this rank, before the sort
    std::uint64_t bytes_sorted_out = 0;  ///< sent by this rank to the others in the sort
};

/// Collective. Throws InputError on every rank for a missing or unreadable file, a bad
/// line, a level beyond p8est's 18, or leaves that do not tile the root cube.
[[nodiscard]] DistributedLeaves read_leaves_distributed(MPI_Comm comm, const std::filesystem::path& path);

}  // namespace dualhex::dist
