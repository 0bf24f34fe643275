// The terminal progress bar (progress_bar.hpp).
#include "progress_bar.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace dualhex::app {

ProgressMode stderr_progress_mode(bool json, bool no_progress) {
    if (json || no_progress || !isatty(STDERR_FILENO)) return ProgressMode::kOff;
    const char* term = std::getenv("TERM");
    if (term != nullptr && std::strcmp(term, "dumb") == 0) return ProgressMode::kSummary;
    return ProgressMode::kBar;
}

CLI::Option* add_no_progress_flag(CLI::App& sub, bool& no_progress) {
    return sub.add_flag("--no-progress", no_progress,
                        "No progress bar or summary line on the terminal (there is none under --json or when "
                        "stderr is not a terminal)");
}

std::string with_commas(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

double ProgressBar::steady_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProgressBar::ProgressBar(std::ostream& out, ProgressMode mode, Clock clock, std::size_t columns, bool ticker)
    : out_(out), mode_(mode), clock_(std::move(clock)), columns_(std::max<std::size_t>(columns, 20)), start_(clock_()) {
    if (ticker) start_ticker();
}

ProgressBar ProgressBar::for_stderr(bool json, bool no_progress) {
    const ProgressMode mode = stderr_progress_mode(json, no_progress);
    std::size_t columns = 80;
    winsize size{};
    if (mode != ProgressMode::kOff && ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
        columns = size.ws_col;
    return ProgressBar(std::cerr, mode, steady_seconds, columns, true);
}

void ProgressBar::start_ticker() {
    if (mode_ != ProgressMode::kBar) return;
    ticker_ = std::thread([this] {
        std::unique_lock lock(mutex_);
        while (!stop_ticker_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stopping_; })) {
            lock.unlock();
            tick();
            lock.lock();
        }
    });
}

ProgressBar::~ProgressBar() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        erase_locked();
    }
    stop_ticker_.notify_all();
    if (ticker_.joinable()) ticker_.join();
}

Progress ProgressBar::callback() {
    if (mode_ == ProgressMode::kOff) return {};
    return [this](std::string_view stage, std::size_t done, std::size_t total) { update(stage, done, total); };
}

std::string ProgressBar::line(std::string_view stage, std::size_t done, std::size_t total, double seconds,
                              std::size_t columns) {
    char time[32];
    std::snprintf(time, sizeof time, "%.1f s", seconds);
    std::string text = "[" + std::string(stage) + "] ";
    if (total > 0) {
        constexpr std::size_t kWidth = 20;
        const std::size_t d = std::min(done, total);
        const std::size_t filled = d * kWidth / total;
        text += std::to_string(d * 100 / total) + "% |" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "| ";
    }
    text += time;
    // Never the last column: a line that wraps cannot be redrawn in place.
    if (text.size() > columns - 1) text = text.substr(0, columns - 4) + "...";
    return text;
}

void ProgressBar::update(std::string_view stage, std::size_t done, std::size_t total) {
    if (mode_ != ProgressMode::kBar) return;
    const std::lock_guard lock(mutex_);
    // Reports of one stage from several threads may arrive out of order: never go back.
    if (stage == stage_ && done < done_) return;
    stage_ = stage;
    done_ = done;
    total_ = total;
    const double now = clock_();
    if (last_draw_ >= 0 && now - last_draw_ < kRedrawInterval) return;
    draw_locked(now);
}

void ProgressBar::tick() {
    if (mode_ != ProgressMode::kBar) return;
    const std::lock_guard lock(mutex_);
    const double now = clock_();
    if (drawn_ == 0 || now - last_draw_ < kRedrawInterval) return;  // nothing shown, or shown just now
    draw_locked(now);
}

void ProgressBar::draw_locked(double now) {
    last_draw_ = now;
    const std::string text = line(stage_, done_, total_, now - start_, columns_);
    // '\r', the new text, then blanks over what is left of a longer previous line.
    out_ << '\r' << text;
    if (drawn_ > text.size()) out_ << std::string(drawn_ - text.size(), ' ') << '\r' << text;
    out_.flush();
    drawn_ = text.size();
}

void ProgressBar::erase_locked() {
    if (drawn_ == 0) return;
    out_ << '\r' << std::string(drawn_, ' ') << '\r';
    out_.flush();
    drawn_ = 0;
    last_draw_ = -1;  // whatever follows the erased bar may draw it again at once
}

void ProgressBar::clear() {
    const std::lock_guard lock(mutex_);
    erase_locked();
}

void ProgressBar::finish(const std::string& summary) {
    if (mode_ == ProgressMode::kOff) return;
    const std::lock_guard lock(mutex_);
    erase_locked();
    char time[32];
    std::snprintf(time, sizeof time, "%.1f", clock_() - start_);
    out_ << summary << " in " << time << " s\n";
    out_.flush();
}

}  // namespace dualhex::app
