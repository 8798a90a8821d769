// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The clock of every algorithm timing the project reports (Pipeline's StageTimings, the
// evaluator's methods, the apps' reports): the calling thread's CPU time. On a shared machine a
// wall clock also counts whatever ran on the core meanwhile (under load several times the
// algorithm's own time). Reading it is a system call, ~0.7 us.
#pragma once

#include <ctime>

namespace travel {

/// CPU time of the calling thread [ms] (kernel time on its behalf, e.g. page faults, included).
inline double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace travel
