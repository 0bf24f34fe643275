// install(): every leaf becomes the rule's placed element or a plain hex, welded by
// exact lattice keys into one CellComplex (install.hpp).
#include "dualhex/install/install.hpp"

#include "context_index.hpp"
#include "corner_welder.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/install/element_templates.hpp"
#include "dualhex/topology/complex_builder.hpp"

namespace dualhex {

using detail::ContextIndex;
using detail::CornerWelder;

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

}  // namespace dualhex
