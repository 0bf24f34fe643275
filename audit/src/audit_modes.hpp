#pragma once
// The two audits behind audit_mesh (audit.hpp), and the complex they share with --certify.
#include <optional>
#include <string>
#include <vector>

#include "dualhex/audit/audit.hpp"
#include "dualhex/topology/cell_complex.hpp"

namespace dualhex::audit::detail {

void audit_hex(const MeshFile& mesh, const AuditOptions& options, AuditReport& report);
void audit_polyhedral(const MeshFile& mesh, const AuditOptions& options, AuditReport& report);

/// The outward faces (loops of file point ids) of a volume cell: a polyhedron's face stream
/// as written, the VTK faces of a tetra / hexahedron / wedge / pyramid.
[[nodiscard]] std::vector<std::vector<std::int64_t>> cell_faces(const MeshCell& cell);

/// The volume cells as a CellComplex on the points they use: vertex k is file point
/// `file_point[k]`, cell c is mesh.cells[c]. Positions: `positions` (one per file point) or
/// (k, 0, 0) if empty. Faces are welded by their cyclic sequence of point ids.
struct MeshComplex {
    CellComplex complex;
    std::vector<std::int64_t> file_point;
};
[[nodiscard]] MeshComplex build_complex(const MeshFile& mesh, const std::vector<LatticePoint>& positions = {});

}  // namespace dualhex::audit::detail
