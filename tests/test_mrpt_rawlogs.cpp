// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// TravelFilter on the two real rawlogs of Debian's mrpt-common: the same VLP-16 sweep stored as
// a CObservationVelodyneScan (raw packets) and as a CObservationRotatingScan (range image).
// Checks: the two encodings give the same classes; the floor around the sensor is ground and
// nothing clearly above it is; and the output summary is pinned (regression).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plugin/SampleLabelling.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace {

using travel::PointClass;

const std::string kConfig =
    std::string(TRAVEL_SHARE_DIR_FOR_TESTS) + "/configs/mrpt_sample_vlp16.yaml";
// The sensor of both samples is 2.24 m above a flat floor (sensor_height in the config).
constexpr double kSensorHeight = 2.24;

/// The first LiDAR frame of `path` through a fresh filter configured like the README's demo.
/// The filter is kept with the frame: frame.aligned points into its pipeline.
struct FilteredFrame {
    travel_mrpt::TravelFilter filter;
    travel_mrpt::TravelFrame frame;
};

std::unique_ptr<FilteredFrame> runFilter(const std::string& path) {
    auto out = std::make_unique<FilteredFrame>();
    out->filter.loadConfigFile(kConfig);
    bool done = false;
    travel_test::forEachObservation(path, [&](const mrpt::obs::CObservation::Ptr& obs) {
        if (!done && obs) done = out->filter.filter(*obs, out->frame);
    });
    if (!done) throw std::runtime_error(path + ": no LiDAR frame");
    return out;
}

#define SKIP_WITHOUT_SAMPLES()                                                                 \
    if (!travel_test::fileExists(travel_test::kVlp16Rawlog) ||                                 \
        !travel_test::fileExists(travel_test::kRotScanRawlog))                                 \
    GTEST_SKIP() << "mrpt-common's sample rawlogs not found in " << travel_test::kMrptDatasets \
                 << " (install the mrpt-common package)"

/// Points of both encodings matched by beam: same ring, nearest azimuth (within
/// `max_azimuth_deg`) and the same range (within `max_range_diff`). The two clouds are not in
/// the same order (packets vs range-image columns) and the range image rebuilds each point from
/// its column's azimuth, so positions differ by a few cm at 10 m.
struct Agreement {
    std::size_t compared = 0, agree = 0, unmatched = 0;
};

Agreement compareByBeam(const travel_mrpt::TravelFrame& a, const travel_mrpt::TravelFrame& b,
                        double max_azimuth_deg, double max_range_diff) {
    constexpr double kDeg = 180.0 / M_PI;
    struct Beam {
        double azimuth, range;
        std::size_t index;
    };
    const auto beamOf = [&](const travel::PointCloud& c, std::size_t i) {
        return Beam{std::atan2(c.y[i], c.x[i]) * kDeg,
                    std::sqrt(c.x[i] * c.x[i] + c.y[i] * c.y[i] + c.z[i] * c.z[i]), i};
    };
    std::vector<std::vector<Beam>> rings;
    for (std::size_t i = 0; i < a.cloud.size(); ++i) {
        if (a.result.labels[i] == PointClass::Invalid) continue;
        const std::size_t r = a.cloud.ring[i];
        if (rings.size() <= r) rings.resize(r + 1);
        rings[r].push_back(beamOf(a.cloud, i));
    }
    for (auto& ring : rings)
        std::sort(ring.begin(), ring.end(),
                  [](const Beam& p, const Beam& q) { return p.azimuth < q.azimuth; });
    Agreement r;
    for (std::size_t j = 0; j < b.cloud.size(); ++j) {
        if (b.result.labels[j] == PointClass::Invalid) continue;
        const Beam q = beamOf(b.cloud, j);
        const std::size_t ring_index = b.cloud.ring[j];
        const Beam* best = nullptr;
        if (ring_index < rings.size()) {
            const auto& ring = rings[ring_index];
            auto it = std::lower_bound(ring.begin(), ring.end(), q.azimuth,
                                       [](const Beam& p, double az) { return p.azimuth < az; });
            for (auto c : {it, it == ring.begin() ? it : std::prev(it)}) {
                if (c == ring.end()) continue;
                if (std::abs(c->azimuth - q.azimuth) > max_azimuth_deg ||
                    std::abs(c->range - q.range) > max_range_diff)
                    continue;
                if (!best || std::abs(c->azimuth - q.azimuth) < std::abs(best->azimuth - q.azimuth))
                    best = &*c;
            }
        }
        if (!best) {
            ++r.unmatched;
            continue;
        }
        ++r.compared;
        r.agree += a.result.labels[best->index] == b.result.labels[j];
    }
    return r;
}

TEST(MrptSampleRawlogs, VelodyneAndRotatingScanGiveTheSameClasses) {
    SKIP_WITHOUT_SAMPLES();
    const auto velodyne_run = runFilter(travel_test::kVlp16Rawlog);
    const auto rotating_run = runFilter(travel_test::kRotScanRawlog);
    const auto& velodyne = velodyne_run->frame;
    const auto& rotating = rotating_run->frame;
    ASSERT_EQ(velodyne.cloud.size(), rotating.cloud.size());
    ASSERT_EQ(velodyne.cloud.ring.size(), velodyne.cloud.size());
    ASSERT_EQ(rotating.cloud.ring.size(), rotating.cloud.size());
    const Agreement r = compareByBeam(velodyne, rotating, 0.3, 0.1);
    const double matched = static_cast<double>(r.compared) / (r.compared + r.unmatched);
    const double agreement = static_cast<double>(r.agree) / r.compared;
    std::printf(
        "velodyne vs rotating scan: %zu points matched (%.2f %%), %zu unmatched, same class "
        "for %.2f %%\n",
        r.compared, 100 * matched, r.unmatched, 100 * agreement);
    EXPECT_GE(matched, 0.98);
    EXPECT_GE(agreement, 0.99);
}

TEST(MrptSampleRawlogs, FloorAroundTheSensorIsGroundAndRaisedStructureIsNot) {
    SKIP_WITHOUT_SAMPLES();
    // The sample is outdoors: the terrain rises and falls by about a metre within 30 m, so
    // "floor" is checked where the sensor height is known (the floor ring, 8-15 m: the lowest
    // beam is at -15 deg) and "raised" against the lowest point of each 1 m x 1 m column.
    for (const std::string& path : {travel_test::kVlp16Rawlog, travel_test::kRotScanRawlog}) {
        SCOPED_TRACE(path);
        const auto run = runFilter(path);
        const auto& f = run->frame;
        ASSERT_NE(f.aligned, nullptr);
        const travel::AlignedCloud& a = *f.aligned;
        const auto column = [&](std::size_t i) {
            return std::make_pair(static_cast<long>(std::floor(a.x[i])),
                                  static_cast<long>(std::floor(a.y[i])));
        };
        std::map<std::pair<long, long>, float> lowest;
        for (std::size_t i = 0; i < f.cloud.size(); ++i) {
            if (!a.valid[i]) continue;
            auto [it, inserted] = lowest.try_emplace(column(i), a.z[i]);
            if (!inserted) it->second = std::min(it->second, a.z[i]);
        }
        std::size_t floor = 0, floor_ground = 0, raised = 0, raised_ground = 0;
        for (std::size_t i = 0; i < f.cloud.size(); ++i) {
            if (!a.valid[i]) continue;
            const double h = a.z[i] + kSensorHeight, r = std::hypot(a.x[i], a.y[i]);
            const bool ground = f.result.labels[i] == PointClass::Ground;
            if (r < 15 && std::abs(h) < 0.15) ++floor, floor_ground += ground;
            if (a.z[i] - lowest[column(i)] > 1.0) ++raised, raised_ground += ground;
        }
        std::printf(
            "%s: floor 8-15 m around the sensor: %zu points, %.1f %% ground; points more "
            "than 1 m above the lowest point of their 1 m column: %zu, %zu ground\n",
            path.c_str(), floor, 100.0 * floor_ground / std::max<std::size_t>(floor, 1), raised,
            raised_ground);
        ASSERT_GT(floor, 500u);
        EXPECT_GE(static_cast<double>(floor_ground) / floor, 0.85);  // measured 0.898 and 0.894
        ASSERT_GT(raised, 3000u);                                    // walls, trees, poles
        EXPECT_EQ(raised_ground, 0u);
    }
}

TEST(MrptSampleRawlogs, SummaryIsPinned) {
    SKIP_WITHOUT_SAMPLES();
    // Measured on the landed code (Release, this config; ground +2.7 % with the own and
    // neighbour planes of clear nodes, issue 14; outliers 46 / 44 -> 23 with the ditch rule of
    // 9b2ae7c: 15 floor points 14.3 m out (0.03 m below the floor), 6-8 at 12.9 m where the
    // floor falls 0.26 m, and one 0.3 m under a raised floor are ground); the tolerances leave
    // room for deliberate algorithm changes of a few per cent, not for a regression.
    struct Expected {
        const std::string& path;
        std::size_t ground, nonground, outlier, invalid, clusters;
    };
    for (const Expected& e : {Expected{travel_test::kVlp16Rawlog, 2834, 8372, 23, 76, 66},
                              Expected{travel_test::kRotScanRawlog, 2815, 8391, 23, 76, 65}}) {
        SCOPED_TRACE(e.path);
        const auto run = runFilter(e.path);
        const auto& f = run->frame;
        const auto& r = f.result;
        EXPECT_EQ(f.cloud.size(), 11305u);
        EXPECT_EQ(r.count(PointClass::Invalid), e.invalid);  // exact: no return / out of range
        EXPECT_NEAR(double(r.count(PointClass::Ground)), double(e.ground), 0.02 * e.ground);
        EXPECT_NEAR(double(r.count(PointClass::NonGround)), double(e.nonground),
                    0.02 * e.nonground);
        EXPECT_NEAR(double(r.count(PointClass::Outlier)), double(e.outlier), 20.0);
        EXPECT_NEAR(double(r.clusters.size()), double(e.clusters), 0.15 * e.clusters);
    }
}

}  // namespace
