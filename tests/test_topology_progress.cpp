// dualhex::ProgressCounter (topology/progress.hpp): from a oneTBB loop, the observer is
// never called by two threads at once, sees every stage end at total, is called a bounded
// number of times, and an empty callback is never called (and costs no counting).
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "dualhex/topology/progress.hpp"

namespace {

using dualhex::Progress;
using dualhex::ProgressCounter;

TEST(ProgressCounter, ParallelReportsAreSerialisedBoundedAndEndAtTotal) {
    constexpr std::size_t kTotal = 100000;
    std::atomic<int> inside{0};
    std::atomic<bool> overlapped{false};
    std::vector<std::size_t> seen;  // written only inside the callback, which is serialised
    std::string stage;
    const Progress progress = [&](std::string_view s, std::size_t done, std::size_t total) {
        if (inside.fetch_add(1) != 0) overlapped = true;
        EXPECT_EQ(total, kTotal);
        stage = s;
        seen.push_back(done);
        inside.fetch_sub(1);
    };
    ProgressCounter counter(progress, "work", kTotal);
    tbb::parallel_for(std::size_t{0}, kTotal, [&](std::size_t) { counter.add(); });
    counter.finish();
    EXPECT_FALSE(overlapped);
    EXPECT_EQ(stage, "work");
    ASSERT_GE(seen.size(), 2u);
    EXPECT_EQ(seen.front(), 0u);  // the start is reported
    EXPECT_EQ(seen.back(), kTotal);
    EXPECT_LE(seen.size(), 256u + 2u);  // at most one report per 1/256 of the work, plus start and end
    for (std::size_t d : seen) EXPECT_LE(d, kTotal);
}

TEST(ProgressCounter, ReportsEachStepOfASmallSerialStage) {
    std::vector<std::size_t> seen;
    const Progress progress = [&](std::string_view, std::size_t done, std::size_t) { seen.push_back(done); };
    ProgressCounter counter(progress, "small", 3);
    counter.add();
    counter.add(2);
    counter.finish();
    EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1, 3, 3}));
}

TEST(ProgressCounter, EmptyCallbackIsNeverCalled) {
    const Progress none;
    ProgressCounter counter(none, "x", 10);
    for (int i = 0; i < 10; ++i) counter.add();
    counter.finish();
    dualhex::report_progress(none, "x", 1, 2);  // must not throw std::bad_function_call
    SUCCEED();
}

}  // namespace
