// install(): every leaf becomes the rule's placed element or a plain hex, welded by
// exact lattice keys into one CellComplex (install.hpp).
//
// Three steps. (1) In parallel, each leaf's context and placement (a leaf's element depends
// only on its context, so leaves are independent); the first failing leaf in leaf order is
// the error, as in a serial run. (2) A serial pass numbers the elements in first-use order
// and makes their templates. (3) The welding: with one thread one builder in leaf order;
// with more, chunks of leaves welded in parallel and merged to the same numbering
// (chunked_weld.hpp). Either way the complex does not depend on the number of threads.
#include "dualhex/install/install.hpp"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdint>
#include <functional>
#include <mutex>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "chunked_weld.hpp"
#include "context_index.hpp"
#include "corner_welder.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/install/element_templates.hpp"
#include "dualhex/schemes/element_library.hpp"
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

namespace {

// Leaves per welding chunk: a few chunks per thread, 64..8192 leaves (any size gives the
// same complex; chunked_weld.hpp).
std::size_t chunk_leaves(std::size_t n_leaves, int threads) {
    return std::clamp<std::size_t>(n_leaves / (8 * static_cast<std::size_t>(threads)), 64, 8192);
}

// Step 1: per leaf, the library index of its element (-1: plain hex) and the world symmetry.
struct LeafPlan {
    std::int16_t element = -1;
    std::int8_t world = 0;
};

// context(n) is leaf n's context, describe(n) names it in an error.
template <class Context, class Describe>
std::vector<LeafPlan> plan_leaves(std::size_t n_leaves, const TransitionRule& rule, const ElementLibrary& library,
                                  const Context& context, const Describe& describe) {
    std::unordered_map<std::string, int> by_name;
    for (std::size_t e = 0; e < library.elements().size(); ++e) by_name.emplace(library.elements()[e].name, static_cast<int>(e));
    std::vector<LeafPlan> plans(n_leaves);
    std::atomic<std::size_t> first_error{n_leaves};
    std::mutex error_mutex;
    std::string error;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_leaves, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t n = r.begin(); n != r.end() && n < first_error.load(std::memory_order_relaxed); ++n) {
            try {
                const LeafContext ctx = context(n);
                const std::optional<Placement> placement = rule.place(ctx);
                if (!placement) continue;
                detail::check_placement_symmetry(*placement);
                const auto it = by_name.find(placement->element);
                if (it == by_name.end()) (void)library.at(placement->element);  // throws, naming the known elements
                plans[n] = {static_cast<std::int16_t>(it->second), static_cast<std::int8_t>(world_symmetry(ctx, *placement).index())};
            } catch (const std::exception& e) {
                const std::lock_guard lock(error_mutex);
                if (n < first_error.load()) {
                    first_error.store(n);
                    error = e.what();
                }
            }
        }
    });
    if (const std::size_t n = first_error.load(); n < n_leaves) throw InstallError("leaf " + describe(n) + ": " + error, n);
    return plans;
}

// Step 2 and the per-leaf emission of step 3.
class LeafEmitter {
public:
    LeafEmitter(const std::vector<Leaf>& leaves, int max_level, const ElementLibrary& library,
                const std::vector<LeafPlan>& plans, detail::TemplateCache& cache, InstallResult& out)
        : leaves_(&leaves), unit_(cache.unit()), max_level_(max_level), hex_(&cache.hex(cache.unit())) {
        std::vector<int> first_use(library.elements().size(), -1);
        out.leaf_element.assign(plans.size(), -1);
        out.leaf_symmetry.assign(plans.size(), 0);
        for (std::size_t n = 0; n < plans.size(); ++n) {
            const LeafPlan& p = plans[n];
            if (p.element < 0) continue;
            int& e = first_use[static_cast<std::size_t>(p.element)];
            if (e < 0) {
                e = cache.element_index(library.elements()[static_cast<std::size_t>(p.element)].name);
                templates_.resize(static_cast<std::size_t>(e) + 1, {});
            }
            const ElementTemplate*& t = templates_[static_cast<std::size_t>(e)][static_cast<std::size_t>(p.world)];
            if (!t) t = &cache.placed(e, CubeSymmetry::from_index(p.world));
            out.leaf_element[n] = static_cast<std::int16_t>(e);
            out.leaf_symmetry[n] = p.world;
        }
        out.element_names = cache.element_names();
        elements_ = &out.leaf_element;
        symmetries_ = &out.leaf_symmetry;
    }

    /// Leaf n's cells, each point welded by `weld(point)` (hex corners by `corner(x, y, z)`,
    /// finest-level corner indices).
    template <class Weld, class Corner>
    void emit(ComplexBuilder& builder, std::size_t n, Weld&& weld, Corner&& corner) const {
        thread_local std::vector<VertexHandle> vs, loop;
        thread_local std::vector<HalfFaceHandle> hfs;
        const Leaf& leaf = (*leaves_)[n];
        const std::int64_t s = std::int64_t{1} << (max_level_ - leaf.level);
        const std::int16_t e = (*elements_)[n];
        if (e >= 0) {
            LeafContext frame;
            if (leaf.level > 0) detail::frame_of(leaf, frame);
            const ElementTemplate& t = *templates_[static_cast<std::size_t>(e)][static_cast<std::size_t>((*symmetries_)[n])];
            detail::emit_welded(builder, t, frame.application_point * (unit_ * s), s, weld, vs, loop, hfs);
            return;
        }
        // The hex template's point c is the leaf corner (c & 1, c >> 1 & 1, c >> 2 & 1).
        vs.resize(8);
        for (std::int64_t c = 0; c < 8; ++c)
            vs[static_cast<std::size_t>(c)] =
                corner((leaf.i + (c & 1)) * s, (leaf.j + (c >> 1 & 1)) * s, (leaf.k + (c >> 2 & 1)) * s);
        detail::emit_cells(builder, *hex_, vs, loop, hfs);
    }

    [[nodiscard]] std::int64_t unit() const { return unit_; }

private:
    using ElementTemplate = detail::ElementTemplate;
    const std::vector<Leaf>* leaves_;
    std::int64_t unit_;
    int max_level_;
    const ElementTemplate* hex_;
    std::vector<std::array<const ElementTemplate*, 48>> templates_;  // per first-use element, per world symmetry
    const std::vector<std::int16_t>* elements_ = nullptr;
    const std::vector<std::int8_t>* symmetries_ = nullptr;
};

// Step 3 with one thread: one builder, grid corners welded densely (corner_welder.hpp).
CellComplex weld_serial(const LeafEmitter& emitter, std::size_t n_leaves, int max_level, std::vector<std::uint32_t>& leaf_cells) {
    ComplexBuilder builder;
    CornerWelder weld(builder, emitter.unit(), max_level, n_leaves);
    // With the corners welded densely, only element points off the corners are hashed.
    builder.reserve(n_leaves + n_leaves / 2, 4 * n_leaves, n_leaves + n_leaves / 2,
                    weld.dense() ? n_leaves / 8 : n_leaves + n_leaves / 2);
    leaf_cells.reserve(n_leaves + 1);
    leaf_cells.push_back(0);
    const auto corner = [&](std::int64_t x, std::int64_t y, std::int64_t z) { return weld.corner(x, y, z); };
    for (std::size_t n = 0; n < n_leaves; ++n) {
        emitter.emit(builder, n, weld, corner);
        leaf_cells.push_back(static_cast<std::uint32_t>(builder.n_cells()));
    }
    return std::move(builder).build();
}

// The finest-level corner indices spanned by leaves [begin, end) (inclusive box).
std::pair<std::array<std::int64_t, 3>, std::array<std::int64_t, 3>> corner_box(const std::vector<Leaf>& leaves, std::size_t begin,
                                                                                std::size_t end, int max_level) {
    std::array<std::int64_t, 3> lo{INT64_MAX, INT64_MAX, INT64_MAX}, hi{INT64_MIN, INT64_MIN, INT64_MIN};
    for (std::size_t n = begin; n < end; ++n) {
        const Leaf& leaf = leaves[n];
        const std::int64_t s = std::int64_t{1} << (max_level - leaf.level);
        const std::array<std::int64_t, 3> at{leaf.i * s, leaf.j * s, leaf.k * s};
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], at[a]);
            hi[a] = std::max(hi[a], at[a] + s);
        }
    }
    return {lo, hi};
}

}  // namespace

InstallResult install(const LeafGrid& grid, const TransitionRule& rule, const ElementLibrary& library,
                      const InstallOptions& options) {
    if (const InstallCheck c = check_installable(grid, options.balance); !c.ok)
        throw InstallError(c.message, c.first, c.second);
    const ContextIndex index(grid, options.outside_root);
    const std::vector<LeafPlan> plans = plan_leaves(
        grid.size(), rule, library, [&](std::size_t n) { return index.context(grid.leaf(n)); },
        [&](std::size_t n) { return grid.describe(n); });
    detail::TemplateCache cache(library);
    InstallResult out;
    out.unit = cache.unit();
    out.max_level = grid.max_level();
    const LeafEmitter emitter(grid.leaves(), out.max_level, library, plans, cache, out);
    const std::size_t n_leaves = grid.size();
    const int threads = tbb::this_task_arena::max_concurrency();
    if (threads == 1) {
        out.complex = weld_serial(emitter, n_leaves, out.max_level, out.leaf_cells);
        return out;
    }
    const std::vector<Leaf>& leaves = grid.leaves();
    out.complex = detail::weld_chunks(
        n_leaves, chunk_leaves(n_leaves, threads),
        [&](ComplexBuilder& builder, std::size_t begin, std::size_t end, const std::function<void()>& leaf_done) {
            auto [lo, hi] = corner_box(leaves, begin, end, out.max_level);
            CornerWelder weld(builder, emitter.unit(), lo, hi, end - begin);
            const auto corner = [&](std::int64_t x, std::int64_t y, std::int64_t z) { return weld.corner(x, y, z); };
            for (std::size_t n = begin; n < end; ++n) {
                emitter.emit(builder, n, weld, corner);
                leaf_done();
            }
        },
        out.leaf_cells);
    return out;
}

InstallResult install_leaves(const std::vector<Leaf>& leaves, const std::vector<LeafContext>& contexts, int max_level,
                             const TransitionRule& rule, const ElementLibrary& library) {
    if (contexts.size() != leaves.size())
        throw std::invalid_argument("install_leaves: " + std::to_string(contexts.size()) + " contexts for " +
                                    std::to_string(leaves.size()) + " leaves");
    for (const Leaf& leaf : leaves)
        if (leaf.level > max_level) throw InstallError("leaf " + to_string(leaf) + " is finer than max_level " + std::to_string(max_level));
    const std::vector<LeafPlan> plans = plan_leaves(
        leaves.size(), rule, library, [&](std::size_t n) { return contexts[n]; },
        [&](std::size_t n) { return to_string(leaves[n]); });
    detail::TemplateCache cache(library);
    InstallResult out;
    out.unit = cache.unit();
    out.max_level = max_level;
    const LeafEmitter emitter(leaves, max_level, library, plans, cache, out);
    // The leaves are any subset of the grid, so no dense corner array: every point is hashed.
    ComplexBuilder builder;
    const std::int64_t U = out.unit;
    const auto weld = [&](const LatticePoint& p) { return builder.add_vertex(p); };
    const auto corner = [&](std::int64_t x, std::int64_t y, std::int64_t z) { return builder.add_vertex({x * U, y * U, z * U}); };
    out.leaf_cells.reserve(leaves.size() + 1);
    out.leaf_cells.push_back(0);
    for (std::size_t n = 0; n < leaves.size(); ++n) {
        emitter.emit(builder, n, weld, corner);
        out.leaf_cells.push_back(static_cast<std::uint32_t>(builder.n_cells()));
    }
    out.complex = std::move(builder).build();
    return out;
}

}  // namespace dualhex
