// dualhex install GRID.leaves -o PREFIX: installs the strongly balanced elements into a
// paired, strongly balanced grid (StrongRule, default element library), verifies the
// result, builds the clipped dual (one hex per primal vertex, boundary kept) and writes
// PREFIX.poly.vtk (VTK_POLYHEDRON) and PREFIX.hex.vtk (VTK_HEXAHEDRON).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "histogram_format.hpp"
#include "progress_bar.hpp"
#include "threads_option.hpp"

#include "dualhex/checkers/certificate.hpp"
#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex::app {
namespace {

struct InstallOptionsCli {
    std::string input, prefix, outside = "coarse", balance = "weak", certify;
    bool json = false, force = false, no_progress = false;
    int threads = 0;  // 0: every core
};

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

void run_install(const InstallOptionsCli& opt) {
    const ThreadLimit limit(opt.threads);
    const std::string poly_path = opt.prefix + ".poly.vtk", hex_path = opt.prefix + ".hex.vtk";
    check_output(poly_path, opt.force);  // before any work
    check_output(hex_path, opt.force);
    if (!opt.certify.empty()) check_output(opt.certify, opt.force);
    const OutsideRoot outside = opt.outside == "mirror" ? OutsideRoot::Mirror : OutsideRoot::Coarse;
    // Steps: read, install, dual, the verification's own steps, write.
    ProgressBar bar = ProgressBar::for_stderr(opt.json, opt.no_progress);
    constexpr std::size_t kSteps = 4 + kVerifySteps;
    const auto step = [&bar](const std::string& name, std::size_t done) {
        bar.update("install " + std::to_string(done + 1) + "/" + std::to_string(kSteps) + ": " + name, done, kSteps);
    };

    step("read", 0);
    auto t0 = Clock::now();
    const LeafGrid grid = read_leaf_file(opt.input);  // InputError -> exit 3
    const double t_read = ms_since(t0);

    const auto library = load_default_element_library();
    if (!opt.certify.empty()) {  // before the work: a certificate the checker would reject is no certificate
        const std::int64_t needed = lattice_unit(*library) << grid.max_level();
        if (needed > kCertificateMaxCoordinate)
            throw UsageError("--certify: the grid's level " + std::to_string(grid.max_level()) +
                             " needs lattice coordinates up to " + std::to_string(needed) +
                             ", beyond the checker's bound " + std::to_string(kCertificateMaxCoordinate) +
                             " (2^19); grids up to level " + std::to_string(max_certifiable_level(lattice_unit(*library))) +
                             " can be certified");
    }
    step("install", 1);
    t0 = Clock::now();
    InstallResult installed;
    try {
        // The weak rule is the strong rule plus the MR elements, which it only places where a
        // concave edge meets leaves two levels finer: on strongly balanced grids both agree.
        const Balance balance = opt.balance == "strong" ? Balance::Strong : Balance::Weak;
        installed = opt.balance == "strong"
                        ? install(grid, StrongRule(), *library, {.outside_root = outside, .balance = balance})
                        : install(grid, WeakRule(), *library, {.outside_root = outside, .balance = balance});
    } catch (const InstallError& e) {  // not paired / not balanced as required: bad input
        bar.clear();
        std::cerr << "error: " << opt.input << ": " << e.what() << '\n';
        throw Exit{kInputError};
    }
    const double t_install = ms_since(t0);
    const CellComplex& k = installed.complex;

    step("dual", 2);
    t0 = Clock::now();
    const std::int64_t extent = installed.unit << installed.max_level;
    const ClippedDual dual = [&] {
        const Incidence inc(k);
        return clipped_dual(k, inc, {0, 0, 0}, {extent, extent, extent});
    }();
    const double t_dual = ms_since(t0);

    t0 = Clock::now();
    const InstallVerification verification =
        verify_installation(installed, [&](std::string_view stage, std::size_t done, std::size_t) {
            step("verify: " + std::string(stage), 3 + done);
        });
    const auto valences = clipped_dual_edge_valences(dual);
    const double t_verify = ms_since(t0);
    const bool ok = verification.ok() && dual.all_cubes();

    step("write", kSteps - 1);
    t0 = Clock::now();
    const double scale = 1.0 / static_cast<double>(extent);
    geometry::write_complex_vtk(poly_path, k, geometry::LatticeEmbedding{Eigen::Vector3d::Zero(), scale}, true);
    {
        geometry::HexMesh mesh;
        mesh.points.reserve(dual.points.size());
        for (const RationalPoint& p : dual.points)
            mesh.points.emplace_back(p.coordinate(0, extent), p.coordinate(1, extent), p.coordinate(2, extent));
        mesh.hexes.reserve(dual.hexes.size());
        for (const auto& h : dual.hexes) {
            std::array<int, 8> q{};
            for (std::size_t i = 0; i < 8; ++i) q[i] = static_cast<int>(h[i]);
            mesh.hexes.push_back(q);
        }
        geometry::write_vtk_legacy(hex_path, mesh, true);
    }
    if (!opt.certify.empty()) {
        // An installation certificate: the complex itself, explicitly, with its claims, for
        // the independent checker (dualhex-proof-checker --file FILE).
        CertificateSpec spec;
        spec.name = "installation";
        spec.kind = CertificateKind::Installation;
        spec.domain = CertificateDomain::box({0, 0, 0}, {extent, extent, extent});
        spec.comments = {"dualhex install " + opt.input + " (" + opt.balance + " rule, outside root " + opt.outside + ")"};
        std::ofstream out = open_output(opt.certify, opt.force);
        write_certificate(out, k, spec);
    }
    const double t_write = ms_since(t0);

    bar.finish("install: " + with_commas(k.n_cells()) + " cells, " + with_commas(dual.hexes.size()) + " dual hexes, " +
               (ok ? "verified" : "FAILED"));
    const std::size_t non_hex = non_hex_cell_count(k);
    const auto elements = installed.elements_used();
    const auto face_sizes = face_size_histogram(k);
    if (opt.json) {
        nlohmann::json errors = nlohmann::json::array();
        for (std::size_t i = 0; i < dual.errors.size() && i < 20; ++i) errors.push_back(dual.errors[i].message);
        print_json({{"input", opt.input},
                    {"outside_root", opt.outside},
                    {"leaves", grid.size()},
                    {"cells", k.n_cells()},
                    {"vertices", k.n_vertices()},
                    {"non_hex_cells", non_hex},
                    {"hexes", dual.hexes.size()},
                    {"dual_points", dual.points.size()},
                    {"non_cube_dual_cells", dual.errors.size()},
                    {"non_cube_examples", errors},
                    {"elements", histogram_json(elements)},
                    {"face_sizes", histogram_json(face_sizes)},
                    {"dual_edge_valences", histogram_json(valences)},
                    {"verification", verification.summary()},
                    {"ok", ok},
                    {"outputs", {poly_path, hex_path}},
                    {"ms", {{"read", t_read}, {"install", t_install}, {"dual", t_dual}, {"verify", t_verify}, {"write", t_write}}}});
    } else {
        std::printf("%s: %zu leaves, levels %d..%d\n", opt.input.c_str(), grid.size(), grid.min_level(), grid.max_level());
        std::printf("installed (%s rule, outside root %s): %zu cells, %zu not hexahedra, %zu vertices\n",
                    opt.balance.c_str(), opt.outside.c_str(), k.n_cells(), non_hex, k.n_vertices());
        std::printf("elements (leaves):            %s\n", histogram_text(elements).c_str());
        std::printf("face sizes:                   %s\n", histogram_text(face_sizes).c_str());
        std::printf("clipped dual:                 %zu hexes over %zu points, %zu vertices without a cube\n",
                    dual.hexes.size(), dual.points.size(), dual.errors.size());
        for (std::size_t i = 0; i < dual.errors.size() && i < 10; ++i) std::printf("  %s\n", dual.errors[i].message.c_str());
        std::printf("interior dual edge valences:  %s\n", histogram_text(valences).c_str());
        std::printf("verification:                 %s\n", verification.summary().c_str());
        std::printf("wrote %s, %s\n", poly_path.c_str(), hex_path.c_str());
        std::printf("time (ms): read %.1f, install %.1f, dual %.1f, verify %.1f, write %.1f\n", t_read, t_install, t_dual,
                    t_verify, t_write);
        std::printf("%s\n", ok ? "OK" : "FAILED");
    }
    if (!ok) throw Exit{kCheckFailed};
}

}  // namespace

void register_install(CLI::App& app) {
    auto opt = std::make_shared<InstallOptionsCli>();
    CLI::App* sub = app.add_subcommand(
        "install",
        "Install the elements into a paired, weakly (or strongly) balanced grid, verify, and write the "
        "polyhedral complex (PREFIX.poly.vtk) and its clipped dual hex mesh (PREFIX.hex.vtk)");
    sub->add_option("grid", opt->input, "Leaf file (paired; weakly balanced, or strongly with --balance strong)")->required();
    sub->add_option("--balance", opt->balance,
                    "weak (default: the weak rule, 13 elements; accepts strongly balanced grids too) or strong "
                    "(the 8 strong elements; refuses grids that are not strongly balanced)")
        ->check(CLI::IsMember({"weak", "strong"}));
    sub->add_option("-o,--output", opt->prefix, "Output prefix: writes PREFIX.poly.vtk and PREFIX.hex.vtk")->required();
    sub->add_flag("--force", opt->force, "Overwrite the output files if they exist");
    add_threads_option(*sub, opt->threads);
    sub->add_option("--certify", opt->certify,
                    "Also write a certificate of the installed complex to FILE (check it with "
                    "dualhex-proof-checker --file FILE)");
    sub->add_option("--outside-root", opt->outside, "Octant cubes outside the root: coarse (default) or mirror")
        ->check(CLI::IsMember({"coarse", "mirror"}));
    add_json_flag(*sub, opt->json);
    add_no_progress_flag(*sub, opt->no_progress);
    sub->callback([opt] { run_install(*opt); });
}

}  // namespace dualhex::app
