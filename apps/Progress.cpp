// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "Progress.hpp"

#include <fcntl.h>
#include <mrpt/system/COutputLogger.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace travel::apps {

void configureMrptLogging(mrpt::system::COutputLogger& logger, Verbosity verbosity,
                          MrptLogRole role) {
    using namespace mrpt::system;
    logger.setMinLoggingLevel(verbosity == Verbosity::Verbose ? LVL_DEBUG
                              : verbosity == Verbosity::Quiet ? LVL_ERROR
                              : role == MrptLogRole::Notes    ? LVL_INFO
                                                              : LVL_WARN);
}

void Notes::listen(mrpt::system::COutputLogger& logger) {
    configureMrptLogging(logger, verbosity_, MrptLogRole::Notes);
    logger.logging_enable_console_output = false;
    logger.logRegisterCallback([this](std::string_view msg, mrpt::system::VerbosityLevel,
                                      std::string_view,
                                      const mrpt::Clock::time_point&) { once(std::string(msg)); });
}

void Notes::attach(ProgressLine* progress) {
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_ = progress;
}

void Notes::once(const std::string& text) {
    bool first = false;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        first = seen_.insert(text).second;
    }
    if (first) say(app_ + ": note: " + text);
}

void Notes::oncePerReason(const std::string& where, const std::string& reason) {
    bool first = false;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        first = seen_reasons_.insert(reason).second;
    }
    if (first) say(app_ + ": note: " + where + ": " + reason + " (not repeated for other frames)");
}

void Notes::say(const std::string& line) {
    if (verbosity_ == Verbosity::Quiet) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (progress_)
        progress_->note(line);
    else
        std::cerr << line << "\n";
}

MuteLibraryStderr::MuteLibraryStderr() {
    std::fflush(stderr);
    const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null_fd < 0) return;
    saved_fd_ = ::dup(STDERR_FILENO);
    if (saved_fd_ >= 0) ::dup2(null_fd, STDERR_FILENO);
    ::close(null_fd);
}

MuteLibraryStderr::~MuteLibraryStderr() {
    if (saved_fd_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_fd_, STDERR_FILENO);
    ::close(saved_fd_);
}

std::string formatDuration(double seconds) {
    char text[32];
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    const long s = std::lround(seconds);
    if (seconds < 60)
        std::snprintf(text, sizeof text, "%.*f s", seconds < 10 ? 1 : 0, seconds);
    else if (s < 3600)
        std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
    return text;
}

std::string formatProgress(const ProgressState& p, const std::string& unit) {
    char text[160];
    if (p.sim_total > 0) {
        // Real-time factor: simulated seconds per wall second.
        const double factor = p.elapsed > 0 ? p.sim_time / p.elapsed : 0.0;
        std::snprintf(text, sizeof text, "t = %.1f / %.4g s, %.1fx real time", p.sim_time,
                      p.sim_total, factor);
        return text;
    }
    const double rate = p.elapsed > 0 ? double(p.done) / p.elapsed : 0.0;
    std::string s =
        p.total ? std::to_string(p.done) + "/" + std::to_string(p.total) : std::to_string(p.done);
    s += " " + unit;
    const bool by_fraction = !p.total && p.fraction >= 0;
    const double fraction = std::min(p.fraction, 1.0);
    if (by_fraction) {
        std::snprintf(text, sizeof text, ", %d %%", int(fraction * 100));  // 100 % only at the end
        s += text;
    }
    if (p.elapsed > 0 && p.done > 0) {
        std::snprintf(text, sizeof text, ", %.1f %s/s", rate, unit.c_str());
        s += text;
        if (p.total > p.done) s += ", ETA " + formatDuration(double(p.total - p.done) / rate);
        // The rest of the input at the pace of the part read.
        if (by_fraction && fraction > 0 && fraction < 1)
            s += ", ETA " + formatDuration(p.elapsed * (1 - fraction) / fraction);
    }
    return s;
}

ProgressLine::ProgressLine(std::string label, std::size_t total, Verbosity verbosity,
                           std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      mode_(verbosity == Verbosity::Quiet ? Mode::Off
            : isatty(STDERR_FILENO) != 0  ? Mode::Terminal
                                          : Mode::Log),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {
    state_.total = total;
}

ProgressLine::~ProgressLine() {
    finish();
}

void ProgressLine::update(std::size_t done) {
    const std::lock_guard<std::mutex> lock(mutex_);
    state_.done = done;
    maybeDraw(false);
}

void ProgressLine::update(std::size_t done, double fraction) {
    const std::lock_guard<std::mutex> lock(mutex_);
    state_.fraction = fraction;
    state_.done = done;
    maybeDraw(false);
}

void ProgressLine::updateSimTime(std::size_t done, double t, double t_total) {
    const std::lock_guard<std::mutex> lock(mutex_);
    state_.done = done;
    state_.sim_time = t;
    state_.sim_total = t_total;
    maybeDraw(false);
}

void ProgressLine::maybeDraw(bool force) {
    if (mode_ == Mode::Off) return;
    const auto now = std::chrono::steady_clock::now();
    const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
    state_.elapsed = std::chrono::duration<double>(now - start_).count();
    if (mode_ == Mode::Terminal) {
        if (!force && since_draw < 0.2) return;  // a readable, cheap redraw rate
    } else {
        // A log: every ~10 % of a known total, else every ~5 s.
        const double fraction = state_.sim_total > 0 ? state_.sim_time / state_.sim_total
                                : state_.total       ? double(state_.done) / double(state_.total)
                                                     : state_.fraction;
        const bool step = fraction >= next_fraction_;
        if (!force && !step && since_draw < 5.0) return;
        while (fraction >= next_fraction_) next_fraction_ += 0.1;
    }
    last_draw_ = now;
    draw();
}

void ProgressLine::draw() {
    const std::string text = label_ + ": " + formatProgress(state_, unit_);
    if (mode_ == Mode::Terminal) {
        // Pad to wipe a longer previous text; "\033[K" would do too but not on every terminal.
        std::fprintf(stderr, "\r%-78s", text.c_str());
    } else {
        std::fprintf(stderr, "%s\n", text.c_str());
    }
    printed_ = true;
    std::fflush(stderr);
}

std::string mountNoteLine(const std::string& app, const std::string& context,
                          const travel::MountNote& note) {
    return app + ": " + (context.empty() ? "" : context + ": ") +
           (note.isWarning() ? "warning: " : "") + note.message;
}

void ProgressLine::note(const std::string& line) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (mode_ == Mode::Terminal && printed_) std::fputc('\n', stderr);
    printed_ = false;  // the next draw starts a fresh line
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
}

void ProgressLine::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (mode_ == Mode::Off) return;
    if (mode_ == Mode::Terminal && printed_) {
        maybeDraw(true);
        std::fputc('\n', stderr);
    }
    mode_ = Mode::Off;
}

}  // namespace travel::apps
