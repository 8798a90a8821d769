// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The calling thread's CPU time, the clock of the apps' timing reports (as of the pipeline's
// StageTimings): on a shared machine a wall clock also counts whatever ran on the core meanwhile.
#pragma once

#include <ctime>

namespace travel::apps {

/// CPU time of the calling thread [ms] (kernel time on its behalf, e.g. page faults, included).
inline double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace travel::apps
