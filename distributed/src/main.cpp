// dualhex-dist: the distributed mesher on p8est (distributed/README.md). GPL-2.0-or-later,
// as it links p4est; the core library it uses stays MIT.
//
//   mpirun -np N dualhex-dist GRID [--balance weak|strong] [--outside-root coarse|mirror]
//                                  [-o PREFIX] [--force] [--threads N] [--json]
//
// Every rank reads GRID (a leaf file); p8est refines a forest to it, balances it, pairs it
// and partitions it; each rank installs and dualizes its share (rank_mesh.hpp); rank 0
// prints the summary, the same for any number of ranks. Exit 0 if every owned vertex's
// dual is a cube, 1 if not, 2 for usage (or an existing output without --force), 3 for bad input.
#include <mpi.h>
#include <p4est_base.h>
#include <sc.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "dualhex/distributed/canonical_json.hpp"
#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "forest.hpp"
#include "pvtu.hpp"
#include "rank_mesh.hpp"

namespace {

using namespace dualhex;
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct Options {
    std::string input, balance = "weak", outside = "coarse", prefix;
    bool force = false, json = false;
    int threads = 1;
};

long peak_rss_kb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

nlohmann::json rank_stats(int rank, const dist::RankMesh& m) {
    return {{"rank", rank},
            {"local_leaves", m.local_leaves},
            {"ghost_leaves", m.ghost_leaves},
            {"installed_cells", m.installed_cells},
            {"points_asked", m.exchange.points_asked},
            {"points_remote", m.exchange.points_remote},
            {"bytes_sent", m.exchange.bytes_sent},
            {"bytes_received", m.exchange.bytes_received},
            {"first_vertex_id", m.first_vertex_id},
            {"peak_rss_kb", peak_rss_kb()},
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
    LeafGrid grid;
    try {
        grid = read_leaf_file(opt.input);  // every rank: the same file, the same verdict
        if (grid.max_level() > dist::kForestMaxLevel)
            throw InputError(opt.input, 0, "finest level " + std::to_string(grid.max_level()) + " is beyond p8est's " +
                                               std::to_string(dist::kForestMaxLevel));
    } catch (const InputError& e) {
        if (rank == 0) std::cerr << "error: " << e.what() << '\n';
        return 3;
    }
    const double t_read = ms_since(t0);
    const Balance balance = opt.balance == "strong" ? Balance::Strong : Balance::Weak;
    t0 = Clock::now();
    const dist::Forest forest(comm, grid, balance);
    grid = LeafGrid();  // the input is not needed past the refinement
    const double t_forest = ms_since(t0);
    t0 = Clock::now();
    const dist::RankMesh mesh = dist::mesh_rank(
        forest, {balance, opt.outside == "mirror" ? OutsideRoot::Mirror : OutsideRoot::Coarse, !opt.prefix.empty()});
    const double t_mesh = ms_since(t0);
    if (!opt.prefix.empty()) {
        dist::write_piece(dist::piece_path(opt.prefix, rank), mesh.piece, rank, mesh.piece_vertex_id);
        if (rank == 0) dist::write_pvtu(opt.prefix, size);
    }
    const int max_level = forest.global_max_level();  // collective: before the ranks part
    const std::vector<nlohmann::json> ranks = gather_json(rank_stats(rank, mesh), comm);
    if (rank != 0) return 0;
    CanonicalSummary total;
    for (const auto& r : ranks) total.add(summary_from_json(r["summary"]));
    nlohmann::json doc{{"input", opt.input}, {"ranks", size}, {"balance", opt.balance}, {"outside_root", opt.outside},
                       {"leaves", forest.global_leaves()}, {"max_level", max_level},
                       {"pairing_rounds", forest.pairing_rounds()}, {"summary", to_json(total)}, {"per_rank", ranks},
                       {"ms", {{"read", t_read}, {"forest", t_forest}, {"mesh", t_mesh}, {"total", ms_since(t_start)}}}};
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
    app.add_option("grid", opt.input, "leaf file (.leaves)")->required();
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
