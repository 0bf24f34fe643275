#pragma once
// Progress of a long operation, reported to whoever asked for it (the `dualhex` program
// draws a bar from it; the library never writes to a terminal).
//
// A Progress callback is called with a short stage name and `done` of `total` units of that
// stage's real work (windows checked, assignments enumerated, stages of a pipeline): never
// a guess from elapsed time. total == 0 means the stage's size is unknown. An empty
// callback costs one branch: ProgressCounter::add returns before touching its counter.
#include <atomic>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>

namespace dualhex {

using Progress = std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

/// Counts the units of one stage done by any number of threads (oneTBB loops) and reports
/// them. The callback is only ever called by one thread at a time: a thread that finds
/// another reporting skips its report (the next one carries the count), so the loop never
/// waits on the observer. Reports at most every `total / 256` units (the observer
/// throttles further by time).
class ProgressCounter {
public:
    ProgressCounter(const Progress& progress, std::string_view stage, std::size_t total)
        : progress_(progress ? &progress : nullptr), stage_(stage), total_(total),
          step_(total / 256 > 0 ? total / 256 : 1) {
        report(0);
    }
    ProgressCounter(const ProgressCounter&) = delete;
    ProgressCounter& operator=(const ProgressCounter&) = delete;

    /// `n` more units done (thread-safe).
    void add(std::size_t n = 1) {
        if (!progress_) return;
        const std::size_t before = done_.fetch_add(n, std::memory_order_relaxed);
        if ((before + n) / step_ != before / step_) try_report(before + n);
    }

    /// The stage is complete: reports total of total (from the calling thread, after the loop).
    void finish() {
        if (!progress_) return;
        done_.store(total_, std::memory_order_relaxed);
        report(total_);
    }

private:
    void try_report(std::size_t done) {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (lock.owns_lock()) (*progress_)(stage_, done, total_);
    }
    void report(std::size_t done) {
        if (!progress_) return;
        const std::lock_guard lock(mutex_);
        (*progress_)(stage_, done, total_);
    }

    const Progress* progress_;
    std::string stage_;
    std::size_t total_;
    std::size_t step_;
    std::atomic<std::size_t> done_{0};
    std::mutex mutex_;
};

/// Reports `stage` as `done` of `total` if there is an observer (single-threaded code).
inline void report_progress(const Progress& progress, std::string_view stage, std::size_t done, std::size_t total) {
    if (progress) progress(stage, done, total);
}

}  // namespace dualhex
