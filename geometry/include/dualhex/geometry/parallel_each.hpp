#pragma once
// parallel_each(n, f): f(i) for i in [0, n) on oneTBB's workers, in blocks of `grain`.
// For order-independent per-item work only: f(i) may write item i's own output slot and
// read shared state, never accumulate into a shared value, so the result is the same for
// any number of threads (reductions are done afterwards, serially, in index order).
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace dualhex::geometry {

template <class F>
void parallel_each(std::size_t n, std::size_t grain, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
    });
}

}  // namespace dualhex::geometry
