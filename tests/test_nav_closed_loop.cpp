// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Closed-loop runs of travel-nav-sim's loop (MRPT's CReactiveNavigationSystem3D on
// CVehicleSimul_DiffDriven, synthetic LiDAR, TRAVEL):
//   - TRAVEL reaches the goal of ramp_kerb.world (15-degree ramp, a 20 cm kerb segment on the
//     slope, a box on the upper level) with no collision, in the file's world and in four
//     seeded variants (kerb and box moved by up to +/-0.3 m: seeds 1-4);
//   - the raw-point source does not climb the ramp (ramp.world: nothing else in the way);
//   - the height-threshold source climbs that ramp (ramp.world) but hits the kerb on the slope
//     (ramp_kerb.world);
//   - a box crossing the robot's path (crossing.world) hits the robot on the per-frame TRAVEL
//     source; with tracking (its predicted path an obstacle) the robot keeps clear of it;
//   - the .reactivenavlog the navigator writes deserializes as CLogFileRecords.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/nav/reactive/CLogFileRecord.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "TempDir.hpp"
#include "nav/Simulation.hpp"
#include "nav/World.hpp"

using namespace travel::navsim;

namespace {

const std::string kShare = TRAVEL_SHARE_DIR_FOR_TESTS;

SimOptions options(SourceKind kind, double timeout = 45.0) {
    SimOptions o;
    o.nav_config_file = kShare + "/configs/nav/reactive3d_travel.ini";
    o.source = kind;
    o.timeout = timeout;
    return o;
}

void print(const std::string& what, const RunReport& r) {
    std::printf("%-34s %-17s time %5.1f s path %5.2f m min clearance %.2f m climbed %.2f m %s\n",
                what.c_str(), toString(r.outcome), r.time, r.path_length, r.min_clearance,
                r.max_height_gain, r.detail.c_str());
}

/// ramp_kerb.world with the kerb and the box moved by a seeded +/-0.3 m (0: unchanged).
World rampKerbWorld(unsigned seed) {
    return shiftedObstacles(loadWorld(kShare + "/worlds/ramp_kerb.world"), seed, 0.3);
}

}  // namespace

class TravelOnRampKerb : public ::testing::TestWithParam<unsigned> {};

TEST_P(TravelOnRampKerb, ReachesTheGoalUpTheRampWithoutCollision) {
    const RunReport r = runSimulation(rampKerbWorld(GetParam()), options(SourceKind::Travel));
    print("travel, ramp_kerb seed " + std::to_string(GetParam()), r);
    EXPECT_EQ(r.outcome, Outcome::Goal) << r.detail;
    // No collision: the footprint never overlaps the kerb, the box or a wall.
    EXPECT_GT(r.min_clearance, 0.0) << "nearest: " << r.min_clearance_to;
    EXPECT_GT(r.max_height_gain, 1.5);  // the upper level is 1.61 m up
    // Never stuck: the goal within 40 s for about 15 m at 0.6 m/s.
    EXPECT_LT(r.time, 40.0);
}

// Seed 0 is the file's world; seed 2 (kerb moved by +0.26 m in x, -0.19 m in y) used to stop in
// front of the kerb (docs/navigation.md says what was fixed, and gives seeds 0-4). Two seeds keep
// CI's closed-loop time down.
#ifndef TRAVEL_SANITIZED
INSTANTIATE_TEST_SUITE_P(Seeds, TravelOnRampKerb, ::testing::Values(0u, 2u));
#else
// Sanitizer builds (3-5x slower) look for memory errors, not for behaviour: one seed is enough.
INSTANTIATE_TEST_SUITE_P(Seeds, TravelOnRampKerb, ::testing::Values(2u));
#endif

// The map source (TRAVEL -> map -> global path -> waypoints): up the ramp past the kerb with a
// margin (the per-frame TRAVEL source passes it at 0.03-0.09 m). Seed 3 once drove into the
// side wall when the map reported a wall cell at one height only (now a column).
class MapOnRampKerb : public ::testing::TestWithParam<unsigned> {};

TEST_P(MapOnRampKerb, ReachesTheGoalWithTenCentimetresClearance) {
    const RunReport r = runSimulation(rampKerbWorld(GetParam()), options(SourceKind::Map));
    print("map, ramp_kerb seed " + std::to_string(GetParam()), r);
    EXPECT_EQ(r.outcome, Outcome::Goal) << r.detail;
    EXPECT_GE(r.min_clearance, 0.10) << "nearest: " << r.min_clearance_to;
    EXPECT_GT(r.max_height_gain, 1.5);
    EXPECT_GE(r.planned_paths.size(), 1u);
}

// Two seeds keep the suite short (seeds 0-4 all pass: docs/navigation.md); sanitizer builds
// skip it (.ci/run).
INSTANTIATE_TEST_SUITE_P(Seeds, MapOnRampKerb, ::testing::Values(0u, 3u));

// dead_end.world: the per-frame TRAVEL source heads for the goal into the U and is trapped
// there; the map source plans around the U (re-planning as the map grows) and arrives.
TEST(NavClosedLoop, MapPlansAroundTheDeadEndWhereTravelIsTrapped) {
    const World w = loadWorld(kShare + "/worlds/dead_end.world");
    const RunReport map = runSimulation(w, options(SourceKind::Map, 45.0));
    print("map, dead_end", map);
    EXPECT_EQ(map.outcome, Outcome::Goal) << map.detail;
    EXPECT_GT(map.min_clearance, 0.0) << "nearest: " << map.min_clearance_to;
    for (const TrajectorySample& s : map.trajectory)  // never inside the U
        EXPECT_FALSE(s.x > 2.2 && s.x < 9.3 && std::abs(s.y) < 2.3) << s.x << " " << s.y;

    const RunReport travel = runSimulation(w, options(SourceKind::Travel, 30.0));
    print("travel, dead_end", travel);
    EXPECT_NE(travel.outcome, Outcome::Goal);
    const TrajectorySample& last = travel.trajectory.back();  // still inside the U
    EXPECT_TRUE(last.x > 2.0 && last.x < 9.5 && std::abs(last.y) < 2.5) << last.x << " " << last.y;
}

// crossing.world: a box crosses the straight line to the goal at 1 m/s, timed to be there when
// the robot arrives. The per-frame TRAVEL source (no tracking) drives into its path and is hit
// after ~9 s; with tracking, the box's path over nav.predict_seconds is an obstacle too and the
// robot keeps clear of it (20 s: the box is long past the robot's line by then).
TEST(NavClosedLoop, TrackingKeepsClearOfTheCrossingMoverWherePerFrameTravelCollides) {
    const World world = loadWorld(kShare + "/worlds/crossing.world");
    const RunReport plain = runSimulation(world, options(SourceKind::Travel, 15.0));
    print("travel, crossing", plain);
    EXPECT_EQ(plain.outcome, Outcome::Collision);
    EXPECT_EQ(plain.min_clearance_to, "mover 1");

    SimOptions o = options(SourceKind::Travel, 20.0);
    o.track = true;
    const RunReport tracked = runSimulation(world, o);
    print("travel + tracking, crossing", tracked);
    EXPECT_NE(tracked.outcome, Outcome::Collision) << tracked.detail;
    EXPECT_NE(tracked.outcome, Outcome::NavigatorGaveUp) << tracked.detail;
    EXPECT_GT(tracked.min_mover_clearance, 0.3);
}

TEST(NavClosedLoop, RawPointsDoNotClimbTheRamp) {
    const World w = loadWorld(kShare + "/worlds/ramp.world");
    const RunReport r = runSimulation(w, options(SourceKind::Raw, 30.0));
    print("raw, ramp", r);
    EXPECT_NE(r.outcome, Outcome::Goal);
    EXPECT_LT(r.max_height_gain, 0.3);  // never further than the foot of the ramp
}

TEST(NavClosedLoop, HeightThresholdClimbsTheRampButHitsTheKerbOnTheSlope) {
    const RunReport alone =
        runSimulation(loadWorld(kShare + "/worlds/ramp.world"), options(SourceKind::Threshold));
    print("threshold, ramp", alone);
    EXPECT_EQ(alone.outcome, Outcome::Goal);

    const RunReport r = runSimulation(rampKerbWorld(0), options(SourceKind::Threshold));
    print("threshold, ramp_kerb", r);
    ASSERT_EQ(r.outcome, Outcome::Collision);
    EXPECT_EQ(r.detail, "footprint overlaps kerb 1");
    // The collision happens on the slope: the robot is already 0.3 m+ up the ramp.
    const TrajectorySample& last = r.trajectory.back();
    EXPECT_GT(last.z, 0.3);
}

// The navigator's "not approaching the target" alarm counts simulated seconds, not wall-clock
// ones: a goal inside a closed square, 3 s of alarm. The robot drives up to the square and
// stops approaching; the navigator gives up 3 s of simulated time after the last step that
// brought it nearer the goal (within two 0.1 s steps: the alarm fires at a navigation step,
// the loop sees it at the next), however fast the machine runs the simulation (1.3-1.6 x real
// time here, slower under sanitizers). On MRPT's wall clock, years after the stamps the
// simulation hands the navigator, this run drove 8.7 m along the square and had not given up
// after 20 s. Two runs are identical step for step.
TEST(NavClosedLoop, TheNavigatorsAlarmCountsSimulatedSeconds) {
    namespace fs = std::filesystem;
    const travel_test::TempDir tmp("travel_test_nav_sim_clock");
    std::ifstream in(kShare + "/configs/nav/reactive3d_travel.ini");
    std::stringstream ini;
    ini << in.rdbuf();
    std::string text = ini.str();
    const std::string key = "alarm_seems_not_approaching_target_timeout   = 20.0";
    ASSERT_NE(text.find(key), std::string::npos);
    text.replace(text.find(key), key.size(), "alarm_seems_not_approaching_target_timeout = 3.0");
    SimOptions o = options(SourceKind::Travel, 20.0);
    o.nav_config_file = (tmp.path / "short_alarm.ini").string();
    std::ofstream(o.nav_config_file) << text;

    const World w = parseWorld(
        "name boxed_goal\nstart 0 0 0\ngoal 4 0\nbounds -2 -3 7 3\n"
        "wall 2.5 -1.5 2.5 1.5 0.2 1.0\nwall 2.5 1.5 5.5 1.5 0.2 1.0\n"
        "wall 2.5 -1.5 5.5 -1.5 0.2 1.0\nwall 5.5 -1.5 5.5 1.5 0.2 1.0\n",
        "boxed_goal");
    const RunReport r = runSimulation(w, o);
    print("travel, goal in a closed square", r);
    ASSERT_EQ(r.outcome, Outcome::NavigatorGaveUp) << r.detail;
    // The last step that brought the robot nearer the goal.
    double nearest = 1e9, nearest_t = 0;
    for (const TrajectorySample& s : r.trajectory) {
        const double d = std::hypot(s.x - w.goal.x(), s.y - w.goal.y());
        if (d < nearest) nearest = d, nearest_t = s.t;
    }
    EXPECT_GT(r.time - nearest_t, 3.0);
    EXPECT_LE(r.time - nearest_t, 3.0 + 0.2 + 1e-6);

    const RunReport again = runSimulation(w, o);
    ASSERT_EQ(again.trajectory.size(), r.trajectory.size());
    for (std::size_t k = 0; k < r.trajectory.size(); ++k) {
        const TrajectorySample &a = r.trajectory[k], &b = again.trajectory[k];
        ASSERT_TRUE(a.x == b.x && a.y == b.y && a.yaw == b.yaw && a.v == b.v && a.w == b.w)
            << "step " << k << ": " << a.x << " " << a.y << " against " << b.x << " " << b.y;
    }
}

TEST(NavClosedLoop, NavlogDeserializesAsLogFileRecords) {
    namespace fs = std::filesystem;
    const travel_test::TempDir tmp("travel_test_nav_navlog");
    const fs::path& dir = tmp.path;
    SimOptions o = options(SourceKind::Travel, 8.0);
    o.navlog_file = (dir / "flat.reactivenavlog").string();
    const RunReport r = runSimulation(loadWorld(kShare + "/worlds/flat_obstacles.world"), o);
    print("travel, flat_obstacles (8 s)", r);
    ASSERT_TRUE(fs::is_regular_file(o.navlog_file));

    mrpt::io::CFileGZInputStream f(o.navlog_file);
    auto arch = mrpt::serialization::archiveFrom(f);
    std::size_t records = 0, with_obstacles = 0;
    for (;;) {
        mrpt::nav::CLogFileRecord rec;
        try {
            arch.ReadObject(&rec);
        } catch (const std::exception&) {
            break;  // end of file
        }
        ++records;
        with_obstacles += rec.WS_Obstacles.size() > 0;
    }
    std::printf("navlog: %zu records, %zu with obstacles, %zu trajectory samples\n", records,
                with_obstacles, r.trajectory.size());
    // One record per navigation step (8 s at 10 Hz).
    EXPECT_GE(records, 70u);
    EXPECT_GE(with_obstacles, records / 2);
}
