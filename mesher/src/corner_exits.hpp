#pragma once
// Internal (features stage): which boundary edge each feature curve leaves its corner by.
// Without it, the first paths out of a corner take whichever neighbour is cheapest and a
// later curve of the same corner may find its side walled off (a valence-3 corner vertex
// with 3 curves has no edge to spare).
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace dualhex::mesher::detail {

/// The injective map curve end -> neighbour maximising the summed cosines between the
/// ends' unit tangents and the unit directions to the neighbours (exhaustive: a corner
/// has a handful of each). Out: per tangent, the neighbour index; all -1 if there are more
/// tangents than neighbours.
[[nodiscard]] inline std::vector<int> assign_exits(const std::vector<Eigen::Vector3d>& tangents,
                                                   const std::vector<Eigen::Vector3d>& directions) {
    std::vector<int> best(tangents.size(), -1);
    if (tangents.size() > directions.size() || tangents.size() > 8) return best;
    std::vector<int> now(tangents.size(), -1);
    std::vector<char> taken(directions.size(), 0);
    double best_score = -1e300;
    auto search = [&](auto&& self, std::size_t i, double score) -> void {
        if (i == tangents.size()) {
            if (score > best_score) {
                best_score = score;
                best = now;
            }
            return;
        }
        for (std::size_t j = 0; j < directions.size(); ++j)
            if (!taken[j]) {
                taken[j] = 1;
                now[i] = static_cast<int>(j);
                self(self, i + 1, score + tangents[i].dot(directions[j]));
                taken[j] = 0;
            }
    };
    search(search, 0, 0.0);
    return best;
}

}  // namespace dualhex::mesher::detail
