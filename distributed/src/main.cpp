// dualhex-dist: the distributed mesher on p8est (distributed/README.md). GPL-2.0-or-later,
// as it links p4est; the core library it uses stays MIT.
//
//   mpirun -np N dualhex-dist GRID.leaves          [common options]
//   mpirun -np N dualhex-dist --surface FILE [size options of `dualhex mesh`] [common options]
//     common: [--balance weak|strong] [--outside-root coarse|mirror] [-o PREFIX] [--force]
//             [--threads N] [--json]
//
// A leaf file is read in byte ranges, one per rank (leaf_reader.hpp), and the forest built
// level by level from the sorted runs (leaf_forest.hpp); a surface is read by every rank
// and the forest refined by the serial octree's criterion (surface_forest.hpp). Then p8est
// balances, pairs and partitions it; each rank installs and dualizes its share
// (rank_mesh.hpp); rank 0 prints the summary, the same for any number of ranks. Exit 0 if
// every owned vertex's dual is a cube, 1 if not, 2 for usage (or an existing output without
// --force, or an octree beyond --max-leaves), 3 for bad input.
#include <mpi.h>
#include <p4est_base.h>
#include <sc.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "commands.hpp"  // apps/: UsageError, for the size options shared with `dualhex mesh`
#include "dualhex/distributed/canonical_json.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/grid/input_error.hpp"
#include "forest.hpp"
#include "leaf_forest.hpp"
#include "leaf_reader.hpp"
#include "mesh_size_cli.hpp"
#include "pvtu.hpp"
#include "rank_mesh.hpp"
#include "surface_forest.hpp"

namespace {

using namespace dualhex;
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct Options {
    std::string input, surface, balance = "weak", outside = "coarse", prefix;
    bool force = false, json = false;
    int threads = 1;
    app::MeshSizeCli size;  // --preset, --size, ... (apps/mesh_size_cli.hpp), with --surface
};

long peak_rss_kb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

// This rank's CPU time (user + system), ms: the machine is shared, wall time is not the cost.
double cpu_ms() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const auto ms = [](const timeval& t) { return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_usec) / 1e3; };
    return ms(u.ru_utime) + ms(u.ru_stime);
}

nlohmann::json rank_stats(int rank, const dist::RankMesh& m, const nlohmann::json& input, long forest_rss_kb) {
    return {{"rank", rank},
            {"input", input},
            {"peak_rss_kb_forest", forest_rss_kb},
            {"local_leaves", m.local_leaves},
            {"ghost_leaves", m.ghost_leaves},
            {"installed_cells", m.installed_cells},
            {"points_asked", m.exchange.points_asked},
            {"points_remote", m.exchange.points_remote},
            {"bytes_sent", m.exchange.bytes_sent},
            {"bytes_received", m.exchange.bytes_received},
            {"first_vertex_id", m.first_vertex_id},
            {"peak_rss_kb", peak_rss_kb()},
            {"cpu_ms", cpu_ms()},
            {"ms", {{"ghost", m.ms.ghost}, {"exchange", m.ms.exchange}, {"contexts", m.ms.contexts},
                    {"install", m.ms.install}, {"dual", m.ms.dual}, {"summary", m.ms.summary}}},
            {"summary", to_json(m.summary)}};
}

// Every rank's JSON text to rank 0 (empty elsewhere).
std::vector<nlohmann::json> gather_json(const nlohmann::json& mine, MPI_Comm comm) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const std::string text = mine.dump();
    int len = static_cast<int>(text.size());
    std::vector<int> lens(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size) + 1, 0);
    MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, comm);
    for (int r = 0; r < size; ++r) displs[static_cast<std::size_t>(r) + 1] = displs[static_cast<std::size_t>(r)] + lens[static_cast<std::size_t>(r)];
    std::string all(rank == 0 ? static_cast<std::size_t>(displs.back()) : 0, '\0');
    MPI_Gatherv(text.data(), len, MPI_CHAR, all.data(), lens.data(), displs.data(), MPI_CHAR, 0, comm);
    std::vector<nlohmann::json> out;
    if (rank == 0)
        for (int r = 0; r < size; ++r)
            out.push_back(nlohmann::json::parse(all.substr(static_cast<std::size_t>(displs[static_cast<std::size_t>(r)]),
                                                           static_cast<std::size_t>(lens[static_cast<std::size_t>(r)]))));
    return out;
}

void print_text(const nlohmann::json& doc) {
    const auto& s = doc["summary"];
    std::cout << "dualhex-dist " << doc["input"].get<std::string>() << " on " << doc["ranks"] << " ranks ("
              << doc["balance"].get<std::string>() << "): " << doc["leaves"] << " leaves after "
              << doc["pairing_rounds"] << " pairing rounds; " << s["cells"] << " cells (" << s["non_hex_cells"]
              << " not hexahedra), " << s["vertices"] << " vertices, " << s["hexes"] << " hexes, "
              << s["non_cube_vertices"] << " non-cube duals\n"
              << "hex hash " << s["hex_hash"].get<std::string>() << ", cell hash " << s["cell_hash"].get<std::string>() << '\n';
    if (doc.contains("output")) std::cout << "wrote " << doc["output"].get<std::string>() << '\n';
}

// The refined forest (before balance and pairing) and what building it measured.
struct Built {
    std::unique_ptr<dist::Forest> forest;
    nlohmann::json rank_input;  ///< this rank's reading and building figures
    nlohmann::json global;      ///< for rank 0's document
    std::optional<geometry::RootCube> root;  ///< a surface's root cube
    std::optional<std::size_t> max_leaves;   ///< a surface's leaf budget
    double read_ms = 0;
};

Built from_leaves(const Options& opt, MPI_Comm comm) {
    Built b;
    const auto t0 = Clock::now();
    dist::DistributedLeaves leaves = dist::read_leaves_distributed(comm, opt.input);
    b.read_ms = ms_since(t0);
    const long read_rss = peak_rss_kb();
    b.forest = std::make_unique<dist::Forest>(comm, leaves.min_level);
    const dist::LeafForestStats st = dist::refine_to_leaves(*b.forest, leaves);
    b.rank_input = {{"bytes_read", leaves.bytes_read},         {"lines", leaves.lines_parsed},
                    {"leaves_parsed", leaves.leaves_parsed},   {"leaves_sorted", leaves.leaves.size()},
                    {"sort_bytes_sent", leaves.bytes_sorted_out}, {"refine_requests_sent", st.requests_sent},
                    {"refine_bytes_sent", st.bytes_sent},      {"peak_rss_kb_read", read_rss}};
    b.global = {{"forest_rounds", st.rounds}};
    return b;
}

Built from_surface(const Options& opt, MPI_Comm comm) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    const mesher::MeshSizeOptions size = app::resolve_size_options(opt.size);
    Built b;
    const auto t0 = Clock::now();
    geometry::SurfaceReport report;
    geometry::TriangleSurface surface = geometry::read_surface(opt.surface, {}, &report);
    const std::size_t triangles = surface.triangles.size();
    if (rank == 0)
        for (const auto& w : report.warnings) std::cerr << "warning: " << w << '\n';
    const geometry::AabbTree tree(std::move(surface));
    if (rank == 0) app::warn_if_capped(size, tree);
    const geometry::SurfaceRefinement criterion(tree, mesher::octree_options(size, tree.bounds()));
    b.read_ms = ms_since(t0);
    const long read_rss = peak_rss_kb();
    b.forest = std::make_unique<dist::Forest>(comm, 0);
    const dist::SurfaceForestStats st = dist::refine_to_surface(*b.forest, criterion);
    b.root = criterion.root();
    b.max_leaves = size.max_leaves;
    const Eigen::Vector3d& o = b.root->origin;
    b.global = {{"octree",
                 {{"leaves", st.octree_leaves}, {"crossing_leaves", st.crossing_leaves},
                  {"curvature_splits", st.curvature_splits}, {"size_level", criterion.size_level()},
                  {"target_size", criterion.options().surface_size}, {"rounds", st.rounds}}},
                {"root", {{"origin", {o.x(), o.y(), o.z()}}, {"size", b.root->size}}}};
    b.rank_input = {{"triangles", triangles}, {"decisions", st.decisions},
                    {"ancestor_recomputations", st.ancestor_recomputations}, {"peak_rss_kb_read", read_rss}};
    return b;
}

int run(const Options& opt, MPI_Comm comm) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    int refuse = 0;  // outputs checked before any work, on rank 0, decision shared
    if (rank == 0 && !opt.prefix.empty() && !opt.force) {
        std::vector<std::string> outputs{opt.prefix + ".pvtu"};
        for (int r = 0; r < size; ++r) outputs.push_back(dist::piece_path(opt.prefix, r));
        for (const std::string& path : outputs)
            if (!refuse && std::filesystem::exists(path)) {
                std::cerr << "error: " << path << " exists (pass --force to replace it)\n";
                refuse = 1;
            }
    }
    MPI_Bcast(&refuse, 1, MPI_INT, 0, comm);
    if (refuse) return 2;
    const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(opt.threads));
    const auto t_start = Clock::now();
    auto t0 = Clock::now();
    Built built;
    try {
        built = opt.surface.empty() ? from_leaves(opt, comm) : from_surface(opt, comm);
    } catch (const InputError& e) {  // every rank has the same (leaf_reader.hpp)
        if (rank == 0) std::cerr << "error: " << e.what() << '\n';
        return 3;
    } catch (const geometry::SurfaceError& e) {  // every rank read the same file
        if (rank == 0) std::cerr << "error: " << e.what() << '\n';
        return 3;
    } catch (const app::UsageError& e) {
        if (rank == 0) std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const geometry::OctreeTooLarge& e) {  // every rank: the estimate, or the global count
        if (rank == 0) std::cerr << "error: " << e.what() << " (a coarser --size or --size-rel, or raise --max-leaves)\n";
        return 2;
    }
    const double t_read = built.read_ms;
    const double t_forest_build = ms_since(t0) - t_read;
    const Balance balance = opt.balance == "strong" ? Balance::Strong : Balance::Weak;
    t0 = Clock::now();
    dist::Forest& forest = *built.forest;
    forest.balance_and_pair(balance);
    if (built.max_leaves && static_cast<std::size_t>(forest.global_leaves()) > *built.max_leaves) {
        if (rank == 0)
            std::cerr << "error: paired grid: " << forest.global_leaves() << " leaves, more than the limit "
                      << *built.max_leaves << " (a coarser --size or --size-rel, or raise --max-leaves)\n";
        return 2;
    }
    const double t_forest = ms_since(t0) + t_forest_build;
    const long forest_rss_kb = peak_rss_kb();
    t0 = Clock::now();
    dist::RankMesh mesh = dist::mesh_rank(
        forest, {balance, opt.outside == "mirror" ? OutsideRoot::Mirror : OutsideRoot::Coarse, !opt.prefix.empty()});
    const double t_mesh = ms_since(t0);
    if (built.root) {  // a surface: the pieces in model units (the root cube's embedding)
        for (auto& p : mesh.piece.points) p = built.root->origin + built.root->size * p;
    }
    if (!opt.prefix.empty()) {
        dist::write_piece(dist::piece_path(opt.prefix, rank), mesh.piece, rank, mesh.piece_vertex_id);
        if (rank == 0) dist::write_pvtu(opt.prefix, size);
    }
    const int max_level = forest.global_max_level();  // collective: before the ranks part
    const std::vector<nlohmann::json> ranks = gather_json(rank_stats(rank, mesh, built.rank_input, forest_rss_kb), comm);
    if (rank != 0) return 0;
    CanonicalSummary total;
    for (const auto& r : ranks) total.add(summary_from_json(r["summary"]));
    nlohmann::json doc{{"input", opt.surface.empty() ? opt.input : opt.surface},
                       {"source", opt.surface.empty() ? "leaves" : "surface"}, {"ranks", size}, {"balance", opt.balance}, {"outside_root", opt.outside},
                       {"leaves", forest.global_leaves()}, {"max_level", max_level},
                       {"pairing_rounds", forest.pairing_rounds()}, {"summary", to_json(total)}, {"per_rank", ranks},
                       {"ms", {{"read", t_read}, {"forest", t_forest}, {"mesh", t_mesh}, {"total", ms_since(t_start)}}}};
    doc.update(built.global);
    if (!opt.prefix.empty()) doc["output"] = opt.prefix + ".pvtu";
    if (opt.json) std::cout << doc.dump(2) << '\n';
    else print_text(doc);
    return total.non_cube_vertices == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    sc_init(MPI_COMM_WORLD, 0, 0, nullptr, SC_LP_ERROR);
    p4est_init(nullptr, SC_LP_ERROR);
    CLI::App app{"dualhex-dist: the distributed dual-scheme mesher on p8est (GPL-2.0-or-later)"};
    Options opt;
    auto* grid = app.add_option("grid", opt.input, "leaf file (.leaves), read in one byte range per rank");
    auto* surface = app.add_option("--surface", opt.surface,
                                   "closed surface (OBJ, OFF, STL, PLY): the forest by the octree criterion of "
                                   "`dualhex mesh` (its size options below); the output is the installed grid's dual")
                        ->excludes(grid);
    auto* input = app.add_option_group("input", "a leaf file or --surface");
    input->add_options(grid, surface);
    input->require_option(1);
    app::add_size_options(app, opt.size);
    app.add_option("--balance", opt.balance, "weak (face, P8EST_CONNECT_FACE; the weak rule) or strong (P8EST_CONNECT_FULL)")
        ->check(CLI::IsMember({"weak", "strong"}));
    app.add_option("--outside-root", opt.outside, "octants outside the root: coarse or mirror")
        ->check(CLI::IsMember({"coarse", "mirror"}));
    app.add_option("-o,--output", opt.prefix, "write PREFIX.pvtu and PREFIX_<rank>.vtu");
    app.add_flag("--force", opt.force, "overwrite existing output");
    app.add_option("--threads", opt.threads, "oneTBB threads per rank (default 1)")->check(CLI::PositiveNumber);
    app.add_flag("--json", opt.json, "one JSON document on stdout (rank 0)");
    int rc = 0;
    try {
        app.parse(argc, argv);
        rc = run(opt, MPI_COMM_WORLD);
    } catch (const CLI::ParseError& e) {
        int rank = 0;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        rc = rank == 0 ? app.exit(e) : 2;
        if (rc != 0) rc = 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        sc_finalize();
        MPI_Abort(MPI_COMM_WORLD, 1);  // a rank failing alone would leave the others in a collective
    }
    sc_finalize();
    MPI_Finalize();
    return rc;
}
