// dualhex.install(leaves, balance="weak", outside_root="coarse"): what `dualhex install`
// does, returning arrays instead of writing files: the clipped dual hex mesh (points,
// hexes in VTK order), per hex its scaled Jacobian and level, and the report.
#include <pybind11/stl.h>

#include <chrono>
#include <stdexcept>

#include "bindings.hpp"
#include "convert.hpp"
#include "leaf_input.hpp"

#include "dualhex/geometry/quality.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/install.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex::python {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

Balance parse_balance(const std::string& s) {
    if (s == "weak") return Balance::Weak;
    if (s == "strong") return Balance::Strong;
    throw std::invalid_argument("balance must be 'weak' or 'strong', got '" + s + "'");
}

OutsideRoot parse_outside(const std::string& s) {
    if (s == "coarse") return OutsideRoot::Coarse;
    if (s == "mirror") return OutsideRoot::Mirror;
    throw std::invalid_argument("outside_root must be 'coarse' or 'mirror', got '" + s + "'");
}

// A hex is dual to a primal vertex; its level is that of the finest leaf among the cells
// around the vertex (the hex's corners that are cell centres).
std::vector<std::int64_t> hex_levels(const InstallResult& installed, const LeafGrid& grid, const ClippedDual& dual) {
    std::vector<int> cell_level(installed.complex.n_cells(), 0);
    for (std::size_t n = 0; n < grid.size(); ++n)
        for (std::size_t c = installed.leaf_cells[n]; c < installed.leaf_cells[n + 1]; ++c)
            cell_level[c] = grid.leaf(n).level;
    std::vector<std::int64_t> level(dual.hexes.size(), 0);
    for (std::size_t h = 0; h < dual.hexes.size(); ++h)
        for (std::uint32_t p : dual.hexes[h])
            if (dual.kind[p] == DualVertexKind::Cell)
                level[h] = std::max<std::int64_t>(level[h], cell_level[dual.primal[p]]);
    return level;
}

struct Installed {
    LeafGrid grid;
    InstallResult result;
    ClippedDual dual;
    InstallVerification verification;
    geometry::HexMesh mesh;
    std::vector<double> quality;
    std::vector<std::int64_t> level;
    std::map<std::string, double> ms;
};

// Runs without the GIL: touches no Python object.
Installed run_install(const LeafInput& in, Balance balance, OutsideRoot outside) {
    Installed out;
    auto t0 = Clock::now();
    out.grid = in.path.empty() ? LeafGrid(in.leaves, in.source(), in.rows) : read_leaf_file(in.path);
    out.ms["read"] = ms_since(t0);
    const auto library = load_default_element_library();
    t0 = Clock::now();
    try {
        const InstallOptions options{.outside_root = outside, .balance = balance};
        out.result = balance == Balance::Strong ? install(out.grid, StrongRule(), *library, options)
                                                : install(out.grid, WeakRule(), *library, options);
    } catch (const InstallError& e) {
        throw GridInstallError(in.source(), e.what());
    }
    out.ms["install"] = ms_since(t0);
    t0 = Clock::now();
    const std::int64_t extent = out.result.unit << out.result.max_level;
    out.dual = clipped_dual(out.result.complex, Incidence(out.result.complex), {0, 0, 0}, {extent, extent, extent});
    out.ms["dual"] = ms_since(t0);
    t0 = Clock::now();
    out.verification = verify_installation(out.result);
    out.ms["verify"] = ms_since(t0);
    for (const RationalPoint& p : out.dual.points)
        out.mesh.points.emplace_back(p.coordinate(0, extent), p.coordinate(1, extent), p.coordinate(2, extent));
    for (const auto& h : out.dual.hexes) {
        std::array<int, 8> q{};
        for (std::size_t i = 0; i < 8; ++i) q[i] = static_cast<int>(h[i]);
        out.mesh.hexes.push_back(q);
    }
    out.quality = geometry::scaled_jacobians(out.mesh);
    out.level = hex_levels(out.result, out.grid, out.dual);
    return out;
}

py::dict report(const Installed& r, const std::string& source, const std::string& balance, const std::string& outside) {
    const CellComplex& k = r.result.complex;
    py::dict d;
    d["input"] = source;
    d["balance"] = balance;
    d["outside_root"] = outside;
    d["leaves"] = r.grid.size();
    d["min_level"] = r.grid.min_level();
    d["max_level"] = r.grid.max_level();
    d["cells"] = k.n_cells();
    d["vertices"] = k.n_vertices();
    d["non_hex_cells"] = non_hex_cell_count(k);
    d["hexes"] = r.dual.hexes.size();
    d["dual_points"] = r.dual.points.size();
    d["non_cube_dual_cells"] = r.dual.errors.size();
    d["elements"] = histogram_dict(r.result.elements_used());
    d["face_sizes"] = histogram_dict(face_size_histogram(k));
    d["dual_edge_valences"] = histogram_dict(clipped_dual_edge_valences(r.dual));
    d["verification"] = r.verification.summary();
    d["ok"] = r.verification.ok() && r.dual.all_cubes();
    d["ms"] = r.ms;
    return d;
}

py::dict install_py(const py::object& leaves, const std::string& balance, const std::string& outside_root, bool check) {
    const Balance b = parse_balance(balance);
    const OutsideRoot o = parse_outside(outside_root);
    const LeafInput in = leaf_input(leaves);
    Installed r;
    {
        py::gil_scoped_release release;
        r = run_install(in, b, o);
    }
    py::dict rep = report(r, in.source(), balance, outside_root);
    if (check && !rep["ok"].cast<bool>())
        throw VerificationError(in.source() + ": the installation fails its verification: " + r.verification.summary() +
                                (r.dual.all_cubes() ? "" : "; " + r.dual.errors.front().message));
    return mesh_dict(r.mesh, r.quality, &r.level, rep);
}

}  // namespace

void bind_install(py::module_& m) {
    m.def("_install", &install_py, py::arg("leaves"), py::arg("balance") = "weak", py::arg("outside_root") = "coarse",
          py::arg("check") = true,
          "Installs the elements into a paired, balanced grid (a leaf file path or an (N, 4) array of "
          "rows level i j k) and builds the clipped dual hex mesh; returns the dict dualhex.Mesh is made of.");
}

}  // namespace dualhex::python
