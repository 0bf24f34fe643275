#include <algorithm>
#include <array>
#include <functional>
#include <span>
#include <sstream>
#include <stdexcept>

#include "dualhex/install/element_templates.hpp"
#include "configuration_parts.hpp"
#include "window_check.hpp"
#include "dualhex/checkers/cube_window.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

std::string format_histogram(const std::map<int, std::size_t>& histogram) {
    std::string out = "{";
    for (const auto& [k, n] : histogram) {
        if (out.size() > 1) out += ", ";
        out += std::to_string(k) + ":" + std::to_string(n);
    }
    return out + "}";
}

std::string format_mask(std::uint8_t mask) {
    std::string out = "0b";
    for (int b = 7; b >= 0; --b) out += ((mask >> b) & 1) ? '1' : '0';
    return out;
}

std::string ConfigurationReport::summary() const {
    std::ostringstream os;
    os << format_mask(mask) << ' ';
    if (!built) {
        os << "ERROR " << error;
        return os.str();
    }
    os << (ok() ? "ok" : "FAIL") << " cells " << cells << " faces " << faces << " checked vertices " << checked_vertices
       << " hexes " << hexes << " violations " << validation.violations.size()
       << " open faces " << open_faces << " F " << format_histogram(face_sizes)
       << " dual " << format_histogram(dual_edge_valences) << " elements {";
    bool first = true;
    for (const auto& [name, n] : elements) {
        os << (first ? "" : ", ") << name << ':' << n;
        first = false;
    }
    os << '}';
    return os.str();
}

namespace {

using Index3 = detail::Index3;
using detail::check;
using detail::check_window;
using detail::floor_mod;

// Builds the complex of a configuration: `octants` are the octant cubes (min corner 2*o)
// that are built; `fine(o)` the status of any octant cube (for contexts); `wrap` maps
// lattice points to keys.
template <class Fine, class Wrap>
detail::ConfigurationParts assemble(std::uint8_t mask, const std::vector<Index3>& octants, Fine&& fine, Wrap&& wrap,
                                    const TransitionRule& rule, detail::TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    ConfigurationComplex out;
    out.mask = mask;
    out.unit = U;
    ComplexBuilder builder;
    std::vector<VertexHandle> vs, loop;
    std::vector<HalfFaceHandle> hfs;
    const detail::ElementTemplate& fine_hex = cache.hex(U / 2);
    for (const Index3& o : octants) {
        const LatticePoint lo{2 * o[0], 2 * o[1], 2 * o[2]};
        if (fine(o)) {
            for (int c = 0; c < 64; ++c) {
                const LatticePoint at = lo * U + LatticePoint{c & 3, (c >> 2) & 3, (c >> 4) & 3} * (U / 2);
                detail::emit(builder, fine_hex, at, 1, wrap, vs, loop, hfs);
                ++out.fine_hexes;
            }
            continue;
        }
        for (int c = 0; c < 8; ++c) {
            PlacedLeaf leaf;
            leaf.leaf = lo + LatticePoint{c & 1, (c >> 1) & 1, (c >> 2) & 1};
            leaf.context = detail::coarse_leaf_context(leaf.leaf, fine);
            leaf.placement = detail::emit_rule_leaf(builder, cache, rule, leaf.context, leaf.context.application_point * U,
                                                    leaf.leaf * U, U, wrap, vs, loop, hfs);
            out.coarse_leaves.push_back(std::move(leaf));
        }
    }
    return detail::parts_of(std::move(out), std::move(builder));
}

}  // namespace

detail::ConfigurationParts detail::periodic_configuration_parts(std::uint8_t mask, const TransitionRule& rule,
                                                                TemplateCache& cache) {
    std::vector<Index3> octants;
    for (int b = 0; b < 8; ++b) octants.push_back({b & 1, (b >> 1) & 1, (b >> 2) & 1});
    const auto fine = [mask](const Index3& o) {
        const int b = static_cast<int>(floor_mod(o[0], 2) | floor_mod(o[1], 2) << 1 | floor_mod(o[2], 2) << 2);
        return ((mask >> b) & 1) != 0;
    };
    const std::int64_t period = 4 * cache.unit();
    const auto wrap = [period](const LatticePoint& p) {
        return LatticePoint{floor_mod(p.x, period), floor_mod(p.y, period), floor_mod(p.z, period)};
    };
    return assemble(mask, octants, fine, wrap, rule, cache);
}

ConfigurationComplex build_periodic_configuration(std::uint8_t mask, const TransitionRule& rule,
                                                  const ElementLibrary& library) {
    detail::TemplateCache cache(library);
    return detail::complete(detail::periodic_configuration_parts(mask, rule, cache));
}

ConfigurationReport check_periodic_configuration(std::uint8_t mask, const TransitionRule& rule,
                                                 const ElementLibrary& library) {
    return check(mask, [&] { return build_periodic_configuration(mask, rule, library); },
                 [](const LatticePoint&) { return true; }, [](const CellComplex&, std::span<const VertexHandle>) { return false; });
}

detail::ConfigurationParts detail::cube_window_parts(std::uint8_t mask, const TransitionRule& rule,
                                                     TemplateCache& cache) {
    std::vector<Index3> octants;
    for (int b = 0; b < 8; ++b) octants.push_back({(b & 1) - 1, ((b >> 1) & 1) - 1, ((b >> 2) & 1) - 1});
    // Octant index o (min corner 2o): -1 is the -side, 0 the +side; beyond, the nearest.
    const auto fine = [mask](const Index3& o) {
        const int b = (o[0] >= 0 ? 1 : 0) | (o[1] >= 0 ? 2 : 0) | (o[2] >= 0 ? 4 : 0);
        return ((mask >> b) & 1) != 0;
    };
    return assemble(mask, octants, fine, [](const LatticePoint& p) { return p; }, rule, cache);
}

ConfigurationComplex build_cube_window(std::uint8_t mask, const TransitionRule& rule, const ElementLibrary& library) {
    detail::TemplateCache cache(library);
    return detail::complete(detail::cube_window_parts(mask, rule, cache));
}

// Three-level assembly over octant cubes first..first+n-1 per axis (octant cube = 4U: two
// level-0 leaves of 2U); wrap: lattice point -> key. The levels are separable by axis:
// cell_along(a, x) is the index along axis a of the octant cube holding coordinate x (any x:
// the contexts reach beyond the built cubes) and level_of(cell) that cube's level. A leaf's
// 64 context cubes differ along each axis in only 4 ways, so 12 indices per leaf are
// computed instead of 3 for each of 67 points (with two integer divisions each).
template <class CellAlong, class LevelOf, class Wrap>
detail::ConfigurationParts assemble_levels(int first, int n_octants, CellAlong&& cell_along, LevelOf&& level_of, Wrap&& wrap,
                                           std::int64_t U, detail::TemplateCache& cache, const TransitionRule& rule) {
    const std::int64_t octant = 4 * U;
    const auto level_at = [&](const LatticePoint& p) {
        return level_of(std::array<int, 3>{cell_along(0, p.x), cell_along(1, p.y), cell_along(2, p.z)});
    };
    ConfigurationComplex out;
    out.unit = U;
    ComplexBuilder builder;
    std::vector<VertexHandle> vs, loop;
    std::vector<HalfFaceHandle> hfs;
    for (int ox = first; ox < first + n_octants; ++ox)
        for (int oy = first; oy < first + n_octants; ++oy)
            for (int oz = first; oz < first + n_octants; ++oz) {
                const int lv = level_at(LatticePoint{ox * octant, oy * octant, oz * octant});
                if (lv < 0 || lv > 2) throw std::invalid_argument("build_periodic_levels: level must be 0, 1 or 2");
                const LatticePoint lo{ox * octant, oy * octant, oz * octant};
                const std::int64_t size = (2 * U) >> lv;  // leaf size at this level
                const std::int64_t n = octant / size;
                for (std::int64_t c = 0; c < n * n * n; ++c) {
                    const LatticePoint at = lo + LatticePoint{c % n, (c / n) % n, c / (n * n)} * size;
                    if (lv == 2) {
                        detail::emit(builder, cache.hex(size), at, 1, wrap, vs, loop, hfs);
                        ++out.fine_hexes;
                        continue;
                    }
                    PlacedLeaf leaf;
                    leaf.leaf = at;
                    LeafContext& ctx = leaf.context;
                    for (int a = 0; a < 3; ++a) {
                        const bool even = floor_mod(at[a], 2 * size) == 0;
                        ctx.application_point[a] = even ? at[a] : at[a] + size;
                        ctx.direction[static_cast<std::size_t>(a)] = even ? 1 : -1;
                    }
                    // Along axis a, the cube at local offset l (-2..1, entry l + 2) of the
                    // context and the leaf-sized cell at local 0 / -1 (entry 0 / 1) of the edge test.
                    std::array<std::array<int, 4>, 3> context_cell{};
                    std::array<std::array<int, 2>, 3> edge_cell{};
                    for (int a = 0; a < 3; ++a) {
                        const std::int64_t p = ctx.application_point[a];
                        const bool up = ctx.direction[static_cast<std::size_t>(a)] > 0;
                        for (int l = -2; l <= 1; ++l)
                            context_cell[static_cast<std::size_t>(a)][static_cast<std::size_t>(l + 2)] =
                                cell_along(a, p + (up ? 2 * size * l : -2 * size * (l + 1)));
                        for (int l = 0; l >= -1; --l)
                            edge_cell[static_cast<std::size_t>(a)][static_cast<std::size_t>(-l)] =
                                cell_along(a, p + (up ? size * l : -size * (l + 1)));
                    }
                    for (int i = -2; i <= 1; ++i)
                        for (int j = -2; j <= 1; ++j)
                            for (int k = -2; k <= 1; ++k)
                                if (level_of(std::array<int, 3>{context_cell[0][static_cast<std::size_t>(i + 2)],
                                                                context_cell[1][static_cast<std::size_t>(j + 2)],
                                                                context_cell[2][static_cast<std::size_t>(k + 2)]}) > lv)
                                    ctx.set_fine(i, j, k);
                    for (int a = 0; a < 3; ++a) {  // the leaf-sized cell across each inner edge
                        std::array<int, 3> cell{};
                        for (std::size_t t = 0; t < 3; ++t) cell[t] = edge_cell[t][static_cast<int>(t) == a ? 0 : 1];
                        if (level_of(cell) > lv + 1) ctx.set_two_finer_across_edge(a);
                    }
                    leaf.placement = detail::emit_rule_leaf(builder, cache, rule, ctx, ctx.application_point, at, size,
                                                            wrap, vs, loop, hfs);
                    out.coarse_leaves.push_back(std::move(leaf));
                }
            }
    return detail::parts_of(std::move(out), std::move(builder));
}

detail::ConfigurationParts detail::periodic_levels_parts(const std::function<int(int, int, int)>& level, int n_octants,
                                                         const TransitionRule& rule, TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    const std::int64_t octant = 4 * U;
    const std::int64_t period = n_octants * octant;
    const auto wrap = [period](const LatticePoint& p) {
        return LatticePoint{floor_mod(p.x, period), floor_mod(p.y, period), floor_mod(p.z, period)};
    };
    // The level of each of the n^3 octant cubes, asked once each (every one is built).
    const auto n = static_cast<std::size_t>(std::max(n_octants, 0));
    std::vector<int> levels(n * n * n);
    for (std::size_t x = 0; x < n; ++x)
        for (std::size_t y = 0; y < n; ++y)
            for (std::size_t z = 0; z < n; ++z)
                levels[(x * n + y) * n + z] = level(static_cast<int>(x), static_cast<int>(y), static_cast<int>(z));
    const auto cell_along = [&](int, std::int64_t x) { return static_cast<int>(floor_mod(x, period) / octant); };
    const auto level_of = [&](const std::array<int, 3>& c) {
        return levels[(static_cast<std::size_t>(c[0]) * n + static_cast<std::size_t>(c[1])) * n + static_cast<std::size_t>(c[2])];
    };
    return assemble_levels(0, n_octants, cell_along, level_of, wrap, U, cache, rule);
}

ConfigurationComplex build_periodic_levels(const std::function<int(int, int, int)>& level, int n_octants,
                                           const TransitionRule& rule, const ElementLibrary& library) {
    detail::TemplateCache cache(library);
    return detail::complete(detail::periodic_levels_parts(level, n_octants, rule, cache));
}

detail::ConfigurationParts detail::window_levels_parts(const std::array<int, 8>& levels, const TransitionRule& rule,
                                                       TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    // The window: the 8 octant cubes around P = origin (indices -1, 0); beyond, the nearest:
    // along each axis, cell 1 on the + side (x >= 0), else 0.
    const auto cell_along = [](int, std::int64_t x) { return x >= 0 ? 1 : 0; };
    const auto level_of = [&](const std::array<int, 3>& c) {
        return levels[static_cast<std::size_t>(c[0] | c[1] << 1 | c[2] << 2)];
    };
    return assemble_levels(-1, 2, cell_along, level_of, [](const LatticePoint& p) { return p; }, U, cache, rule);
}

ConfigurationComplex build_window_levels(const std::array<int, 8>& levels, const TransitionRule& rule,
                                         const ElementLibrary& library) {
    detail::TemplateCache cache(library);
    return detail::complete(detail::window_levels_parts(levels, rule, cache));
}

ConfigurationReport check_periodic_levels(const std::function<int(int, int, int)>& level, int n_octants,
                                          const TransitionRule& rule, const ElementLibrary& library) {
    return check(0, [&] { return build_periodic_levels(level, n_octants, rule, library); },
                 [](const LatticePoint&) { return true; }, [](const CellComplex&, std::span<const VertexHandle>) { return false; });
}

ConfigurationReport check_window_levels(const std::array<int, 8>& levels, const TransitionRule& rule,
                                        const ElementLibrary& library) {
    // two octant cubes of 4U: the window is [-4U, 4U]^3
    return check_window(0, 4 * detail::common_unit(library), [&] { return build_window_levels(levels, rule, library); });
}

ConfigurationReport check_cube_window(std::uint8_t mask, const TransitionRule& rule, const ElementLibrary& library) {
    return check_window(mask, 2 * detail::common_unit(library), [&] { return build_cube_window(mask, rule, library); });
}

}  // namespace dualhex
