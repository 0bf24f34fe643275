// Agreeing on one input error over the ranks (first_error.hpp).
#include "first_error.hpp"

#include <climits>
#include <string>

namespace dualhex::dist {

void throw_first_error(MPI_Comm comm, const std::optional<InputError>& mine) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    struct {
        long key;
        int rank;
    } in{LONG_MAX, rank}, out{};
    if (mine) in.key = mine->line() > 0 ? mine->line() : LONG_MAX - 1;  // located errors first
    MPI_Allreduce(&in, &out, 1, MPI_LONG_INT, MPI_MINLOC, comm);
    if (out.key == LONG_MAX) return;
    std::string file, message;
    int line = 0;
    if (rank == out.rank) file = mine->file(), message = mine->message(), line = mine->line();
    auto bcast = [&](std::string& s) {
        int n = static_cast<int>(s.size());
        MPI_Bcast(&n, 1, MPI_INT, out.rank, comm);
        s.resize(static_cast<std::size_t>(n));
        MPI_Bcast(s.data(), n, MPI_CHAR, out.rank, comm);
    };
    bcast(file);
    bcast(message);
    MPI_Bcast(&line, 1, MPI_INT, out.rank, comm);
    throw InputError(file, line, message);
}

}  // namespace dualhex::dist
