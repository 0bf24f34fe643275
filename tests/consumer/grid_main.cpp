// Uses the installed dualhex::grid (and through it dualhex::topology): parses a leaf file
// from text, balances nothing, turns the uniform grid into a complex and validates it.
#include <dualhex/grid/grid_complex.hpp>
#include <dualhex/grid/leaf_file.hpp>
#include <dualhex/topology/validation.hpp>

#include <iostream>

int main() {
    const dualhex::LeafGrid grid = dualhex::parse_leaves(
        "# the root cube split once\n1 0 0 0\n1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n1 1 1 1\n",
        "<consumer>");
    const dualhex::CellComplex complex = dualhex::box_to_complex(grid);
    const bool ok = grid.size() == 8 && complex.n_cells() == 8 && complex.n_vertices() == 27 &&
                    dualhex::validate(complex).ok();
    std::cout << (ok ? "consumer (grid) OK" : "consumer (grid) FAILED") << '\n';
    return ok ? 0 : 1;
}
