// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "Interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace travel::apps {

namespace {

volatile std::sig_atomic_t g_signals = 0;

extern "C" void onInterrupt(int) {
    // Only async-signal-safe work here: count, and leave at once on the second signal.
    if (g_signals > 0) _exit(kInterruptedExitCode);
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
    std::error_code ec;
    std::filesystem::remove(path_, ec);
}

}  // namespace travel::apps
