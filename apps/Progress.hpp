// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The apps' one progress line and their console rules: -q prints nothing but errors, -v adds
// details (and MRPT's DEBUG lines); on a terminal (stderr is a tty) the progress is one line
// redrawn with '\r', elsewhere (pipe, CI log) a plain line every ~10 % or ~5 s.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <set>
#include <string>

#include "travel/MountEstimator.hpp"

namespace mrpt::system {
class COutputLogger;
}

namespace travel::apps {

/// -q / (nothing) / -v.
enum class Verbosity { Quiet, Normal, Verbose };

/// CommonFlags rejects -q with -v as a usage error; should both still arrive (a caller that
/// skips that check), -q wins: a script asked for silence.
inline Verbosity verbosityFrom(bool quiet, bool verbose) {
    return quiet ? Verbosity::Quiet : verbose ? Verbosity::Verbose : Verbosity::Normal;
}

/// Whose messages an mrpt::system::COutputLogger carries.
enum class MrptLogRole {
    Library,  ///< MRPT's own objects (navigator, time loggers): internal chatter at INFO
    Notes     ///< our TravelFilter: its INFO lines are notes for the user ("not deskewed")
};

/// The one rule for MRPT's console output (MRPT 2.5 has no global level: every logger is set
/// one by one): nothing but errors with -q, DEBUG lines only with -v, else warnings and above
/// (INFO and above for our filter's notes).
void configureMrptLogging(mrpt::system::COutputLogger& logger, Verbosity verbosity,
                          MrptLogRole role = MrptLogRole::Library);

/// Silences, while it lives, what a library writes straight to stderr with no logger to set:
/// liboctomap 1.9.7 prints " done." on every binary tree write (.bt exports, the serialized
/// map). Our own errors travel as exceptions, so nothing of ours is lost.
class MuteLibraryStderr {
  public:
    MuteLibraryStderr();
    ~MuteLibraryStderr();
    MuteLibraryStderr(const MuteLibraryStderr&) = delete;
    MuteLibraryStderr& operator=(const MuteLibraryStderr&) = delete;

  private:
    int saved_fd_ = -1;
};

/// What the progress line shows at one moment.
struct ProgressState {
    std::size_t done = 0;   ///< frames (or records) finished
    std::size_t total = 0;  ///< 0: unknown
    /// Of the input read (bytes of a rawlog or capture) when `total` is unknown; < 0: unknown.
    double fraction = -1;
    double elapsed = 0;  ///< [s] wall time since the start
    /// Simulated time (travel-nav-sim): shown instead of frames when sim_total > 0.
    double sim_time = 0, sim_total = 0;
};

/// "12/100 frames, 8.3 frames/s, ETA 10.6 s" (k/N, rate, remaining time when N is known),
/// "12 frames, 37 %, 8.3 frames/s, ETA 6.8 s" (the fraction of the input read, when N is not),
/// or "t = 12.3 / 60 s, 2.1x real time" with a simulated time. `unit` names what is counted.
std::string formatProgress(const ProgressState& state, const std::string& unit = "frames");

/// TRAVEL's note on the sensor mount (an `auto` estimate, or a configured value far from the
/// measured ground), as every app prints it: "<app>: [<context>: ][warning: ]<message>".
std::string mountNoteLine(const std::string& app, const std::string& context,
                          const travel::MountNote& note);

/// "42 s", "3 min 05 s", "1 h 02 min".
std::string formatDuration(double seconds);

/// One progress display on stderr. update() is cheap when nothing is due (one clock read).
/// Nothing at all with Verbosity::Quiet. finish() (or the destructor) ends the line. Every
/// method may be called from any thread (notes come from workers while the main thread draws).
class ProgressLine {
  public:
    ProgressLine(std::string label, std::size_t total, Verbosity verbosity,
                 std::string unit = "frames");
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void update(std::size_t done);
    /// The number of frames unknown: `fraction` of the input read (RawlogReader::fractionRead;
    /// < 0: unknown) gives the percentage and the ETA.
    void update(std::size_t done, double fraction);
    /// travel-nav-sim: `done` steps, simulated time `t` of `t_total` seconds.
    void updateSimTime(std::size_t done, double t, double t_total);
    void setTotal(std::size_t total) {
        const std::lock_guard<std::mutex> lock(mutex_);
        state_.total = total;
    }
    /// Prints `line` (a warning) on stderr on a line of its own, even with -q, the progress line
    /// going on below it.
    void note(const std::string& line);
    /// Draws the last state (a terminal) and ends the line; idempotent.
    void finish();

  private:
    enum class Mode { Off, Terminal, Log };
    void maybeDraw(bool force);
    void draw();

    std::mutex mutex_;  // notes come from worker threads (-j 2) while the main thread updates
    std::string label_, unit_;
    Mode mode_;
    ProgressState state_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    bool printed_ = false;  ///< at least one line was written
    double next_fraction_ = 0.1;
};

/// An app's notes for the user on stderr, none with -q: "<app>: note: <text>" once per text, on
/// a line of their own above the progress line while one is attached. listen() routes our
/// TravelFilter's COutputLogger here: MRPT would print its INFO lines on stdout with a time stamp
/// ("[12:00:00|INFO |TravelFilter] ..."), and stdout carries only the app's own output.
class Notes {
  public:
    Notes(std::string app, Verbosity verbosity) : app_(std::move(app)), verbosity_(verbosity) {}
    Notes(const Notes&) = delete;
    Notes& operator=(const Notes&) = delete;
    /// Sets `logger`'s level (configureMrptLogging, MrptLogRole::Notes), turns its console
    /// output off and takes its messages as notes; this object must outlive the logger.
    void listen(mrpt::system::COutputLogger& logger);
    /// Lines go above `progress` from now on; nullptr: straight to stderr.
    void attach(ProgressLine* progress);
    /// "<app>: note: <text>", the first time `text` comes.
    void once(const std::string& text);
    /// "<app>: note: <where>: <reason> (not repeated for other frames)", the first time `reason`
    /// comes, wherever (the file or record it happened to first): a reason that every later frame
    /// shares (a skipped or unmapped frame) is noted once, naming where to look.
    void oncePerReason(const std::string& where, const std::string& reason);
    /// `line` as it is.
    void say(const std::string& line);

    /// attach(&progress) for the lifetime of this object, then attach(nullptr).
    class Attached {
      public:
        Attached(Notes& notes, ProgressLine& progress) : notes_(notes) { notes_.attach(&progress); }
        ~Attached() { notes_.attach(nullptr); }
        Attached(const Attached&) = delete;
        Attached& operator=(const Attached&) = delete;

      private:
        Notes& notes_;
    };

  private:
    std::string app_;
    Verbosity verbosity_;
    std::mutex mutex_;  // notes may come from a worker thread (travel-map -j 2)
    std::set<std::string> seen_, seen_reasons_;
    ProgressLine* progress_ = nullptr;
};

}  // namespace travel::apps
