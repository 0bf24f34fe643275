#pragma once
// Checks shared by the readers: a cell type with its point count, a polyhedron's face
// stream, point ids in range. Each returns the error text (the reader adds file and line).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace dualhex::audit::detail {

/// Unknown type, or a fixed-size type with the wrong number of points.
[[nodiscard]] std::optional<std::string> cell_type_error(int type, std::size_t listed_points);
/// "nfaces, n0, ids..., n1, ids..." exactly filling `stream`, ids in [0, n_points).
[[nodiscard]] std::optional<std::string> decode_face_stream(std::span<const std::int64_t> stream,
                                                            std::size_t n_points,
                                                            std::vector<std::vector<std::int64_t>>& faces);
[[nodiscard]] std::optional<std::string> point_id_error(std::span<const std::int64_t> ids, std::size_t n_points);

}  // namespace dualhex::audit::detail
