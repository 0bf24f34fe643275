#pragma once
// Writing a polyhedral CellComplex (e.g. the installed schemes before dualisation) as a
// VTK legacy file (ASCII, version 4.2) with one VTK_POLYHEDRON (42) cell per complex
// cell: its faces listed with their outward loops. Lattice positions become doubles
// through a LatticeEmbedding (origin + scale * lattice point).
//
// Throws std::runtime_error if the file exists and !overwrite, or cannot be written.
#include <string>

#include <Eigen/Core>

#include "dualhex/topology/cell_complex.hpp"

namespace dualhex::geometry {

struct LatticeEmbedding {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    double scale = 1.0;
    [[nodiscard]] Eigen::Vector3d operator()(const LatticePoint& p) const {
        return origin + scale * Eigen::Vector3d(double(p.x), double(p.y), double(p.z));
    }
};

/// Cell data: "faces" (number of faces per cell). Readable by ParaView / VTK >= 8.
void write_complex_vtk(const std::string& path, const CellComplex& complex, const LatticeEmbedding& embed = {},
                       bool overwrite = false);

}  // namespace dualhex::geometry
