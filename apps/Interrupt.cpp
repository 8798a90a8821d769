// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "Interrupt.hpp"

#include <time.h>
#include <unistd.h>

#include <atomic>
#include <csignal>

#include "travel/io/BinaryFile.hpp"

namespace travel::apps {

namespace {

volatile std::sig_atomic_t g_signals = 0;
std::atomic<long long> g_first_signal_ms{0};  // lock-free on the targets we build for
static_assert(std::atomic<long long>::is_always_lock_free, "used in a signal handler");

long long monotonicMs() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);  // async-signal-safe (POSIX)
    return static_cast<long long>(t.tv_sec) * 1000 + t.tv_nsec / 1000000;
}

extern "C" void onInterrupt(int) {
    // Only async-signal-safe work here: note the first signal, and leave at once on a second
    // one. A signal within half a second of the first is the same request delivered twice:
    // `timeout -s INT` signals the process and then its process group, and exiting there
    // would skip the cleanup the first one asked for.
    const long long now = monotonicMs();
    if (g_signals > 0) {
        if (now - g_first_signal_ms.load() >= 500) _exit(kInterruptedExitCode);
        return;
    }
    g_first_signal_ms.store(now);
    g_signals = 1;
}

}  // namespace

void installInterruptHandlers() {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and writes go on; the loops check the flag
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() {
    return g_signals != 0;
}

void throwIfInterrupted() {
    if (interrupted()) throw Interrupted();
}

TempDir::TempDir(std::filesystem::path path) : path_(std::move(path)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

PartialOutput::~PartialOutput() {
    if (committed_ || path_.empty()) return;
    travel::removeCutFile(path_.string());
}

}  // namespace travel::apps
