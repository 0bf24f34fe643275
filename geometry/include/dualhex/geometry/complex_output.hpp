#pragma once
// Writing a polyhedral CellComplex (e.g. the installed schemes before dualisation) as a
// VTK legacy file (ASCII, version 4.2) with one VTK_POLYHEDRON (42) cell per complex
// cell: its faces listed with their outward loops. Lattice positions become doubles
// through a LatticeEmbedding (origin + scale * lattice point). write_complex_faces_vtk
// writes the faces only, as polygons, for readers without VTK_POLYHEDRON.
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

/// The faces of the complex as VTK_POLYGON (7) cells (legacy ASCII), each face loop as
/// stored; cell data "cells" = number of complex cells on the face (1 = boundary).
/// Readable by tools without polyhedron support (meshio, gmsh's VTK reader).
void write_complex_faces_vtk(const std::string& path, const CellComplex& complex, const LatticeEmbedding& embed = {},
                             bool overwrite = false);

}  // namespace dualhex::geometry
