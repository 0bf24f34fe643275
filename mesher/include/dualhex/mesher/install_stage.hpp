#pragma once
// Stages "install", "verify" and "dual" of the mesher: the schemes placed into the graded
// grid, the installation's post-check, and the clipped dual over the whole root cube.
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"
#include "dualhex/install.hpp"
#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex::mesher {

/// Input: a paired grid with `balance`. Output: the default element library installed
/// with the weak rule (Balance::Weak) or the strong rule, root boundary Coarse.
/// Throws InstallError if the grid is not installable.
[[nodiscard]] InstallResult install_schemes(const LeafGrid& grid, Balance balance);

/// verify_installation(installed); throws std::runtime_error with its summary if it fails
/// (a bug, never bad input: the grid was checked by install).
[[nodiscard]] InstallVerification require_verified(const InstallResult& installed);

/// The lattice extent of the root cube: unit << max_level.
[[nodiscard]] std::int64_t root_extent(const InstallResult& installed);

/// The clipped dual of the installed complex over [0, root_extent]^3: one hex per primal
/// vertex. Throws std::runtime_error if a dual cell is not a cube (a bug).
[[nodiscard]] ClippedDual root_clipped_dual(const InstallResult& installed);

}  // namespace dualhex::mesher
