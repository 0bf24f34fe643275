#pragma once
// Placed-element templates and their emission into a ComplexBuilder: the welding step of
// install(), shared with the checkers' torus and window assemblies (namespace detail: an
// implementation interface, not for pipeline authors).
//
// A template is one element moved by one world symmetry about the origin (library
// `instance`, so reflections keep cells outward-oriented), its coordinates rescaled to the
// common lattice unit U (the lcm of the library's `leaf` resolutions, made even so fine
// leaves of U/2 stay integral). Emission adds the template's points once (translated,
// scaled, optionally wrapped) and its cells as loops of those vertices: the builder welds
// by exact keys and deduplicates shared faces.
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "dualhex/schemes/placement.hpp"
#include "dualhex/topology/complex_builder.hpp"

namespace dualhex {
class ElementLibrary;
}

namespace dualhex::detail {

struct ElementTemplate {
    std::string element;  // "" for the plain hexahedron
    std::vector<LatticePoint> points;
    std::vector<std::uint32_t> face_offsets{0};  // loops of all cells' outward half-faces
    std::vector<std::uint32_t> face_points;
    std::vector<std::uint32_t> cell_offsets{0};  // into faces
    [[nodiscard]] std::size_t n_cells() const { return cell_offsets.size() - 1; }
};

using Index3 = std::array<std::int64_t, 3>;

[[nodiscard]] inline std::int64_t floor_mod(std::int64_t a, std::int64_t m) { return ((a % m) + m) % m; }
[[nodiscard]] inline std::int64_t floor_div(std::int64_t a, std::int64_t m) { return (a - floor_mod(a, m)) / m; }

/// The octant cube (min corner 2o, coarse-leaf units) that a leaf with this application
/// point and direction sees as local octant `local` (each in {-2,-1,0,1}).
[[nodiscard]] inline Index3 world_octant(const LeafContext& ctx, const std::array<int, 3>& local) {
    Index3 w{};
    for (std::size_t a = 0; a < 3; ++a) {
        const std::int64_t half = ctx.application_point[static_cast<int>(a)] / 2;
        w[a] = ctx.direction[a] > 0 ? half + local[a] : half - local[a] - 1;
    }
    return w;
}

/// The context of the coarse leaf with min corner `leaf` (coarse-leaf units; octant cube o
/// has min corner 2o): its application point (the corner of its octant it touches), its
/// direction, and the 4x4x4 octant cubes around the application point, `fine(o)` giving
/// the status of octant cube o.
template <class Fine>
[[nodiscard]] LeafContext coarse_leaf_context(const LatticePoint& leaf, Fine&& fine) {
    LeafContext ctx;
    for (int a = 0; a < 3; ++a) {
        const bool even = floor_mod(leaf[a], 2) == 0;
        ctx.application_point[a] = even ? leaf[a] : leaf[a] + 1;
        ctx.direction[static_cast<std::size_t>(a)] = even ? 1 : -1;
    }
    for (int i = -2; i <= 1; ++i)
        for (int j = -2; j <= 1; ++j)
            for (int k = -2; k <= 1; ++k)
                if (fine(world_octant(ctx, {i, j, k}))) ctx.set_fine(i, j, k);
    return ctx;
}

/// The common lattice unit of a library (see above); 2 for an empty library.
[[nodiscard]] std::int64_t common_unit(const ElementLibrary& library);

class TemplateCache {
public:
    explicit TemplateCache(const ElementLibrary& library);
    [[nodiscard]] std::int64_t unit() const { return unit_; }
    /// The hex [0, size]^3 (size in lattice units).
    [[nodiscard]] const ElementTemplate& hex(std::int64_t size);
    /// Element index (for per-leaf records), throws std::out_of_range naming known elements.
    [[nodiscard]] int element_index(const std::string& name);
    [[nodiscard]] const std::string& element_name(int index) const { return names_[static_cast<std::size_t>(index)]; }
    [[nodiscard]] const std::vector<std::string>& element_names() const { return names_; }
    [[nodiscard]] const ElementTemplate& placed(int element, const CubeSymmetry& world);

private:
    const ElementLibrary* library_;
    std::int64_t unit_;
    std::unordered_map<std::int64_t, ElementTemplate> hexes_;
    std::unordered_map<std::string, int> index_;
    std::vector<std::string> names_;
    std::vector<std::array<int, 48>> slot_;  // per element, per symmetry: index into templates_ or -1
    std::deque<ElementTemplate> templates_;  // stable references
};

/// Throws UnknownPatternError-free std::invalid_argument if the placement's symmetry moves
/// the leaf out of its local box [0,1]^3 (only the 6 axis permutations keep it).
void check_placement_symmetry(const Placement& placement);

/// Adds the template's cells over `vertices` (vertices[n] is the template's point n).
inline void emit_cells(ComplexBuilder& builder, const ElementTemplate& t, std::span<const VertexHandle> vertices,
                       std::vector<VertexHandle>& loop, std::vector<HalfFaceHandle>& halffaces) {
    for (std::size_t c = 0; c + 1 < t.cell_offsets.size(); ++c) {
        halffaces.clear();
        for (std::uint32_t f = t.cell_offsets[c]; f < t.cell_offsets[c + 1]; ++f) {
            loop.clear();
            for (std::uint32_t q = t.face_offsets[f]; q < t.face_offsets[f + 1]; ++q) loop.push_back(vertices[t.face_points[q]]);
            halffaces.push_back(builder.add_face(loop));
        }
        builder.add_cell(halffaces);
    }
}

/// Adds the template at `translation + scale * p`, each point welded by `weld(point)`.
template <class Weld>
void emit_welded(ComplexBuilder& builder, const ElementTemplate& t, const LatticePoint& translation,
                 std::int64_t scale, Weld&& weld, std::vector<VertexHandle>& vertices, std::vector<VertexHandle>& loop,
                 std::vector<HalfFaceHandle>& halffaces) {
    vertices.resize(t.points.size());
    for (std::size_t n = 0; n < t.points.size(); ++n) vertices[n] = weld(translation + t.points[n] * scale);
    emit_cells(builder, t, vertices, loop, halffaces);
}

/// Adds the template at `translation + scale * p` (each point then passed through `wrap`
/// and welded by the builder).
template <class Wrap>
void emit(ComplexBuilder& builder, const ElementTemplate& t, const LatticePoint& translation, std::int64_t scale,
          Wrap&& wrap, std::vector<VertexHandle>& vertices, std::vector<VertexHandle>& loop,
          std::vector<HalfFaceHandle>& halffaces) {
    emit_welded(
        builder, t, translation, scale, [&](const LatticePoint& p) { return builder.add_vertex(wrap(p)); }, vertices,
        loop, halffaces);
}

/// Emits the rule's choice for a leaf of `size` lattice units with min corner `corner`:
/// its element about `origin` (the context's application point in lattice units) scaled by
/// size / unit, or a plain hex. Returns the placement (nullopt: the hex). Throws what the
/// rule throws, and for an unknown element or a symmetry that leaves the leaf box.
template <class Wrap>
std::optional<Placement> emit_rule_leaf(ComplexBuilder& builder, TemplateCache& cache, const TransitionRule& rule,
                                        const LeafContext& context, const LatticePoint& origin,
                                        const LatticePoint& corner, std::int64_t size, Wrap&& wrap,
                                        std::vector<VertexHandle>& vertices, std::vector<VertexHandle>& loop,
                                        std::vector<HalfFaceHandle>& halffaces) {
    std::optional<Placement> placement = rule.place(context);
    if (!placement) {
        emit(builder, cache.hex(size), corner, 1, wrap, vertices, loop, halffaces);
        return placement;
    }
    check_placement_symmetry(*placement);
    const ElementTemplate& t = cache.placed(cache.element_index(placement->element), world_symmetry(context, *placement));
    emit(builder, t, origin, size / cache.unit(), wrap, vertices, loop, halffaces);
    return placement;
}

}  // namespace dualhex::detail
