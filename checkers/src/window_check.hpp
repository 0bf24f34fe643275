#pragma once
// Internal: checking a built configuration complex (validation with an interior filter,
// open faces, the dual, histograms) and the cube-window variant of it. Shared by the
// configuration checks and the compositional windows.
#include <span>

#include "dualhex/install/element_templates.hpp"
#include "dualhex/install/open_faces.hpp"
#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex::detail {

// `accept(p)`: the vertex at p gets the interior checks; `on_domain_boundary(p)`: p lies
// on the domain's boundary (a boundary face all of whose points do is expected).
template <class Filter, class OnBoundary>
ConfigurationReport analyse(ConfigurationComplex built, Filter&& accept, OnBoundary&& on_domain_boundary) {
    ConfigurationReport r;
    r.mask = built.mask;
    r.built = true;
    const CellComplex& cx = built.complex;
    ValidationOptions options;
    options.interior_filter = [&](VertexHandle v) { return accept(cx.position(v)); };
    r.validation = validate(cx, options);
    r.vertices = cx.n_vertices();
    r.edges = cx.n_edges();
    r.faces = cx.n_faces();
    r.cells = cx.n_cells();
    const Incidence inc(cx);
    for (std::size_t v = 0; v < cx.n_vertices(); ++v)
        if (!inc.is_boundary(VertexHandle(v)) && accept(cx.position(VertexHandle(v)))) ++r.checked_vertices;
    r.open_faces = detail::check_open_faces(cx, inc, accept, on_domain_boundary, r.validation);
    const DualResult dual = interior_dual(cx, inc);
    for (VertexHandle v : dual.mesh.primal_vertex)
        if (accept(cx.position(v))) ++r.hexes;
    r.face_sizes = face_size_histogram(cx);
    r.dual_edge_valences = interior_dual_edge_valence_histogram(cx, inc);
    for (const PlacedLeaf& leaf : built.coarse_leaves) ++r.elements[leaf.placement ? leaf.placement->element : "hex"];
    if (built.fine_hexes) r.elements["fine"] = built.fine_hexes;
    return r;
}

template <class Build, class Filter, class OnBoundary>
ConfigurationReport check(std::uint8_t mask, Build&& build, Filter&& accept, OnBoundary&& on_boundary) {
    try {
        return analyse(build(), accept, on_boundary);
    } catch (const std::exception& e) {
        ConfigurationReport r;
        r.mask = mask;
        r.error = e.what();
        return r;
    }
}


// The window [-half, half]^3: vertices strictly inside get the interior checks; a boundary
// face is expected iff all its points lie in one plane of the window's surface.
template <class Build>
ConfigurationReport check_window(std::uint8_t mask, std::int64_t half, Build&& build) {
    const auto inside = [half](const LatticePoint& p) {
        return -half < p.x && p.x < half && -half < p.y && p.y < half && -half < p.z && p.z < half;
    };
    const auto on_surface = [half](const CellComplex& cx, std::span<const VertexHandle> loop) {
        for (int a = 0; a < 3; ++a)
            for (std::int64_t side : {-half, half}) {
                bool all = true;
                for (VertexHandle v : loop) all = all && cx.position(v)[a] == side;
                if (all) return true;
            }
        return false;
    };
    return check(mask, build, inside, on_surface);
}

}  // namespace dualhex::detail
