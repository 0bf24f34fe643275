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
// level-0 leaves of 2U). level_at(p): the level of the octant cube containing lattice point p
// (any p: the contexts reach beyond the built cubes); wrap: lattice point -> key.
template <class LevelAt, class Wrap>
detail::ConfigurationParts assemble_levels(int first, int n_octants, LevelAt&& level_at, Wrap&& wrap, std::int64_t U,
                                     detail::TemplateCache& cache, const TransitionRule& rule) {
    const std::int64_t octant = 4 * U;
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
                    for (int i = -2; i <= 1; ++i)
                        for (int j = -2; j <= 1; ++j)
                            for (int k = -2; k <= 1; ++k) {
                                const int local[3] = {i, j, k};
                                LatticePoint w;
                                for (int a = 0; a < 3; ++a)
                                    w[a] = ctx.application_point[a] + (ctx.direction[static_cast<std::size_t>(a)] > 0
                                                                           ? 2 * size * local[a]
                                                                           : -2 * size * (local[a] + 1));
                                if (level_at(w) > lv) ctx.set_fine(i, j, k);
                            }
                    for (int a = 0; a < 3; ++a) {  // the leaf-sized cell across each inner edge
                        LatticePoint w;
                        for (int t = 0; t < 3; ++t) {
                            const int local = t == a ? 0 : -1;
                            w[t] = ctx.application_point[t] +
                                   (ctx.direction[static_cast<std::size_t>(t)] > 0 ? size * local : -size * (local + 1));
                        }
                        if (level_at(w) > lv + 1) ctx.set_two_finer_across_edge(a);
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
    const auto level_at = [&](const LatticePoint& p) {
        return level(static_cast<int>(floor_mod(p.x, period) / octant), static_cast<int>(floor_mod(p.y, period) / octant),
                     static_cast<int>(floor_mod(p.z, period) / octant));
    };
    return assemble_levels(0, n_octants, level_at, wrap, U, cache, rule);
}

ConfigurationComplex build_periodic_levels(const std::function<int(int, int, int)>& level, int n_octants,
                                           const TransitionRule& rule, const ElementLibrary& library) {
    detail::TemplateCache cache(library);
    return detail::complete(detail::periodic_levels_parts(level, n_octants, rule, cache));
}

detail::ConfigurationParts detail::window_levels_parts(const std::array<int, 8>& levels, const TransitionRule& rule,
                                                       TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    const std::int64_t octant = 4 * U;
    // The window: the 8 octant cubes around P = origin (indices -1, 0); beyond, the nearest.
    const auto level_at = [&](const LatticePoint& p) {
        int b = 0;
        for (int a = 0; a < 3; ++a)
            if (p[a] >= 0) b |= 1 << a;
        (void)octant;
        return levels[static_cast<std::size_t>(b)];
    };
    return assemble_levels(-1, 2, level_at, [](const LatticePoint& p) { return p; }, U, cache, rule);
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
