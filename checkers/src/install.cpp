#include "dualhex/checkers/install.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>

#include "assembly.hpp"
#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

namespace {

// Reflect a cell coordinate across the root faces until it lies in [0, n).
std::int64_t mirror(std::int64_t c, std::int64_t n) {
    while (c < 0 || c >= n) c = c < 0 ? -1 - c : 2 * n - 1 - c;
    return c;
}

// The leaf's application point and direction (level-L units).
void frame_of(const Leaf& leaf, LeafContext& ctx) {
    for (int a = 0; a < 3; ++a) {
        const std::int64_t x = leaf.coord(a);
        const bool even = (x & 1) == 0;
        ctx.application_point[a] = even ? x : x + 1;
        ctx.direction[static_cast<std::size_t>(a)] = even ? 1 : -1;
    }
}

// Weak balance: for each inner edge of the leaf whose two adjacent faces are interfaces,
// is the leaf-sized cell sharing that edge (its diagonal neighbour) refined twice, i.e. does
// it hold leaves two or more levels finer? (Pairing: a cell's children are all leaves or all
// subdivided, so its first child tells.) Only concave edges can need it, so only they are
// looked up.
void set_edge_two_finer(const LeafGrid& grid, const Leaf& leaf, OutsideRoot outside, LeafContext& ctx) {
    const std::int64_t cells = std::int64_t{1} << leaf.level;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        int fb[3] = {0, 0, 0}, fc[3] = {0, 0, 0};
        fb[b] = -1;
        fc[c] = -1;
        if (!ctx.fine(fb[0], fb[1], fb[2]) || !ctx.fine(fc[0], fc[1], fc[2])) continue;
        Leaf cell{leaf.level, 0, 0, 0};
        bool inside = true;
        for (int t = 0; t < 3; ++t) {
            const int local = t == a ? 0 : -1;
            std::int64_t x = ctx.application_point[t] +
                             (ctx.direction[static_cast<std::size_t>(t)] > 0 ? local : -local - 1);
            if (x < 0 || x >= cells) {
                inside = false;
                x = mirror(x, cells);
            }
            (t == 0 ? cell.i : t == 1 ? cell.j : cell.k) = x;
        }
        if (!inside && outside == OutsideRoot::Coarse) continue;
        if (grid.is_subdivided(cell) && grid.is_subdivided(children(cell)[0])) ctx.set_two_finer_across_edge(a);
    }
}

// World neighbourhood masks per (level L, application point / 2), for every application
// point some fine octant cube reaches (absent: all coarse).
class ContextIndex {
public:
    ContextIndex(const LeafGrid& grid, OutsideRoot outside)
        : grid_(&grid), outside_(outside), masks_(grid.size() / 4 + 16) {
        for (const Leaf& node : grid.interior_nodes()) {
            if (node.level == 0 || child_index(node) != 0) continue;
            // Leaves of level node.level see parent(node) as a fine octant cube (pairing: all
            // of node's siblings are subdivided too).
            scatter(masks_, node.level, parent(node));
        }
    }

    [[nodiscard]] LeafContext context(const Leaf& leaf) const {
        LeafContext ctx;
        if (leaf.level == 0) return ctx;
        frame_of(leaf, ctx);
        const LatticePoint& P = ctx.application_point;
        if (const std::uint64_t* m = masks_.find(Leaf{leaf.level, P.x / 2, P.y / 2, P.z / 2}))
            ctx.neighbourhood = to_local_neighbourhood(*m, ctx.direction);
        set_edge_two_finer(*grid_, leaf, outside_, ctx);
        return ctx;
    }

private:
    // Marks octant cube c (level L - 1) in the masks of the level-L application points
    // whose 4x4x4 neighbourhood contains it (and its mirror images across the root faces).
    void scatter(CellMap<std::uint64_t>& masks, int L, const Leaf& c) {
        const std::int64_t n = std::int64_t{1} << (L - 1);
        std::array<std::array<std::int64_t, 5>, 3> images{};
        std::array<int, 3> count{};
        for (int a = 0; a < 3; ++a) {
            auto& img = images[static_cast<std::size_t>(a)];
            int& k = count[static_cast<std::size_t>(a)];
            img[static_cast<std::size_t>(k++)] = c.coord(a);
            if (outside_ == OutsideRoot::Mirror)
                for (std::int64_t x : {std::int64_t{-2}, std::int64_t{-1}, n, n + 1})
                    if (mirror(x, n) == c.coord(a) && x != c.coord(a)) img[static_cast<std::size_t>(k++)] = x;
        }
        for (int ix = 0; ix < count[0]; ++ix)
            for (int iy = 0; iy < count[1]; ++iy)
                for (int iz = 0; iz < count[2]; ++iz) {
                    const std::int64_t cx = images[0][static_cast<std::size_t>(ix)],
                                       cy = images[1][static_cast<std::size_t>(iy)],
                                       cz = images[2][static_cast<std::size_t>(iz)];
                    for (int w = 0; w < 64; ++w) {
                        const std::int64_t vx = cx - ((w & 3) - 2), vy = cy - (((w >> 2) & 3) - 2),
                                           vz = cz - (((w >> 4) & 3) - 2);
                        if (vx < 0 || vy < 0 || vz < 0 || vx > n || vy > n || vz > n) continue;
                        *masks.insert(Leaf{L, vx, vy, vz}, 0).first |= std::uint64_t{1} << w;
                    }
                }
    }

    const LeafGrid* grid_;
    OutsideRoot outside_;
    CellMap<std::uint64_t> masks_;
};

// Welds the points on finest-level grid corners (multiples of the unit U inside the root)
// through a dense array indexed by corner, every other point through the builder's hash
// table. The two sets are disjoint, so every point still gets exactly one vertex, numbered
// in first-use order as before; but corners, most of the points, are found where the leaf
// order puts them (the array is in the leaves' lexicographic order) instead of at random
// slots of a large table. Off for grids whose corner array would dwarf the grid (deep,
// sparse ones): then everything is hashed.
class CornerWelder {
public:
    CornerWelder(ComplexBuilder& builder, std::int64_t unit, int max_level, std::size_t n_leaves)
        : builder_(&builder), unit_(unit) {
        if (max_level > 20) return;
        const auto n1 = static_cast<std::uint64_t>((std::int64_t{1} << max_level) + 1);
        const std::uint64_t corners = n1 * n1 * n1;
        if (corners > std::max<std::uint64_t>(std::uint64_t{1} << 22, 16 * static_cast<std::uint64_t>(n_leaves))) return;
        // calloc: untouched parts of the array cost no memory (fresh zero pages).
        ids_.reset(static_cast<std::uint32_t*>(std::calloc(corners, sizeof(std::uint32_t))));
        if (ids_) n1_ = static_cast<std::int64_t>(n1);
    }

    [[nodiscard]] bool dense() const { return ids_ != nullptr; }

    /// The vertex at finest-level corner (x, y, z), i.e. at the point U * (x, y, z).
    VertexHandle corner(std::int64_t x, std::int64_t y, std::int64_t z) {
        const LatticePoint p{x * unit_, y * unit_, z * unit_};
        if (!ids_ || x < 0 || y < 0 || z < 0 || x >= n1_ || y >= n1_ || z >= n1_) return builder_->add_vertex(p);
        std::uint32_t& id = ids_.get()[static_cast<std::size_t>((x * n1_ + y) * n1_ + z)];
        if (id == 0) id = static_cast<std::uint32_t>(builder_->add_vertex_unwelded(p).idx) + 1;
        return VertexHandle(static_cast<std::int32_t>(id - 1));
    }

    VertexHandle operator()(const LatticePoint& p) {
        if (ids_ && p.x % unit_ == 0 && p.y % unit_ == 0 && p.z % unit_ == 0)
            return corner(p.x / unit_, p.y / unit_, p.z / unit_);
        return builder_->add_vertex(p);
    }

private:
    struct Free {
        void operator()(std::uint32_t* p) const { std::free(p); }
    };
    ComplexBuilder* builder_;
    std::int64_t unit_;
    std::int64_t n1_ = 0;
    std::unique_ptr<std::uint32_t, Free> ids_;
};

}  // namespace

std::map<std::string, std::size_t> InstallResult::elements_used() const {
    std::map<std::string, std::size_t> out;
    for (std::int16_t e : leaf_element) ++out[e < 0 ? std::string("hex") : element_names[static_cast<std::size_t>(e)]];
    return out;
}

InstallCheck check_installable(const LeafGrid& grid, Balance balance) {
    GridCheck c = is_paired(grid);
    if (c.ok) c = is_balanced(grid, balance);
    if (c.ok) return {};
    return {false, "cannot install: " + c.message, c.first, c.second};
}

std::vector<LeafContext> leaf_contexts(const LeafGrid& grid, OutsideRoot outside) {
    const ContextIndex index(grid, outside);
    std::vector<LeafContext> out;
    out.reserve(grid.size());
    for (const Leaf& leaf : grid.leaves()) out.push_back(index.context(leaf));
    return out;
}

LeafContext leaf_context(const LeafGrid& grid, std::size_t n, OutsideRoot outside) {
    const Leaf& leaf = grid.leaf(n);
    LeafContext ctx;
    if (leaf.level == 0) return ctx;
    frame_of(leaf, ctx);
    const std::int64_t cells = std::int64_t{1} << (leaf.level - 1);
    for (int i = -2; i <= 1; ++i)
        for (int j = -2; j <= 1; ++j)
            for (int k = -2; k <= 1; ++k) {
                const int local[3] = {i, j, k};
                Leaf cube{leaf.level - 1, 0, 0, 0};
                bool inside = true;
                for (int a = 0; a < 3; ++a) {
                    const int w = ctx.direction[static_cast<std::size_t>(a)] > 0 ? local[a] : -1 - local[a];
                    std::int64_t c = ctx.application_point[a] / 2 + w;
                    if (c < 0 || c >= cells) {
                        inside = false;
                        c = mirror(c, cells);
                    }
                    (a == 0 ? cube.i : a == 1 ? cube.j : cube.k) = c;
                }
                if (!inside && outside == OutsideRoot::Coarse) continue;
                bool fine = true;  // covered by leaves finer than the leaf: every child subdivided
                for (const Leaf& child : children(cube)) fine = fine && grid.is_subdivided(child);
                if (fine) ctx.set_fine(i, j, k);
            }
    set_edge_two_finer(grid, leaf, outside, ctx);
    return ctx;
}

InstallResult install(const LeafGrid& grid, const TransitionRule& rule, const ElementLibrary& library,
                      const InstallOptions& options) {
    if (const InstallCheck c = check_installable(grid, options.balance); !c.ok)
        throw InstallError(c.message, c.first, c.second);
    const ContextIndex index(grid, options.outside_root);
    detail::TemplateCache cache(library);
    InstallResult out;
    out.unit = cache.unit();
    out.max_level = grid.max_level();
    const std::int64_t U = out.unit;
    const std::size_t n_leaves = grid.size();
    out.leaf_cells.reserve(n_leaves + 1);
    out.leaf_cells.push_back(0);
    out.leaf_element.assign(n_leaves, -1);
    out.leaf_symmetry.assign(n_leaves, 0);

    ComplexBuilder builder;
    CornerWelder weld(builder, U, out.max_level, n_leaves);
    // With the corners welded densely, only element points off the corners are hashed.
    builder.reserve(n_leaves + n_leaves / 2, 4 * n_leaves, n_leaves + n_leaves / 2,
                    weld.dense() ? n_leaves / 8 : n_leaves + n_leaves / 2);
    std::vector<VertexHandle> vs, loop;
    std::vector<HalfFaceHandle> hfs;
    const detail::ElementTemplate& hex = cache.hex(U);
    std::string last_name;
    int last_index = -1;
    for (std::size_t n = 0; n < n_leaves; ++n) {
        const Leaf& leaf = grid.leaf(n);
        const std::int64_t s = std::int64_t{1} << (out.max_level - leaf.level);
        const LeafContext ctx = index.context(leaf);
        std::optional<Placement> placement;
        try {
            placement = rule.place(ctx);
            if (placement) {
                detail::check_placement_symmetry(*placement);
                if (last_index < 0 || placement->element != last_name) {
                    last_index = cache.element_index(placement->element);
                    last_name = placement->element;
                }
            }
        } catch (const std::exception& e) {
            throw InstallError("leaf " + grid.describe(n) + ": " + e.what(), n);
        }
        if (placement) {
            const CubeSymmetry world = world_symmetry(ctx, *placement);
            out.leaf_element[n] = static_cast<std::int16_t>(last_index);
            out.leaf_symmetry[n] = static_cast<std::int8_t>(world.index());
            detail::emit_welded(builder, cache.placed(last_index, world), ctx.application_point * (U * s), s, weld, vs,
                                loop, hfs);
        } else {
            // The hex template's point c is the leaf corner (c & 1, c >> 1 & 1, c >> 2 & 1).
            vs.resize(8);
            for (std::int64_t c = 0; c < 8; ++c)
                vs[static_cast<std::size_t>(c)] =
                    weld.corner((leaf.i + (c & 1)) * s, (leaf.j + (c >> 1 & 1)) * s, (leaf.k + (c >> 2 & 1)) * s);
            detail::emit_cells(builder, hex, vs, loop, hfs);
        }
        out.leaf_cells.push_back(static_cast<std::uint32_t>(builder.n_cells()));
    }
    out.element_names = cache.element_names();
    out.complex = std::move(builder).build();
    return out;
}

std::string InstallVerification::summary() const {
    std::string out = ok() ? "ok" : "FAIL";
    out += ": " + std::to_string(validation.violations.size()) + " violations, " + std::to_string(open_faces) +
           " open faces, " + std::to_string(hexes) + "/" + std::to_string(interior_vertices) + " interior vertices with a cube dual";
    for (std::size_t k = 0; k < kViolationKinds; ++k)
        if (validation.per_kind[k] > 0)
            out += std::string(", ") + to_string(static_cast<ViolationKind>(k)) + " " + std::to_string(validation.per_kind[k]);
    return out;
}

InstallVerification verify_installation(const InstallResult& installed) {
    InstallVerification v;
    const CellComplex& cx = installed.complex;
    const std::int64_t extent = installed.unit << installed.max_level;
    v.validation = validate(cx);
    const Incidence inc(cx);
    const auto inside = [extent](const LatticePoint& p) {
        for (int a = 0; a < 3; ++a)
            if (p[a] <= 0 || p[a] >= extent) return false;
        return true;
    };
    const auto on_surface = [extent](const CellComplex& c, std::span<const VertexHandle> loop) {
        for (int a = 0; a < 3; ++a)
            for (std::int64_t side : {std::int64_t{0}, extent}) {
                bool all = true;
                for (VertexHandle w : loop) all = all && c.position(w)[a] == side;
                if (all) return true;
            }
        return false;
    };
    v.open_faces = detail::check_open_faces(cx, inc, inside, on_surface, v.validation);
    const DualResult dual = interior_dual(cx, inc);
    v.hexes = dual.mesh.hexes.size();
    v.interior_vertices = v.hexes + dual.errors.size();
    v.face_sizes = face_size_histogram(cx);
    v.dual_edge_valences = interior_dual_edge_valence_histogram(cx, inc);
    return v;
}

}  // namespace dualhex
