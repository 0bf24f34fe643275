// Uses the installed dualhex::topology: applies a cube symmetry to a lattice point.
#include <dualhex/topology/cube_symmetry.hpp>

#include <iostream>

int main() {
    int rotations = 0;
    for (int i = 0; i < dualhex::CubeSymmetry::kOrder; ++i)
        if (dualhex::CubeSymmetry::from_index(i).is_rotation()) ++rotations;
    // (x,y,z) -> (-y,x,z): a quarter turn about z.
    const dualhex::CubeSymmetry quarter_turn({1, 0, 2}, {-1, 1, 1});
    const dualhex::LatticePoint p = quarter_turn.apply({1, 2, 3});
    std::cout << "rotations " << rotations << ", image " << p << ' ' << quarter_turn.to_string() << '\n';
    const bool ok = rotations == 24 && quarter_turn.is_rotation() &&
                    quarter_turn.inverse().apply(p) == dualhex::LatticePoint{1, 2, 3};
    std::cout << (ok ? "consumer OK" : "consumer FAILED") << '\n';
    return ok ? 0 : 1;
}
