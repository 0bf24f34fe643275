#pragma once
// The progress bar of the long commands (mesh, certify, variants --combined, verify,
// install, audit): one line on stderr redrawn with '\r',
//   [stage] 42% |########............| 3.1 s
// at most ~10 times a second, erased when the command is done and replaced by a one-line
// summary ("mesh: 29,128 hexes in 4.2 s"). Only on a terminal: under --json, --no-progress
// or when stderr is not a TTY it writes nothing at all, so logs and piped output stay
// exactly what they were. No colour is ever used (NO_COLOR holds trivially); TERM=dumb
// gets the summary but no redrawn bar (such terminals may not honour '\r').
//
// The library reports real fractions of work through dualhex::Progress (topology/progress.hpp);
// this file is the only one that turns them into terminal output.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>

#include <CLI/CLI.hpp>

#include "dualhex/topology/progress.hpp"

namespace dualhex::app {

/// What the bar may do on this stream.
enum class ProgressMode {
    kOff,      ///< nothing (not a terminal, --json, --no-progress)
    kSummary,  ///< only the final summary line (TERM=dumb)
    kBar,      ///< the redrawn bar, then the summary
};

/// The mode for stderr: kOff unless stderr is a TTY and neither `json` nor `no_progress`.
ProgressMode stderr_progress_mode(bool json, bool no_progress);

/// Adds `--no-progress` (no bar or summary even on a terminal).
CLI::Option* add_no_progress_flag(CLI::App& sub, bool& no_progress);

/// 29128 -> "29,128" (summaries are read by people).
std::string with_commas(std::size_t n);

class ProgressBar {
public:
    using Clock = std::function<double()>;  ///< seconds since any fixed point

    /// Draws on `out`; `clock` is injectable so tests can drive time; `columns` bounds the
    /// line (a wrapped line could not be redrawn with '\r'). `ticker`: a thread calls
    /// tick() ~5 times a second, so the elapsed time moves during a long stage.
    ProgressBar(std::ostream& out, ProgressMode mode, Clock clock = steady_seconds, std::size_t columns = 80,
                bool ticker = false);
    /// The stderr bar of a command (mode from stderr_progress_mode, width from the terminal).
    static ProgressBar for_stderr(bool json, bool no_progress);
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;
    ProgressBar(ProgressBar&&) = delete;
    ~ProgressBar();  ///< erases a bar left drawn (a command that failed prints no summary)

    /// A dualhex::Progress feeding update(); empty when the mode is kOff, so the library
    /// does not even count.
    [[nodiscard]] Progress callback();
    /// `done` of `total` (0: unknown) of `stage`; redraws if ~0.1 s passed since the last draw.
    void update(std::string_view stage, std::size_t done, std::size_t total);
    /// Redraws the last state (its elapsed time) if the bar is drawn and ~0.1 s passed.
    void tick();
    /// Erases the bar (call before writing anything else to the same terminal); the next
    /// update draws it again.
    void clear();
    /// Erases the bar and prints "<summary> in <elapsed> s" on its own line.
    void finish(const std::string& summary);
    [[nodiscard]] bool active() const { return mode_ != ProgressMode::kOff; }
    [[nodiscard]] double elapsed() const { return clock_() - start_; }

    /// The line drawn for this state (no '\r'; at most `columns` - 1 characters).
    static std::string line(std::string_view stage, std::size_t done, std::size_t total, double seconds,
                            std::size_t columns);
    static double steady_seconds();

    static constexpr double kRedrawInterval = 0.1;  ///< seconds between redraws, at most

private:
    void start_ticker();
    void draw_locked(double now);
    void erase_locked();

    std::ostream& out_;
    ProgressMode mode_;
    Clock clock_;
    std::size_t columns_;
    double start_;
    double last_draw_ = -1;   ///< clock of the last draw (< 0: never drawn)
    std::size_t drawn_ = 0;   ///< characters of the bar now on the terminal (0: none)
    std::string stage_;       ///< the stage last reported, and its count (never goes back)
    std::size_t done_ = 0, total_ = 0;
    std::mutex mutex_;
    std::condition_variable stop_ticker_;
    bool stopping_ = false;
    std::thread ticker_;  ///< last: started after everything it reads
};

}  // namespace dualhex::app
