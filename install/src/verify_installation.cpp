// verify_installation(): the checks of an installed grid (verify_installation.hpp).
#include "dualhex/install/verify_installation.hpp"

#include "dualhex/install/open_faces.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

std::string InstallVerification::summary() const {
    std::string out = ok() ? "ok" : "FAIL";
    out += ": " + std::to_string(validation.violations.size()) + " violations, " + std::to_string(open_faces) +
           " open faces, " + std::to_string(hexes) + "/" + std::to_string(interior_vertices) + " interior vertices with a cube dual";
    for (std::size_t k = 0; k < kViolationKinds; ++k)
        if (validation.per_kind[k] > 0)
            out += std::string(", ") + to_string(static_cast<ViolationKind>(k)) + " " + std::to_string(validation.per_kind[k]);
    return out;
}

InstallVerification verify_installation(const InstallResult& installed, const Progress& progress) {
    InstallVerification v;
    const CellComplex& cx = installed.complex;
    const std::int64_t extent = installed.unit << installed.max_level;
    report_progress(progress, "validate", 0, kVerifySteps);
    v.validation = validate(cx);
    const Incidence inc(cx);
    const auto inside = [extent](const LatticePoint& p) {
        for (int a = 0; a < 3; ++a)
            if (p[a] <= 0 || p[a] >= extent) return false;
        return true;
    };
    const auto on_surface = [extent](const CellComplex& c, std::span<const VertexHandle> loop) {
        for (int a = 0; a < 3; ++a)
            for (std::int64_t side : {std::int64_t{0}, extent}) {
                bool all = true;
                for (VertexHandle w : loop) all = all && c.position(w)[a] == side;
                if (all) return true;
            }
        return false;
    };
    report_progress(progress, "open faces", 1, kVerifySteps);
    v.open_faces = detail::check_open_faces(cx, inc, inside, on_surface, v.validation);
    report_progress(progress, "interior dual", 2, kVerifySteps);
    const DualResult dual = interior_dual(cx, inc);
    v.hexes = dual.mesh.hexes.size();
    v.interior_vertices = v.hexes + dual.errors.size();
    report_progress(progress, "valences", 3, kVerifySteps);
    v.face_sizes = face_size_histogram(cx);
    v.dual_edge_valences = interior_dual_edge_valence_histogram(cx, inc);
    return v;
}

}  // namespace dualhex
