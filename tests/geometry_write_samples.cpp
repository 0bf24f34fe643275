// Test helper for geometry_meshio_readback: writes, into the directory given as argv[1],
//   cube.{vtk,vtu,mesh}   the unit cube as one hex (8 points)
//   block.{vtk,vtu,mesh}  a 3x2x2 block of hexes (12 hexes, 36 points), sheared, with cell
//                         data: level h % 3, scaled_jacobian 1 - h / 100 (hex h)
//   complex.vtk           a 2x2x2 box of leaves as a polyhedral complex (27 points, 8 cells)
//   complex_faces.vtk     its 36 faces as polygons (24 on the boundary)
// Exit 0 on success, 1 with a message otherwise.
#include <filesystem>
#include <iostream>

#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/grid/grid_complex.hpp"

using namespace dualhex;
using namespace dualhex::geometry;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: geometry_write_samples DIR\n";
        return 1;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        HexMesh cube;
        for (int v : {0, 1, 3, 2, 4, 5, 7, 6}) cube.points.emplace_back(v & 1, (v >> 1) & 1, (v >> 2) & 1);
        cube.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
        HexMesh block;
        const int nx = 3, ny = 2, nz = 2;
        auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
        for (int k = 0; k <= nz; ++k)
            for (int j = 0; j <= ny; ++j)
                for (int i = 0; i <= nx; ++i) block.points.emplace_back(i + 0.1 * k, j, k);
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                    block.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                           id(i, j + 1, k + 1)});
        HexCellData block_data;
        for (std::size_t h = 0; h < block.hexes.size(); ++h) {
            block_data.level.push_back(static_cast<int>(h % 3));
            block_data.scaled_jacobian.push_back(1.0 - static_cast<double>(h) / 100.0);
        }
        for (const char* ext : {".vtk", ".vtu", ".mesh"}) {
            write_hex_mesh((dir / (std::string("cube") + ext)).string(), cube, true);
            write_hex_mesh((dir / (std::string("block") + ext)).string(), block, true, block_data);
        }
        const CellComplex box = leaves_to_complex(leaf_box(1, {0, 0, 0}, {2, 2, 2}));
        write_complex_vtk((dir / "complex.vtk").string(), box, {}, true);
        write_complex_faces_vtk((dir / "complex_faces.vtk").string(), box, {}, true);
    } catch (const std::exception& e) {
        std::cerr << "geometry_write_samples: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
