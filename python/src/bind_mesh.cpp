// dualhex.mesh(surface=None, **options): the `dualhex mesh` pipeline on a surface file, a
// (V, F) pair of arrays, or (None) the embedded torus; returns the hex mesh as arrays and
// the report. Options: mesh_options.cpp.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include "bindings.hpp"
#include "convert.hpp"
#include "leaf_input.hpp"
#include "mesh_options.hpp"

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/mesher/default_shape.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"

namespace dualhex::python {
namespace {

const std::string kArraysSource = "<(V, F) arrays>";

// (V, F): V an (N, 3) float array, F an (M, 3) integer array of vertex ids.
geometry::TriangleSurface surface_from_arrays(const py::handle& pair) {
    const py::tuple vf = py::reinterpret_borrow<py::object>(pair).cast<py::tuple>();
    if (vf.size() != 2) throw py::value_error("surface: expected (V, F), got a tuple of " + std::to_string(vf.size()));
    const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vf[0]);
    const py::array f_raw = py::array::ensure(vf[1]);
    if (!v || v.ndim() != 2 || v.shape(1) != 3) throw py::value_error("surface: V must be an (N, 3) float array");
    if (!f_raw || f_raw.ndim() != 2 || f_raw.shape(1) != 3 || (f_raw.size() > 0 && f_raw.dtype().kind() != 'i' &&
                                                               f_raw.dtype().kind() != 'u'))
        throw py::value_error("surface: F must be an (M, 3) integer array of vertex ids");
    const auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(f_raw);
    geometry::TriangleSurface s;
    s.source = kArraysSource;
    const auto vr = v.unchecked<2>();
    for (py::ssize_t i = 0; i < vr.shape(0); ++i) {
        if (!std::isfinite(vr(i, 0)) || !std::isfinite(vr(i, 1)) || !std::isfinite(vr(i, 2)))
            throw geometry::SurfaceError(kArraysSource, "vertex " + std::to_string(i) + " is not finite");
        s.vertices.emplace_back(vr(i, 0), vr(i, 1), vr(i, 2));
    }
    const auto fr = f.unchecked<2>();
    for (py::ssize_t t = 0; t < fr.shape(0); ++t) {
        std::array<int, 3> tri{};
        for (int c = 0; c < 3; ++c) {
            const std::int64_t id = fr(t, c);
            if (id < 0 || id >= static_cast<std::int64_t>(s.vertices.size()))
                throw geometry::SurfaceError(kArraysSource, "triangle " + std::to_string(t) + ": vertex id " +
                                                                std::to_string(id) + " out of range [0, " +
                                                                std::to_string(s.vertices.size()) + ")");
            tri[static_cast<std::size_t>(c)] = static_cast<int>(id);
        }
        s.triangles.push_back(tri);
    }
    return s;
}

struct SurfaceInput {
    std::string path;                  // a file to read, or
    geometry::TriangleSurface surface;  // arrays (source set), or the default torus (source empty)
    bool from_arrays = false;
    [[nodiscard]] std::string name() const {
        return !path.empty() ? path : from_arrays ? kArraysSource : std::string("<default torus>");
    }
};

SurfaceInput surface_input(const py::handle& surface) {
    SurfaceInput in;
    if (surface.is_none()) return in;
    if (as_path(surface, in.path)) return in;
    if (py::isinstance<py::tuple>(surface) || py::isinstance<py::list>(surface)) {
        in.surface = surface_from_arrays(py::tuple(py::reinterpret_borrow<py::object>(surface)));
        in.from_arrays = true;
        return in;
    }
    throw py::type_error("surface: expected None, a path, or (V, F) arrays, got " + std::string(py::str(py::type::of(surface))));
}

struct Meshed {
    std::size_t triangles = 0;
    geometry::SurfaceReport surface;
    mesher::MeshPipelineResult result;
    std::vector<double> quality;
};

// Runs without the GIL.
Meshed run_mesh(SurfaceInput in, const mesher::MeshPipelineOptions& options) {
    Meshed out;
    geometry::TriangleSurface s = !in.path.empty() ? geometry::read_surface(in.path, {}, &out.surface)
                                  : in.from_arrays ? geometry::clean_surface(std::move(in.surface), {}, &out.surface)
                                                   : mesher::default_shape();
    out.triangles = s.triangles.size();
    const geometry::AabbTree tree(std::move(s));
    out.result = mesher::mesh_surface(tree, options);
    out.quality = geometry::scaled_jacobians(out.result.mesh);
    return out;
}

py::dict report(const Meshed& m, const std::string& name, const mesher::MeshPipelineOptions& options) {
    const auto& r = m.result;
    const auto& q = r.quality;
    py::dict d;
    d["input"] = name;
    d["options"] = mesh_options_dict(options);
    d["warnings"] = m.surface.warnings;
    d["triangles"] = m.triangles;
    d["leaves"] = r.leaves;
    d["cells"] = r.cells;
    d["dual_hexes"] = r.dual_hexes;
    d["hexes"] = r.mesh.hexes.size();
    d["vertices"] = r.mesh.points.size();
    d["boundary_vertices"] = r.boundary_vertices;
    d["core_hexes"] = r.core_hexes;
    d["pad_hexes"] = r.pad_hexes;
    d["inverted_after_pad"] = r.inverted_after_pad;
    d["smooth_iterations"] = r.smooth_iterations_done;
    py::dict topo;
    topo["manifold"] = r.topology.manifold;
    topo["matches"] = r.topology.matches;
    topo["euler"] = r.topology.euler;
    topo["input_euler"] = r.topology.input_euler;
    topo["problems"] = r.topology.problems;
    d["topology"] = topo;
    d["inverted_hexes"] = r.inverted_hexes;  // ids of hexes with SJ <= the flat threshold: the check fails
    py::dict dist;
    dist["mean"] = r.distance.relative(r.distance.mean());
    dist["max"] = r.distance.relative(r.distance.max());
    dist["on_surface"] = r.distance.share_vertices_on_surface;
    d["surface_distance"] = dist;
    py::dict sj;
    sj["min"] = q.min;
    sj["mean"] = q.mean;
    sj["below_0"] = q.share_negative;
    sj["below_0_2"] = q.share_below_02;
    d["scaled_jacobian"] = sj;
    d["singular_edge_valences"] = histogram_dict(r.singular_edge_valences);
    d["dual_edge_valences"] = histogram_dict(r.dual_edge_valences);
    d["hausdorff"] = r.hausdorff.max;
    d["hausdorff_mean"] = r.hausdorff.mean;
    const auto& t = r.ms;
    d["ms"] = std::map<std::string, double>{
        {"octree", t.octree}, {"balance", t.balance}, {"pair", t.pair},       {"balance_pair", t.balance_pair},
        {"install", t.install}, {"verify", t.verify}, {"dual", t.dual},       {"core", t.core},
        {"pad", t.pad},         {"features", t.features}, {"smooth", t.smooth}, {"optimise", t.optimise},
        {"check", t.check},     {"report", t.report}};
    return d;
}

py::dict mesh_py(const py::object& surface, const py::kwargs& kwargs) {
    mesher::MeshPipelineOptions options;
    apply_mesh_options(kwargs, options);
    SurfaceInput in = surface_input(surface);
    const std::string name = in.name();
    Meshed m;
    {
        py::gil_scoped_release release;
        m = run_mesh(std::move(in), options);
    }
    if (!m.surface.warnings.empty()) {  // as the CLI prints them: once, each naming its file
        const py::object warn = py::module_::import("warnings").attr("warn");
        for (const auto& w : m.surface.warnings) warn(w, py::module_::import("builtins").attr("UserWarning"), 2);
    }
    return mesh_dict(m.result.mesh, m.quality, nullptr, report(m, name, options));
}

}  // namespace

void bind_mesh(py::module_& m) {
    m.def("_mesh", &mesh_py, py::arg("surface") = py::none(),
          "Meshes a closed triangle surface (a file path, (V, F) arrays, or None for the embedded torus) with "
          "hexahedra; keyword options as in dualhex.mesh_option_names(); returns the dict dualhex.Mesh is made of.");
    m.def("mesh_option_names", &mesh_option_names, "The keyword options dualhex.mesh() accepts.");
    m.def("mesh_defaults", [] { return mesh_options_dict({}); }, "The default values of dualhex.mesh()'s options.");
}

}  // namespace dualhex::python
