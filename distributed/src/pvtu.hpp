#pragma once
// Parallel VTK output: each rank writes PREFIX_<rank>.vtu (its hexes, ASCII XML
// UnstructuredGrid, cell data `rank` and `vertex_id`, the global id of the primal vertex
// each hex is dual to) and rank 0 writes PREFIX.pvtu, the index ParaView opens.
#include <cstdint>
#include <string>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::dist {

/// PREFIX_<rank>.vtu (the file name a .pvtu refers to is its basename).
[[nodiscard]] std::string piece_path(const std::string& prefix, int rank);

void write_piece(const std::string& path, const geometry::HexMesh& mesh, int rank, const std::vector<std::uint64_t>& vertex_id);

/// The index over `ranks` pieces.
void write_pvtu(const std::string& prefix, int ranks);

}  // namespace dualhex::dist
