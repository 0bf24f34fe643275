// The terminal progress bar (apps/progress_bar.hpp), fed a fake clock and a string stream:
// what is drawn, how often, how it is erased, and that the off and summary-only modes
// write exactly what they promise.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "progress_bar.hpp"

namespace {

using dualhex::app::ProgressBar;
using dualhex::app::ProgressMode;

// A clock the test moves by hand.
struct FakeClock {
    double now = 100.0;
    ProgressBar::Clock clock() {
        return [this] { return now; };
    }
};

// The text a terminal would show after `raw`: each '\r' returns to column 0 and later
// characters overwrite earlier ones; '\n' starts a new line.
std::string screen(const std::string& raw) {
    std::string out, line;
    std::size_t col = 0;
    for (char c : raw) {
        if (c == '\r') {
            col = 0;
        } else if (c == '\n') {
            while (!line.empty() && line.back() == ' ') line.pop_back();
            out += line + '\n';
            line.clear();
            col = 0;
        } else {
            if (col < line.size()) line[col] = c;
            else line += c;
            ++col;
        }
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return out + line;
}

std::size_t count(const std::string& s, char c) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), c)); }

TEST(ProgressBar, LineShowsStagePercentBarAndTime) {
    EXPECT_EQ(ProgressBar::line("windows", 42, 100, 3.14, 80), "[windows] 42% |########............| 3.1 s");
    EXPECT_EQ(ProgressBar::line("x", 0, 7, 0, 80), "[x] 0% |....................| 0.0 s");
    EXPECT_EQ(ProgressBar::line("x", 7, 7, 12.06, 80), "[x] 100% |####################| 12.1 s");
    // more than total (a late report) is shown as complete, not as 120%
    EXPECT_EQ(ProgressBar::line("x", 12, 10, 1, 80), "[x] 100% |####################| 1.0 s");
    // unknown size: no percentage
    EXPECT_EQ(ProgressBar::line("enumerating", 5, 0, 2, 80), "[enumerating] 2.0 s");
}

TEST(ProgressBar, LineNeverReachesTheLastColumn) {
    const std::string long_stage(200, 's');
    for (std::size_t columns : {20, 40, 81, 120}) {
        const std::string text = ProgressBar::line(long_stage, 1, 2, 1, columns);
        EXPECT_LT(text.size(), columns);
        EXPECT_EQ(text.substr(text.size() - 3), "...");
    }
}

TEST(ProgressBar, DrawsThrottledAndNeverGoesBackWithinAStage) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kBar, t.clock());
    bar.update("a", 1, 10);  // first report: drawn at once
    EXPECT_EQ(screen(out.str()), "[a] 10% |##..................| 0.0 s");
    for (int i = 2; i <= 9; ++i) {  // 8 reports within 0.08 s: none drawn
        t.now += 0.01;
        bar.update("a", static_cast<std::size_t>(i), 10);
    }
    EXPECT_EQ(count(out.str(), '\r'), 1u);
    t.now += 0.05;  // 0.13 s after the first draw
    bar.update("a", 5, 10);  // an out-of-order report from another thread: ignored
    EXPECT_EQ(count(out.str(), '\r'), 1u);
    bar.update("a", 10, 10);
    EXPECT_EQ(screen(out.str()), "[a] 100% |####################| 0.1 s");
}

TEST(ProgressBar, ShorterLineOverwritesTheLongerOneCompletely) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kBar, t.clock());
    bar.update("a long stage name", 1, 2);
    t.now += 1;
    bar.update("b", 0, 0);
    EXPECT_EQ(screen(out.str()), "[b] 1.0 s");
}

TEST(ProgressBar, TickRedrawsTheTimeOnlyWhileDrawn) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kBar, t.clock());
    bar.tick();  // nothing drawn yet: nothing to refresh
    EXPECT_EQ(out.str(), "");
    bar.update("a", 1, 4);
    t.now += 0.04;
    bar.tick();  // too soon
    EXPECT_EQ(count(out.str(), '\r'), 1u);
    t.now += 2;
    bar.tick();
    EXPECT_EQ(screen(out.str()), "[a] 25% |#####...............| 2.0 s");
    bar.clear();
    t.now += 2;
    bar.tick();  // erased: stays erased until the next update
    EXPECT_EQ(screen(out.str()), "");
}

TEST(ProgressBar, FinishErasesTheBarAndLeavesOneSummaryLine) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kBar, t.clock());
    bar.update("mesh 3/14: pair", 2, 14);
    t.now += 4.25;
    bar.update("mesh 11/14: optimise", 10, 14);
    bar.finish("mesh: 29,128 hexes");
    EXPECT_EQ(screen(out.str()), "mesh: 29,128 hexes in 4.2 s\n");
    EXPECT_EQ(out.str().find('%', out.str().rfind('\r')), std::string::npos);  // no bar after the last erase
}

TEST(ProgressBar, ClearBeforeOtherOutputLeavesItClean) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kBar, t.clock());
    bar.update("check one", 0, 2);
    bar.clear();
    out << "PASS  check one\n";
    bar.update("check two", 1, 2);  // right after a clear: drawn at once
    bar.finish("verify: 2 checks");
    EXPECT_EQ(screen(out.str()), "PASS  check one\nverify: 2 checks in 0.0 s\n");
}

TEST(ProgressBar, OffModeWritesNothingAndGivesNoCallback) {
    FakeClock t;
    std::ostringstream out;
    {
        ProgressBar bar(out, ProgressMode::kOff, t.clock());
        EXPECT_FALSE(bar.callback());  // the library does not even count
        bar.update("a", 1, 2);
        t.now += 1;
        bar.tick();
        bar.clear();
        bar.finish("summary");
    }
    EXPECT_EQ(out.str(), "");
}

TEST(ProgressBar, SummaryModeDrawsNoBarButTheSummary) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kSummary, t.clock());
    const dualhex::Progress progress = bar.callback();
    ASSERT_TRUE(progress);
    progress("a", 1, 2);
    t.now += 1.5;
    bar.tick();
    bar.finish("certify: 3 certificates");
    EXPECT_EQ(out.str(), "certify: 3 certificates in 1.5 s\n");  // no '\r' at all (TERM=dumb)
}

TEST(ProgressBar, CallbackFeedsTheBar) {
    FakeClock t;
    std::ostringstream out;
    ProgressBar bar(out, ProgressMode::kBar, t.clock());
    bar.callback()("windows", 3, 4);
    EXPECT_EQ(screen(out.str()), "[windows] 75% |###############.....| 0.0 s");
}

TEST(ProgressBar, DestructorErasesABarLeftDrawn) {
    FakeClock t;
    std::ostringstream out;
    {
        ProgressBar bar(out, ProgressMode::kBar, t.clock());
        bar.update("a", 1, 2);  // the command fails here: no finish
    }
    EXPECT_EQ(screen(out.str()), "");
}

TEST(ProgressBar, WithCommas) {
    using dualhex::app::with_commas;
    EXPECT_EQ(with_commas(0), "0");
    EXPECT_EQ(with_commas(999), "999");
    EXPECT_EQ(with_commas(1000), "1,000");
    EXPECT_EQ(with_commas(29128), "29,128");
    EXPECT_EQ(with_commas(1234567), "1,234,567");
}

}  // namespace
