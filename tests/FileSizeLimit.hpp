// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A file size limit (RLIMIT_FSIZE) for a scope of one test: a write past `bytes` fails with
// EFBIG, as on a full disk, whoever runs the test (a read-only folder does not stop root).
// SIGXFSZ is ignored meanwhile, so that the write fails instead of the process. The limit is
// the process's (ctest runs each test in a process of its own); both are restored at the end.
#pragma once

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>

namespace travel_test {

class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        EXPECT_EQ(getrlimit(RLIMIT_FSIZE, &saved_), 0);
        handler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = std::min(bytes, saved_.rlim_max);
        EXPECT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

  private:
    rlimit saved_{};
    void (*handler_)(int) = SIG_DFL;
};

}  // namespace travel_test
