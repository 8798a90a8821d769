// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The apps' progress text (apps/Progress.hpp) for given counts and times: no clock involved.
#include <gtest/gtest.h>

#include "Progress.hpp"

using travel::apps::formatDuration;
using travel::apps::formatProgress;
using travel::apps::ProgressState;
using travel::apps::Verbosity;
using travel::apps::verbosityFrom;

TEST(Progress, KnownTotalShowsCountRateAndEta) {
    ProgressState s;
    s.done = 25, s.total = 100, s.elapsed = 5.0;  // 5 frames/s, 75 left: 15 s
    EXPECT_EQ(formatProgress(s), "25/100 frames, 5.0 frames/s, ETA 15 s");
    EXPECT_EQ(formatProgress(s, "scans"), "25/100 scans, 5.0 scans/s, ETA 15 s");
}

TEST(Progress, UnknownTotalHasNoEta) {
    ProgressState s;
    s.done = 12, s.elapsed = 4.0;
    EXPECT_EQ(formatProgress(s), "12 frames, 3.0 frames/s");
}

TEST(Progress, NothingDoneYetHasNoRate) {
    ProgressState s;
    s.total = 10;
    EXPECT_EQ(formatProgress(s), "0/10 frames");
    s.elapsed = 1.0;
    EXPECT_EQ(formatProgress(s), "0/10 frames");
}

TEST(Progress, FinishedHasNoEta) {
    ProgressState s;
    s.done = s.total = 10, s.elapsed = 2.0;
    EXPECT_EQ(formatProgress(s), "10/10 frames, 5.0 frames/s");
}

TEST(Progress, SimulatedTimeAndRealTimeFactor) {
    ProgressState s;
    s.done = 123, s.sim_time = 12.3, s.sim_total = 60, s.elapsed = 6.15;
    EXPECT_EQ(formatProgress(s), "t = 12.3 / 60 s, 2.0x real time");
}

TEST(Progress, Durations) {
    EXPECT_EQ(formatDuration(4.3), "4.3 s");
    EXPECT_EQ(formatDuration(42), "42 s");
    EXPECT_EQ(formatDuration(185), "3 min 05 s");
    EXPECT_EQ(formatDuration(3720), "1 h 02 min");
    EXPECT_EQ(formatDuration(-1), "?");
}

TEST(Progress, QuietWinsOverVerbose) {
    EXPECT_EQ(verbosityFrom(true, true), Verbosity::Quiet);
    EXPECT_EQ(verbosityFrom(false, true), Verbosity::Verbose);
    EXPECT_EQ(verbosityFrom(false, false), Verbosity::Normal);
}

TEST(Progress, FractionOfTheInputGivesPercentAndEta) {
    ProgressState s;
    s.done = 10, s.fraction = 0.25, s.elapsed = 2.0;  // a quarter in 2 s: 6 s to go
    EXPECT_EQ(formatProgress(s), "10 frames, 25 %, 5.0 frames/s, ETA 6.0 s");
    s.fraction = 0.999;  // 100 % only at the end
    EXPECT_EQ(formatProgress(s), "10 frames, 99 %, 5.0 frames/s, ETA 0.0 s");
    s.fraction = 1.0;
    EXPECT_EQ(formatProgress(s), "10 frames, 100 %, 5.0 frames/s");
}

TEST(Progress, FractionBeforeTheFirstFrameHasNoRate) {
    ProgressState s;
    s.fraction = 0.05, s.elapsed = 1.0;
    EXPECT_EQ(formatProgress(s), "0 frames, 5 %");
}

TEST(Progress, UnknownFractionOrKnownTotalShowsNoPercent) {
    ProgressState s;
    s.done = 12, s.elapsed = 4.0, s.fraction = -1;  // a gzip rawlog without /proc
    EXPECT_EQ(formatProgress(s), "12 frames, 3.0 frames/s");
    s.total = 24, s.fraction = 0.9;  // the count wins
    EXPECT_EQ(formatProgress(s), "12/24 frames, 3.0 frames/s, ETA 4.0 s");
}
