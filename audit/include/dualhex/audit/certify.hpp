#pragma once
// `dualhex audit --certify`: the audited mesh as an explicit complex with exact integer
// coordinates, for a certificate the standalone checker (proofs/checker) re-checks.
//
// Coordinates must be dyadic: x * 2^K an integer for one K in [0, 64] (dualhex's writers
// write lattice points times 1/2^depth, which is exact in binary). The smallest such K is
// used; every scaled coordinate must satisfy |x| <= 2^19, and the bounding box an extent
// <= 2^19 on each axis (the checker's bounds), and the
// points used by cells must be pairwise distinct (the checker requires distinct
// positions). Otherwise the certificate is refused with the reason.
#include <cstdint>
#include <optional>
#include <string>

#include "dualhex/audit/mesh_file.hpp"
#include "dualhex/topology/cell_complex.hpp"

namespace dualhex::audit {

inline constexpr std::int64_t kCertificateCoordinateBound = std::int64_t{1} << 19;

struct CertificateComplex {
    CellComplex complex;  ///< vertices = the points used by cells, at x * 2^scale_exponent
    int scale_exponent = 0;
    LatticePoint lo, hi;  ///< bounding box of the scaled points
};

/// The complex, or std::nullopt with `refusal` set to the reason.
[[nodiscard]] std::optional<CertificateComplex> certificate_complex(const MeshFile& mesh, std::string& refusal);

}  // namespace dualhex::audit
