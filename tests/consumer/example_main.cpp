// The README's library example (kept compiling and running by the consumer test): install
// the schemes into a leaf file's grid and write the hex mesh (the clipped dual) as VTK.
#include <dualhex/geometry/hex_output.hpp>
#include <dualhex/grid/leaf_file.hpp>
#include <dualhex/install.hpp>
#include <dualhex/schemes/weak_rule.hpp>
#include <dualhex/topology/clipped_dual.hpp>
#include <dualhex/topology/incidence.hpp>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: example GRID.leaves OUT.vtk\n";
        return 2;
    }
    try {
        const dualhex::LeafGrid grid = dualhex::read_leaf_file(argv[1]);  // InputError: file:line: ...
        const auto library = dualhex::load_default_element_library();      // the shipped elements
        const dualhex::InstallResult installed = dualhex::install(grid, dualhex::WeakRule(), *library);
        if (!dualhex::verify_installation(installed).ok()) return 1;

        const std::int64_t n = installed.unit << installed.max_level;  // the root cube is [0, n]^3
        const dualhex::ClippedDual dual =
            dualhex::clipped_dual(installed.complex, dualhex::Incidence(installed.complex), {0, 0, 0}, {n, n, n});
        dualhex::geometry::HexMesh mesh;
        for (const dualhex::RationalPoint& p : dual.points)
            mesh.points.emplace_back(p.coordinate(0, n), p.coordinate(1, n), p.coordinate(2, n));
        for (const auto& h : dual.hexes) mesh.hexes.push_back({int(h[0]), int(h[1]), int(h[2]), int(h[3]),
                                                               int(h[4]), int(h[5]), int(h[6]), int(h[7])});
        dualhex::geometry::write_vtk_legacy(argv[2], mesh, /*overwrite=*/true);
        std::cout << grid.size() << " leaves -> " << mesh.hexes.size() << " hexes in " << argv[2] << '\n';
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 3;
    }
}
