#pragma once
// One input error for all ranks: each rank may have found its own (in its byte range of
// the file, or at a boundary of its sorted leaves); every rank gets the one with the
// smallest line (located errors before file-level ones, line 0), from the lowest rank
// among equals, so the message is the same for any number of ranks that see it.
#include <mpi.h>

#include <optional>

#include "dualhex/grid/input_error.hpp"

namespace dualhex::dist {

/// Collective. Throws the agreed InputError on every rank if any rank had one.
void throw_first_error(MPI_Comm comm, const std::optional<InputError>& mine);

}  // namespace dualhex::dist
