// The features stage's refusal of snaps that invert hexes (feature_refusal.hpp): a small
// repair by the optimiser, then undoing the curves and corners it could not repair.
#include "dualhex/mesher/feature_refusal.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/optimise.hpp"

namespace dualhex::mesher {
namespace {

// Hexes inverted now that were not inverted before the snap, in id order.
std::vector<std::size_t> inverted_by_snap(const QualityState& state, const std::vector<double>& sj_before) {
    std::vector<std::size_t> out;
    for (std::size_t h = 0; h < sj_before.size(); ++h)
        if (!(state.scaled_jacobian[h] > 0) && sj_before[h] > 0) out.push_back(h);
    return out;
}

class Undo {
public:
    Undo(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before, VertexConstraints& c,
         FeatureSnapReport& report)
        : mesh_(mesh), before_(before), c_(c), report_(report) {}

    // Gives up what the snap did on hex h: its corner and curve vertices become surface
    // vertices where they were (only these: the rest of a curve stays a crease); a hex
    // without snapped vertices has its moved vertices put back. Returns the points put back.
    std::size_t hex(std::size_t h) {
        std::size_t restored = 0;
        bool snapped = false;
        for (int v : mesh_.hexes[h]) {
            const auto u = static_cast<std::size_t>(v);
            if (c_.role[u] != VertexRole::Curve && c_.role[u] != VertexRole::Corner) continue;
            snapped = true;
            (c_.role[u] == VertexRole::Corner ? report_.corners_undone : report_.curve_vertices_undone) += 1;
            restored += release(u);
            std::erase_if(report_.path_edges, [v](const PathEdge& e) { return e.from == v || e.to == v; });
        }
        if (!snapped)  // moved by the snap's neighbours (patch projection, repair)
            for (int v : mesh_.hexes[h]) restored += put_back(static_cast<std::size_t>(v));
        return restored;
    }

private:
    geometry::HexMesh& mesh_;
    const std::vector<Eigen::Vector3d>& before_;
    VertexConstraints& c_;
    FeatureSnapReport& report_;

    std::size_t put_back(std::size_t v) {
        if (mesh_.points[v] == before_[v]) return 0;
        mesh_.points[v] = before_[v];
        return 1;
    }
    std::size_t release(std::size_t v) {
        if (c_.role[v] == VertexRole::Curve) --report_.curve_vertices;
        c_.role[v] = VertexRole::Surface;  // before the snap every snapped vertex was a surface vertex
        c_.curve[v] = -1;
        return put_back(v);
    }
};

}  // namespace

void refuse_inverting_snaps(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before,
                            const std::vector<double>& sj_before, VertexConstraints& constraints,
                            FeatureSnapReport& report, const geometry::AabbTree& tree, const FeatureCurves& curves,
                            QualityState& state, const FeatureRefusalOptions& options) {
    if (before.size() != mesh.points.size() || sj_before.size() != mesh.hexes.size())
        throw std::invalid_argument("feature refusal: " + std::to_string(before.size()) + " points and " +
                                    std::to_string(sj_before.size()) + " hex qualities for a mesh of " +
                                    std::to_string(mesh.points.size()) + " and " + std::to_string(mesh.hexes.size()));
    std::vector<std::size_t> bad = inverted_by_snap(state, sj_before);
    report.inverted_by_snap = bad.size();
    if (bad.empty()) return;
    if (options.repair_work_per_vertex > 0) {
        OptimiseOptions repair;
        repair.min_quality = 1e-3;  // untangle only: raising quality is the optimise stage's job
        repair.bad_below = 0;       // inverted hexes only: flat ones too are the optimise stage's
        repair.work_per_vertex = options.repair_work_per_vertex;
        (void)optimise_region(mesh, bad, options.repair_rings, constraints, tree, curves, repair);
        state = quality_state(mesh);
    }
    bad = inverted_by_snap(state, sj_before);
    report.repaired = report.inverted_by_snap - std::min(bad.size(), report.inverted_by_snap);
    Undo undo(mesh, before, constraints, report);
    while (!bad.empty()) {
        for (std::size_t h : bad)  // skip a hex an earlier undo of this round already fixed
            if (!(geometry::scaled_jacobian(mesh, h) > 0)) report.vertices_restored += undo.hex(h);
        state = quality_state(mesh);
        bad = inverted_by_snap(state, sj_before);
    }
}

}  // namespace dualhex::mesher
