// Repair of a non-manifold cell selection (manifold_repair.hpp).
#include "dualhex/geometry/manifold_repair.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace dualhex::geometry {
namespace {

// vertex -> the cells containing it, CSR.
struct VertexCells {
    std::vector<std::size_t> start;
    std::vector<std::size_t> cells;
    VertexCells(const std::vector<std::array<int, 8>>& hexes, std::size_t vertex_count) : start(vertex_count + 1, 0) {
        for (const auto& h : hexes)
            for (int v : h) ++start[static_cast<std::size_t>(v) + 1];
        for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
        cells.resize(start.back());
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        for (std::size_t c = 0; c < hexes.size(); ++c)
            for (int v : hexes[c]) cells[fill[static_cast<std::size_t>(v)]++] = c;
        // a cell listing a vertex twice (degenerate) appears twice: harmless, deduplicated below
    }
    [[nodiscard]] std::vector<std::size_t> at(int v) const {
        std::vector<std::size_t> out(
            cells.begin() + static_cast<std::ptrdiff_t>(start[static_cast<std::size_t>(v)]),
            cells.begin() + static_cast<std::ptrdiff_t>(start[static_cast<std::size_t>(v) + 1]));
        out.erase(std::unique(out.begin(), out.end()), out.end());  // ascending by construction
        return out;
    }
};

bool has_edge(const std::array<int, 8>& h, int a, int b) {
    for (const auto& e : kHexEdgeCorners)
        if ((h[e[0]] == a && h[e[1]] == b) || (h[e[0]] == b && h[e[1]] == a)) return true;
    return false;
}

std::vector<std::size_t> edge_star(const std::vector<std::array<int, 8>>& cells, const VertexCells& incidence, int a,
                                   int b) {
    std::vector<std::size_t> out;
    for (std::size_t c : incidence.at(a))
        if (has_edge(cells[c], a, b)) out.push_back(c);
    return out;
}

void check_input(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                 const std::vector<char>& selected, const std::vector<double>& score) {
    if (selected.size() != cells.size() || score.size() != cells.size())
        throw std::invalid_argument("manifold repair: " + std::to_string(cells.size()) + " cells but " +
                                    std::to_string(selected.size()) + " selection flags and " +
                                    std::to_string(score.size()) + " scores");
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!std::isfinite(score[c]))
            throw std::invalid_argument("manifold repair: cell " + std::to_string(c) + " has a non-finite score");
        for (int v : cells[c])
            if (v < 0 || static_cast<std::size_t>(v) >= vertex_count)
                throw std::invalid_argument("manifold repair: cell " + std::to_string(c) + ": vertex id " +
                                            std::to_string(v) + " not in [0, " + std::to_string(vertex_count) + ")");
    }
}

std::vector<std::array<int, 8>> selected_cells(const std::vector<std::array<int, 8>>& cells,
                                               const std::vector<char>& selected) {
    std::vector<std::array<int, 8>> out;
    for (std::size_t c = 0; c < cells.size(); ++c)
        if (selected[c]) out.push_back(cells[c]);
    return out;
}

// The repair state shared by the rounds.
struct Repair {
    const std::vector<std::array<int, 8>>& cells;
    const std::vector<double>& score;
    const ManifoldRepairOptions& options;
    VertexCells incidence;
    ManifoldRepairResult result;
    std::vector<char> frozen;        // changed in the score phase
    std::vector<int> changed_round;  // last round a cell changed, -1 never

    // The cell to change at a spot with this star, if any.
    [[nodiscard]] std::optional<std::size_t> choose(const std::vector<std::size_t>& star, bool fill) const {
        std::optional<std::size_t> best;
        double best_cost = 0;
        bool best_adds = false;
        for (std::size_t c : star) {  // ascending: the first of equal choices wins
            const bool adds = !result.selected[c];
            if (fill ? !adds : (frozen[c] || (!adds && !options.may_remove))) continue;
            const double cost = adds ? -score[c] : score[c];
            if (!best || cost < best_cost || (cost == best_cost && adds && !best_adds)) {
                best = c;
                best_cost = cost;
                best_adds = adds;
            }
        }
        return best;
    }

    // One change at the spot unless its star already changed this round; true if changed.
    bool visit(const std::vector<std::size_t>& star, int round, bool fill, DefectSpot spot, std::array<int, 2> at) {
        if (std::any_of(star.begin(), star.end(), [&](std::size_t c) { return changed_round[c] == round; }))
            return false;
        const auto c = choose(star, fill);
        if (!c) return false;
        result.selected[*c] = !result.selected[*c];
        changed_round[*c] = round;
        if (!fill) frozen[*c] = 1;
        result.changes.push_back({*c, result.selected[*c] != 0, round, spot, at});
        return true;
    }

    // One round over all spots of `defects`; the number of changes.
    std::size_t round(const BoundaryDefects& defects, int r, bool fill) {
        std::size_t changes = 0;
        for (const auto& e : defects.non_manifold_edges)
            changes += visit(edge_star(cells, incidence, e.a, e.b), r, fill, DefectSpot::Edge, {e.a, e.b});
        for (int v : defects.non_manifold_vertices)
            changes += visit(incidence.at(v), r, fill, DefectSpot::Vertex, {v, -1});
        return changes;
    }
};

}  // namespace

ManifoldRepairResult repair_manifold_selection(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                                               std::vector<char> selected, const std::vector<double>& score,
                                               const ManifoldRepairOptions& options) {
    check_input(cells, vertex_count, selected, score);
    Repair repair{cells,
                  score,
                  options,
                  VertexCells(cells, vertex_count),
                  {},
                  std::vector<char>(cells.size(), 0),
                  std::vector<int>(cells.size(), -1)};
    for (auto& s : selected) s = s != 0;
    repair.result.selected = std::move(selected);
    bool fill = options.score_rounds <= 0;
    BoundaryDefects defects = boundary_defects(selected_cells(cells, repair.result.selected), vertex_count);
    int r = 0;
    for (; r < options.max_rounds && !defects.manifold(); ++r) {
        fill = fill || r >= options.score_rounds;
        std::size_t changes = repair.round(defects, r, fill);
        if (changes == 0 && !fill) {  // the score phase is stuck: fill from here on
            fill = true;
            changes = repair.round(defects, r, fill);
        }
        if (changes == 0) break;  // a fixed point with defects: reported below
        defects = boundary_defects(selected_cells(cells, repair.result.selected), vertex_count);
    }
    repair.result.rounds = r;
    repair.result.hit_round_limit = r == options.max_rounds && !defects.manifold();
    repair.result.remaining = std::move(defects);
    return std::move(repair.result);
}

}  // namespace dualhex::geometry
