// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Ctrl-C (SIGINT) and SIGTERM for the apps: the handler only sets a flag; the frame loops call
// throwIfInterrupted(), which unwinds the stack (RAII removes temporary files and partial
// outputs) and runMain() exits with 130. A second signal, half a second or more after the
// first, exits at once (_exit(130)), without any cleanup: the user asked twice. One arriving
// sooner is the first delivered twice (`timeout` signals the process, then its group).
#pragma once

#include <filesystem>
#include <stdexcept>

namespace travel::apps {

/// The exit code of an interrupted run (128 + SIGINT, as a shell reports it).
constexpr int kInterruptedExitCode = 130;

/// Thrown by throwIfInterrupted(); runMain() turns it into exit code 130.
struct Interrupted : std::runtime_error {
    Interrupted() : std::runtime_error("interrupted") {}
};

/// Installs the SIGINT / SIGTERM handlers (runMain() does it for every app).
void installInterruptHandlers();
/// True once SIGINT or SIGTERM arrived.
bool interrupted();
void throwIfInterrupted();

/// A temporary directory (created empty, any old one of the name removed) that is removed with
/// everything in it when the object goes: normal end, exception or interrupt.
class TempDir {
  public:
    explicit TempDir(std::filesystem::path path);
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

/// An output file written in place that must not survive an unfinished run: removed on
/// destruction unless commit() was called (an interrupt or an error leaves no partial file).
class PartialOutput {
  public:
    explicit PartialOutput(std::filesystem::path path) : path_(std::move(path)) {}
    ~PartialOutput();
    PartialOutput(const PartialOutput&) = delete;
    PartialOutput& operator=(const PartialOutput&) = delete;
    void commit() { committed_ = true; }

  private:
    std::filesystem::path path_;
    bool committed_ = false;
};

}  // namespace travel::apps
