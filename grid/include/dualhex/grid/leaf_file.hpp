#pragma once
// Leaf files (.leaves), DESIGN.md section 8, exactly: one leaf per line "L i j k"
// (decimal integers separated by spaces/tabs); '#' starts a comment, also after a leaf;
// blank lines are allowed. The leaves must tile the root cube exactly.
//
// Errors are InputError with file and 1-based line, and the message names the entity:
//   "f.leaves:7: expected 4 fields 'L i j k', found 5 in '3 1 2 0 9'"
//   "f.leaves:7: not an integer: 'x' in '3 x 2 0'"
//   "f.leaves:7: invalid leaf 3 8 0 0: coordinates must be in [0, 2^3)"
//   "f.leaves:9: duplicate leaf 3 1 2 0 (line 9), first given as 3 1 2 0 (line 4)"
//   "f.leaves:9: overlap: leaf 3 1 1 1 (line 9) lies inside leaf 2 0 0 0 (line 3)"
//   "f.leaves: gap: cell 2 1 0 3 (level 2) is not covered by any leaf"
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "dualhex/grid/leaf_grid.hpp"

namespace dualhex {

/// Reads and validates a leaf file. Throws InputError (also if it cannot be read).
[[nodiscard]] LeafGrid read_leaf_file(const std::filesystem::path& path);
/// One raw line of a leaf file (no '\n'): its leaf, or nothing for a blank or comment line.
/// Throws InputError(source, line, ...) as the file reader does. For readers of a part of
/// a file (the distributed mesher reads a byte range per rank).
[[nodiscard]] std::optional<Leaf> parse_leaf_line(std::string_view raw, const std::string& source, int line);
/// Parses leaf-file text; `source` names it in diagnostics.
[[nodiscard]] LeafGrid parse_leaves(std::string_view text, const std::string& source = {});

/// The grid as leaf-file text, leaves in stored order. Each line of `header` (if any)
/// is written first as a '#' comment.
[[nodiscard]] std::string format_leaves(const LeafGrid& grid, std::string_view header = {});
/// Writes format_leaves(grid, header) to `path`. Throws InputError if it cannot write.
void write_leaf_file(const LeafGrid& grid, const std::filesystem::path& path, std::string_view header = {});

}  // namespace dualhex
