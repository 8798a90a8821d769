// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// RangeImage: columns at the azimuth seam, rows from the ring field, the scan order and the
// elevation tables, on synthetic scans with exact rings and on the real scans in
// ../shared/data (skipped with a message when absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "travel/Errors.hpp"
#include "travel/Params.hpp"
#include "travel/RangeImage.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace fs = std::filesystem;

namespace travel {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

const fs::path kDataDir = fs::path(TRAVEL_DATA_DIR);
const fs::path kKittiScans = kDataDir / "semantickitti/sequences/00/velodyne";

// Finite, not a stored no-return (0, 0, 0), 3-D range in [lo, hi].
std::vector<uint8_t> validByRange(const PointCloud& cloud, double lo, double hi) {
    std::vector<uint8_t> valid(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double r =
            std::sqrt(double(cloud.x[i]) * cloud.x[i] + double(cloud.y[i]) * cloud.y[i] +
                      double(cloud.z[i]) * cloud.z[i]);
        valid[i] = std::isfinite(r) && r >= lo && r <= hi;
    }
    return valid;
}

double elevationDeg(const PointCloud& cloud, std::size_t i) {
    return std::atan2(double(cloud.z[i]), std::hypot(double(cloud.x[i]), double(cloud.y[i]))) /
           kDeg;
}

// Every valid point has a row and a column in range, every invalid one -1 / -1.
void expectAllInRange(const RangeImage& image, const std::vector<uint8_t>& valid) {
    ASSERT_EQ(image.row().size(), valid.size());
    ASSERT_EQ(image.col().size(), valid.size());
    std::size_t bad = 0;
    for (std::size_t i = 0; i < valid.size(); ++i) {
        const int row = image.row()[i], col = image.col()[i];
        if (valid[i]) {
            bad += row < 0 || row >= image.rows() || col < 0 || col >= image.cols();
        } else {
            bad += row != -1 || col != -1;
        }
    }
    EXPECT_EQ(bad, 0u) << "points with a row or column out of range";
}

struct RowStats {
    std::vector<double> mean_elevation_deg;  // NaN for empty rows
    std::vector<std::size_t> count;
    // Share of consecutive non-empty rows whose mean elevation increases.
    double increasingShare() const {
        int pairs = 0, increasing = 0;
        double previous = std::numeric_limits<double>::quiet_NaN();
        for (double m : mean_elevation_deg) {
            if (std::isnan(m)) continue;
            if (!std::isnan(previous)) ++pairs, increasing += m > previous;
            previous = m;
        }
        return pairs == 0 ? 1.0 : double(increasing) / pairs;
    }
};

RowStats rowStats(const RangeImage& image, const PointCloud& cloud,
                  const std::vector<uint8_t>& valid) {
    RowStats stats;
    stats.mean_elevation_deg.assign(image.rows(), 0.0);
    stats.count.assign(image.rows(), 0);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const int row = image.row()[i];
        if (!valid[i] || row < 0 || row >= image.rows()) continue;
        stats.mean_elevation_deg[row] += elevationDeg(cloud, i);
        ++stats.count[row];
    }
    for (int r = 0; r < image.rows(); ++r) {
        stats.mean_elevation_deg[r] = stats.count[r] > 0
                                          ? stats.mean_elevation_deg[r] / stats.count[r]
                                          : std::numeric_limits<double>::quiet_NaN();
    }
    return stats;
}

// Share of valid points whose row is within `tolerance` of truth[i].
double shareWithin(const RangeImage& image, const std::vector<uint8_t>& valid,
                   const std::vector<int>& truth, int tolerance) {
    std::size_t total = 0, close = 0;
    for (std::size_t i = 0; i < valid.size(); ++i) {
        if (!valid[i]) continue;
        ++total;
        close += std::abs(image.row()[i] - truth[i]) <= tolerance;
    }
    return total == 0 ? 1.0 : double(close) / total;
}

std::vector<int> asInts(const std::vector<uint16_t>& rings) {
    return std::vector<int>(rings.begin(), rings.end());
}

Params paramsFor(int num_rings, const char* table, const char* source = "auto") {
    Params params;
    params.num_rings = num_rings;
    params.elevation_table = table;
    params.ring_source = source;
    return params;
}

// A cloud of single points (x, y, z), all valid.
PointCloud cloudOf(const std::vector<std::vector<float>>& points) {
    PointCloud cloud;
    for (const auto& p : points) cloud.push_back(p[0], p[1], p[2]);
    return cloud;
}

// ---- Synthetic scans ----------------------------------------------------------------------

struct Sensor {
    const char* name;
    sim::LidarModel model;
    const char* table;
};

std::vector<Sensor> sensors() {
    return {{"hdl64", sim::LidarModel::hdl64(), "hdl64"},
            {"hdl32", sim::LidarModel::hdl32(), "hdl32"},
            {"vlp16", sim::LidarModel::vlp16(), "vlp16"},
            {"os128", sim::LidarModel::os128(), "os128"}};
}

// urbanObjects() inside four 40 m high walls 40 m away: every beam returns all around, as in
// a street canyon. (In an open scene the upward beams return only from a few objects; such
// rings can merge in the scan order, see ScanOrderOpenSceneKeepsElevationOrder.)
sim::Scene enclosedScene() {
    sim::Scene scene = sim::urbanObjects();
    const double d = 40.0;
    const Eigen::Vector2d corners[] = {{-d, -d}, {d, -d}, {d, d}, {-d, d}};
    for (int k = 0; k < 4; ++k) {
        sim::Wall wall;
        wall.id = 100 + k;
        wall.a = corners[k];
        wall.b = corners[(k + 1) % 4];
        wall.height = 40.0;
        scene.walls.push_back(wall);
    }
    return scene;
}

sim::Scan simulate(const sim::Scene& scene, sim::LidarModel model, sim::PointOrder order,
                   double noise = 0.0, bool emit_no_returns = false) {
    model.order = order;
    model.range_noise_sigma = noise;
    model.emit_no_returns = emit_no_returns;
    return sim::scan(scene, model,
                     sim::sensorPoseAt(scene, 0.0, 0.0, sim::kSensorHeight, 0.0, 0.0, 0.0));
}

// ---- Columns ------------------------------------------------------------------------------

TEST(RangeImageColumns, SeamAndAxes) {
    const float tiny = 1e-4f;
    // +0 and -0 in y make atan2 +180 and -180: the last and the first column (clamped formula).
    const PointCloud cloud =
        cloudOf({{1, 0, 0},
                 {-1, 0, 0},
                 {-1, -0.0f, 0},
                 {1, -tiny, 0},
                 {-1, tiny, 0},
                 {-1, -tiny, 0},
                 {0, 1, 0},
                 {0, -1, 0},
                 {std::cos(float(31.5 * kDeg)), std::sin(float(31.5 * kDeg)), 0}});
    const std::vector<uint8_t> valid(cloud.size(), 1);
    for (int columns : {2048, 360, 17}) {
        Params params = paramsFor(64, "hdl64", "table");
        params.num_columns = columns;
        RangeImage image;
        image.build(cloud, valid, params);
        ASSERT_EQ(image.cols(), columns);
        const auto& col = image.col();
        const int n = columns;
        EXPECT_EQ(col[0], n / 2) << "azimuth 0, " << n << " columns";
        EXPECT_EQ(col[1], n - 1) << "azimuth +180";
        EXPECT_EQ(col[2], 0) << "azimuth -180";
        EXPECT_EQ(col[3], (n - 1) / 2) << "just below 0";
        EXPECT_EQ(col[4], n - 1) << "just below +180";
        EXPECT_EQ(col[5], 0) << "just above -180";
        EXPECT_EQ(col[6], static_cast<int>(std::floor(0.75 * n))) << "azimuth +90";
        EXPECT_EQ(col[7], static_cast<int>(std::floor(0.25 * n))) << "azimuth -90";
        EXPECT_EQ(col[8], static_cast<int>(std::floor((211.5 / 360.0) * n))) << "azimuth +31.5";
    }
}

TEST(RangeImageColumns, MatchTheFormulaAllAround) {
    PointCloud cloud;
    const int samples = 100000;
    for (int k = 0; k < samples; ++k) {
        const double azimuth = -kPi + 2.0 * kPi * (k + 0.37) / samples;
        const double range = 1.0 + (k % 97);
        cloud.push_back(float(range * std::cos(azimuth)), float(range * std::sin(azimuth)),
                        float(0.1 * (k % 13) - 0.6));
    }
    const std::vector<uint8_t> valid(cloud.size(), 1);
    Params params = paramsFor(64, "hdl64", "table");
    params.num_columns = 2048;
    RangeImage image;
    image.build(cloud, valid, params);
    int mismatches = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double azimuth = std::atan2(double(cloud.y[i]), double(cloud.x[i]));
        const double exact = (azimuth + kPi) / (2.0 * kPi) * 2048;
        const int expected = std::clamp(static_cast<int>(std::floor(exact)), 0, 2047);
        if (image.col()[i] != expected) {
            ++mismatches;
            // Only a hair from a column boundary (the fast atan2 errs by 2e-6 rad).
            EXPECT_LT(std::abs(exact - std::round(exact)), 0.01) << "azimuth " << azimuth;
        }
    }
    EXPECT_LT(mismatches, 50);
}

// ---- Tables -------------------------------------------------------------------------------

TEST(ElevationTables, Values) {
    const auto table = [](const char* name, int num_rings = 64) {
        return elevationTableDeg(paramsFor(num_rings, name));
    };
    const auto hdl64 = table("hdl64"), hdl32 = table("hdl32"), vlp16 = table("vlp16"),
               os128 = table("os128");
    ASSERT_EQ(hdl64.size(), 64u);
    ASSERT_EQ(hdl32.size(), 32u);
    ASSERT_EQ(vlp16.size(), 16u);
    ASSERT_EQ(os128.size(), 128u);
    for (const auto* t : {&hdl64, &hdl32, &vlp16, &os128}) {
        EXPECT_TRUE(std::is_sorted(t->begin(), t->end()));
        EXPECT_EQ(std::adjacent_find(t->begin(), t->end()), t->end());
    }
    EXPECT_NEAR(hdl64.front(), -25.5, 1.0);
    EXPECT_NEAR(hdl64.back(), 2.0, 0.2);
    EXPECT_NEAR(hdl32.front(), -30.67, 1e-9);
    EXPECT_NEAR(hdl32.back(), 10.67, 1e-9);
    EXPECT_NEAR(hdl32[1] - hdl32[0], 1.3336, 1e-3);
    EXPECT_EQ(vlp16.front(), -15.0);
    EXPECT_EQ(vlp16.back(), 15.0);
    EXPECT_NEAR(vlp16[1] - vlp16[0], 2.0, 1e-12);
    EXPECT_EQ(os128.front(), -22.5);
    EXPECT_EQ(os128.back(), 22.5);

    Params uniform = paramsFor(5, "uniform");
    uniform.min_elevation_deg = -10.0;
    uniform.max_elevation_deg = 10.0;
    EXPECT_EQ(elevationTableDeg(uniform), (std::vector<double>{-10, -5, 0, 5, 10}));
    uniform.num_rings = 1;
    EXPECT_EQ(elevationTableDeg(uniform), std::vector<double>{-10.0});

    Params unknown;
    unknown.elevation_table = "hdl128";
    EXPECT_THROW(elevationTableDeg(unknown), ConfigError);
}

// Far points (the hdl64 table's 0.2 m beam origin is negligible at 1 km) at each beam's
// elevation, and 40 % of the way to each neighbour, find that beam.
TEST(RangeImageTable, NearestBeam) {
    for (const char* name : {"hdl64", "hdl32", "vlp16", "os128", "uniform"}) {
        Params params = paramsFor(40, name, "table");
        const std::vector<double> table = elevationTableDeg(params);
        PointCloud cloud;
        std::vector<int> expected;
        const double range = 1000.0;
        for (std::size_t k = 0; k < table.size(); ++k) {
            for (double toward : {-0.4, 0.0, 0.4}) {
                const std::size_t neighbour =
                    toward < 0 ? (k == 0 ? k : k - 1) : (k + 1 < table.size() ? k + 1 : k);
                const double elevation =
                    table[k] + std::fabs(toward) * (table[neighbour] - table[k]);
                const double azimuth = 0.1 * double(expected.size());
                cloud.push_back(float(range * std::cos(elevation * kDeg) * std::cos(azimuth)),
                                float(range * std::cos(elevation * kDeg) * std::sin(azimuth)),
                                float(range * std::sin(elevation * kDeg)));
                expected.push_back(int(k));
            }
        }
        const std::vector<uint8_t> valid(cloud.size(), 1);
        RangeImage image;
        image.build(cloud, valid, params);
        EXPECT_EQ(image.source(), RingSource::Table);
        EXPECT_EQ(image.rows(), int(table.size())) << name;
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            EXPECT_EQ(image.row()[i], expected[i]) << name << " point " << i;
        }
    }
}

// Points above the top beam, below the lowest, straight up or down, at the origin, NaN or
// infinite: valid or not, no row or column is ever out of range.
TEST(RangeImageTable, OddPointsStayInRange) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const PointCloud cloud = cloudOf({{10, 0, 50},     // 79 deg up
                                      {10, 0, -50},    // 79 deg down
                                      {0, 0, 5},       // straight up
                                      {0, 0, -5},      // straight down
                                      {0, 0, 0},       // no-return zeros
                                      {nan, 1, 1},     // NaN
                                      {1, nan, 1},     //
                                      {1, 1, nan},     //
                                      {inf, 1, 1},     // infinite
                                      {1, -inf, 1},    //
                                      {1, 1, inf},     //
                                      {-inf, inf, 0},  //
                                      {1e-30f, 1e-30f, 1e-30f},
                                      {3e38f, 3e38f, -3e38f}});
    for (const char* name : {"hdl64", "hdl32", "vlp16", "os128", "uniform"}) {
        for (uint8_t flag : {uint8_t{1}, uint8_t{0}}) {
            const std::vector<uint8_t> valid(cloud.size(), flag);
            RangeImage image;
            image.build(cloud, valid, paramsFor(64, name, "table"));
            expectAllInRange(image, valid);
            if (flag) {
                EXPECT_EQ(image.row()[0], image.rows() - 1) << name << ": above the top beam";
                EXPECT_EQ(image.row()[1], 0) << name << ": below the lowest beam";
                EXPECT_EQ(image.row()[2], image.rows() - 1) << name << ": straight up";
                EXPECT_EQ(image.row()[3], 0) << name << ": straight down";
            }
        }
    }
}

// A named table fixes the rows; num_rings only sizes the uniform table.
TEST(RangeImageTable, TableSizeWins) {
    const PointCloud cloud = cloudOf({{10, 0, 0}, {10, 0, 5}});
    const std::vector<uint8_t> valid(cloud.size(), 1);
    RangeImage image;
    image.build(cloud, valid, paramsFor(64, "vlp16", "table"));
    EXPECT_EQ(image.rows(), 16);
    EXPECT_EQ(image.row()[1], 15);
    image.build(cloud, valid, paramsFor(7, "uniform", "table"));
    EXPECT_EQ(image.rows(), 7);
}

// ---- Ring field ---------------------------------------------------------------------------

TEST(RangeImageField, AscendingReversedAndPermutedNumberings) {
    const sim::Scan scan =
        simulate(sim::urbanObjects(), sim::LidarModel::hdl32(), sim::PointOrder::ColumnMajor);
    const std::vector<uint8_t> valid = validByRange(scan.cloud, 1.0, 100.0);
    const std::vector<int> truth = asInts(scan.cloud.ring);
    const Params params = paramsFor(32, "hdl32");
    RangeImage image;

    image.build(scan.cloud, valid, params);
    EXPECT_EQ(image.source(), RingSource::Field);
    EXPECT_EQ(image.rows(), 32);
    expectAllInRange(image, valid);
    EXPECT_EQ(shareWithin(image, valid, truth, 0), 1.0);

    // Ring 0 = top beam (Ouster drivers).
    PointCloud reversed = scan.cloud;
    for (auto& ring : reversed.ring) ring = static_cast<uint16_t>(31 - ring);
    image.build(reversed, valid, params);
    EXPECT_EQ(image.source(), RingSource::Field);
    EXPECT_EQ(shareWithin(image, valid, truth, 0), 1.0);

    // Interleaved laser ids (raw Velodyne order): even beams first, then odd ones.
    PointCloud interleaved = scan.cloud;
    for (auto& ring : interleaved.ring) ring = static_cast<uint16_t>((ring % 2) * 16 + ring / 2);
    image.build(interleaved, valid, params);
    EXPECT_EQ(image.source(), RingSource::Field);
    EXPECT_EQ(shareWithin(image, valid, truth, 0), 1.0);

    // Fewer rings numbered than num_rings: rows keep the field's numbers.
    image.build(scan.cloud, valid, paramsFor(64, "hdl32"));
    EXPECT_EQ(image.rows(), 64);
    EXPECT_EQ(shareWithin(image, valid, truth, 0), 1.0);
}

TEST(RangeImageField, RingsOutOfRange) {
    sim::Scan scan =
        simulate(sim::urbanObjects(), sim::LidarModel::vlp16(), sim::PointOrder::ColumnMajor);
    std::vector<uint8_t> valid = validByRange(scan.cloud, 1.0, 100.0);
    const std::vector<int> truth = asInts(scan.cloud.ring);
    RangeImage image;

    // Invalid points may carry any ring.
    valid[0] = 0;
    scan.cloud.ring[0] = 60000;
    image.build(scan.cloud, valid, paramsFor(16, "vlp16"));
    EXPECT_EQ(image.source(), RingSource::Field);
    EXPECT_EQ(shareWithin(image, valid, truth, 0), 1.0);

    // A valid point's ring >= num_rings: auto moves on (column-major: to the table), a forced
    // field is an error naming the ring.
    valid[0] = 1;
    image.build(scan.cloud, valid, paramsFor(16, "vlp16"));
    EXPECT_EQ(image.source(), RingSource::Table);
    expectAllInRange(image, valid);
    try {
        image.build(scan.cloud, valid, paramsFor(16, "vlp16", "field"));
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("60000"), std::string::npos) << e.what();
    }
    PointCloud no_ring = scan.cloud;
    no_ring.ring.clear();
    EXPECT_THROW(image.build(no_ring, valid, paramsFor(16, "vlp16", "field")), InputError);
}

// ---- Scan order ---------------------------------------------------------------------------

TEST(RangeImageScanOrder, RecoversTheRingsOfRingMajorScans) {
    const sim::Scene scene = enclosedScene();
    for (const Sensor& sensor : sensors()) {
        for (double noise : {0.0, 0.02}) {
            sim::Scan scan = simulate(scene, sensor.model, sim::PointOrder::RingMajor, noise);
            const std::vector<int> truth = asInts(scan.cloud.ring);
            scan.cloud.ring.clear();
            const std::vector<uint8_t> valid = validByRange(scan.cloud, 1.0, 200.0);
            const int beams = int(sensor.model.numBeams());
            RangeImage image;
            image.build(scan.cloud, valid, paramsFor(beams, sensor.table));
            EXPECT_EQ(image.source(), RingSource::ScanOrder) << sensor.name;
            EXPECT_EQ(image.rows(), beams);
            expectAllInRange(image, valid);
            EXPECT_GE(shareWithin(image, valid, truth, 0), 0.999)
                << sensor.name << ", noise " << noise;
        }
    }
}

// Stored no-returns (zeros), NaN points and points the caller marked invalid do not break the
// walk, and a cloud stored backwards (top ring first, clockwise, like the ouster128 sample) is
// recovered too.
TEST(RangeImageScanOrder, ZerosNaNsAndBackwardStorage) {
    sim::Scan scan = simulate(enclosedScene(), sim::LidarModel::hdl64(), sim::PointOrder::RingMajor,
                              0.0, /*emit_no_returns=*/true);
    std::vector<int> truth = asInts(scan.cloud.ring);
    scan.cloud.ring.clear();
    PointCloud& cloud = scan.cloud;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 5; i < cloud.size(); i += 101) cloud.x[i] = nan;
    for (std::size_t i = 0; i < cloud.size(); i += 7) cloud.x[i] = cloud.y[i] = cloud.z[i] = 0;
    std::vector<uint8_t> valid = validByRange(cloud, 1.0, 200.0);
    for (std::size_t i = 3; i < valid.size(); i += 5) valid[i] = 0;  // e.g. range-filtered

    RangeImage image;
    image.build(cloud, valid, paramsFor(64, "hdl64"));
    EXPECT_EQ(image.source(), RingSource::ScanOrder);
    expectAllInRange(image, valid);
    EXPECT_GE(shareWithin(image, valid, truth, 0), 0.999);

    std::reverse(cloud.x.begin(), cloud.x.end());
    std::reverse(cloud.y.begin(), cloud.y.end());
    std::reverse(cloud.z.begin(), cloud.z.end());
    std::reverse(valid.begin(), valid.end());
    std::reverse(truth.begin(), truth.end());
    image.build(cloud, valid, paramsFor(64, "hdl64"));
    EXPECT_EQ(image.source(), RingSource::ScanOrder);
    expectAllInRange(image, valid);
    EXPECT_GE(shareWithin(image, valid, truth, 0), 0.999);
}

// Points stored column by column have no azimuth wrap-around per ring: auto rejects the scan
// order and uses the table, which finds the simulated beams (within one row: 100 % here).
TEST(RangeImageScanOrder, ColumnMajorFallsBackToTheTable) {
    for (const Sensor& sensor : sensors()) {
        // The hdl64 table is KITTI's (measured, from 0.2 m above the origin), not the simulated
        // nominal blocks.
        if (std::string(sensor.name) == "hdl64") continue;
        sim::Scan scan = simulate(sim::urbanObjects(), sensor.model, sim::PointOrder::ColumnMajor);
        const std::vector<int> truth = asInts(scan.cloud.ring);
        scan.cloud.ring.clear();
        const std::vector<uint8_t> valid = validByRange(scan.cloud, 1.0, 200.0);
        const int beams = int(sensor.model.numBeams());
        RangeImage image;
        image.build(scan.cloud, valid, paramsFor(beams, sensor.table));
        EXPECT_EQ(image.source(), RingSource::Table) << sensor.name;
        expectAllInRange(image, valid);
        EXPECT_GE(shareWithin(image, valid, truth, 1), 0.99) << sensor.name;
        EXPECT_THROW(image.build(scan.cloud, valid, paramsFor(beams, sensor.table, "scan_order")),
                     InputError);
    }
}

// Rings stored one after another but not in elevation order: auto rejects the scan order and
// uses the table, whether the disorder shows in the first rings found (the walk stops there)
// or only in the last one; ring_source = scan_order keeps the rings and sorts them by elevation.
TEST(RangeImageScanOrder, RingsOutOfElevationOrder) {
    const sim::Scan scan =
        simulate(enclosedScene(), sim::LidarModel::vlp16(), sim::PointOrder::RingMajor);
    const int beams = 16;
    // Storage orders of the rings: the first rings shuffled; only the lowest ring out of place.
    const std::vector<std::vector<int>> orders = {
        {9, 2, 14, 5, 0, 11, 7, 3, 15, 1, 12, 8, 4, 13, 6, 10},
        {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 0}};
    for (const std::vector<int>& order : orders) {
        PointCloud cloud;
        std::vector<int> truth;
        for (const int ring : order) {
            for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
                if (scan.cloud.ring[i] != ring) continue;
                cloud.push_back(scan.cloud.x[i], scan.cloud.y[i], scan.cloud.z[i]);
                truth.push_back(ring);
            }
        }
        const std::vector<uint8_t> valid = validByRange(cloud, 1.0, 200.0);
        RangeImage image;
        image.build(cloud, valid, paramsFor(beams, "vlp16"));
        EXPECT_EQ(image.source(), RingSource::Table) << "storage order from ring " << order[0];
        expectAllInRange(image, valid);
        image.build(cloud, valid, paramsFor(beams, "vlp16", "scan_order"));
        EXPECT_EQ(image.source(), RingSource::ScanOrder);
        EXPECT_GE(shareWithin(image, valid, truth, 0), 0.999) << "storage order from " << order[0];
    }
}

// In an open scene the upward beams return only from a few objects, and a ring whose returns
// end before the next ring's begin (in azimuth) is merged with it: fewer rows, still in
// elevation order, still within one row of the truth for almost every point.
TEST(RangeImageScanOrder, OpenSceneKeepsElevationOrder) {
    sim::Scan scan =
        simulate(sim::urbanObjects(), sim::LidarModel::vlp16(), sim::PointOrder::RingMajor);
    const std::vector<int> truth = asInts(scan.cloud.ring);
    scan.cloud.ring.clear();
    const std::vector<uint8_t> valid = validByRange(scan.cloud, 1.0, 200.0);
    RangeImage image;
    image.build(scan.cloud, valid, paramsFor(16, "vlp16"));
    EXPECT_EQ(image.source(), RingSource::ScanOrder);
    expectAllInRange(image, valid);
    EXPECT_EQ(rowStats(image, scan.cloud, valid).increasingShare(), 1.0);
    EXPECT_GE(shareWithin(image, valid, truth, 1), 0.99);
}

TEST(RangeImage, ReusesItsBuffersAndChecksItsInput) {
    const sim::Scan scan =
        simulate(sim::urbanObjects(), sim::LidarModel::vlp16(), sim::PointOrder::RingMajor);
    const std::vector<uint8_t> valid = validByRange(scan.cloud, 1.0, 100.0);
    RangeImage image;
    image.build(scan.cloud, valid, paramsFor(16, "vlp16"));
    const int16_t* rows = image.row().data();
    const int32_t* cols = image.col().data();
    image.build(scan.cloud, valid, paramsFor(16, "vlp16", "table"));
    EXPECT_EQ(image.row().data(), rows);
    EXPECT_EQ(image.col().data(), cols);

    EXPECT_THROW(image.build(scan.cloud, std::vector<uint8_t>(3, 1), Params()),
                 std::invalid_argument);
    Params bad;
    bad.ring_source = "laser";
    EXPECT_THROW(image.build(scan.cloud, valid, bad), ConfigError);

    PointCloud empty;
    image.build(empty, {}, Params());
    EXPECT_TRUE(image.row().empty());
    EXPECT_EQ(image.cols(), Params().num_columns);
}

// ---- Real scans ---------------------------------------------------------------------------

std::string frameName(int i) {
    char name[16];
    std::snprintf(name, sizeof name, "%06d", i);
    return name;
}

// KITTI's rings by the usual recipe: KITTI frames are cut at azimuth 0 and each laser sweeps
// counter-clockwise, so a ring starts where the azimuth crosses 0 upwards; the top laser is
// stored first.
std::vector<int> kittiReferenceRows(const PointCloud& cloud) {
    std::vector<int> rows(cloud.size());
    int ring = 0;
    double previous = std::atan2(double(cloud.y[0]), double(cloud.x[0]));
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double azimuth = std::atan2(double(cloud.y[i]), double(cloud.x[i]));
        if (i > 0 && previous < 0 && azimuth >= 0 && azimuth - previous < kPi) ++ring;
        previous = azimuth;
        rows[i] = 63 - ring;
    }
    return rows;
}

TEST(RangeImageReal, KittiScanOrder) {
    if (!fs::exists(kKittiScans / "000005.bin")) {
        GTEST_SKIP() << "SemanticKITTI scans not found in " << kKittiScans
                     << " (../shared/data is not part of the repository)";
    }
    PointCloud cloud;
    RangeImage image, table_image;
    for (int f = 0; f < 6; ++f) {
        readScan((kKittiScans / (frameName(f) + ".bin")).string(), cloud, ScanFormat::KittiBin);
        const std::vector<uint8_t> valid = validByRange(cloud, 2.7, 80.0);
        image.build(cloud, valid, Params());
        EXPECT_EQ(image.source(), RingSource::ScanOrder) << frameName(f);
        EXPECT_EQ(image.rows(), 64);
        expectAllInRange(image, valid);
        const RowStats stats = rowStats(image, cloud, valid);
        EXPECT_GE(stats.increasingShare(), 0.95) << frameName(f);
        for (int r = 0; r < 64; ++r) EXPECT_GT(stats.count[r], 500u) << "row " << r;
        const std::vector<int> reference = kittiReferenceRows(cloud);
        EXPECT_GE(shareWithin(image, valid, reference, 0), 0.998) << frameName(f);

        // The measured hdl64 table, when the scan order is not available.
        table_image.build(cloud, valid, paramsFor(64, "hdl64", "table"));
        expectAllInRange(table_image, valid);
        const std::vector<int> scan_rows(image.row().begin(), image.row().end());
        EXPECT_GE(shareWithin(table_image, valid, scan_rows, 1), 0.95) << frameName(f);
        EXPECT_GE(shareWithin(table_image, valid, scan_rows, 0), 0.75) << frameName(f);
    }
}

TEST(RangeImageReal, NuScenesRingField) {
    const fs::path path = kDataDir / "nuscenes/hdl32_000000.bin";
    if (!fs::exists(path)) GTEST_SKIP() << path << " not found";
    PointCloud cloud;
    readScan(path.string(), cloud, ScanFormat::NuScenesBin);
    const std::vector<uint8_t> valid = validByRange(cloud, 1.0, 70.0);
    const std::vector<int> field = asInts(cloud.ring);
    const Params params = paramsFor(32, "hdl32");
    RangeImage image;
    image.build(cloud, valid, params);
    EXPECT_EQ(image.source(), RingSource::Field);
    EXPECT_EQ(image.rows(), 32);
    expectAllInRange(image, valid);
    // nuScenes numbers the rings from the lowest beam: the field is kept as is.
    EXPECT_EQ(shareWithin(image, valid, field, 0), 1.0);
    const RowStats stats = rowStats(image, cloud, valid);
    EXPECT_EQ(stats.increasingShare(), 1.0);
    EXPECT_NEAR(stats.mean_elevation_deg.front(), -30.67, 0.5);
    EXPECT_NEAR(stats.mean_elevation_deg.back(), 10.67, 0.5);

    // The same frame numbered top-down, or by interleaved laser ids, gives the same rows.
    PointCloud renumbered = cloud;
    for (auto& ring : renumbered.ring) ring = static_cast<uint16_t>(31 - ring);
    image.build(renumbered, valid, params);
    EXPECT_EQ(shareWithin(image, valid, field, 0), 1.0);
    renumbered = cloud;
    for (auto& ring : renumbered.ring) ring = static_cast<uint16_t>((ring % 2) * 16 + ring / 2);
    image.build(renumbered, valid, params);
    EXPECT_EQ(shareWithin(image, valid, field, 0), 1.0);

    // Without the field (stored column by column): the hdl32 table.
    renumbered.ring.clear();
    image.build(renumbered, valid, params);
    EXPECT_EQ(image.source(), RingSource::Table);
    EXPECT_GE(shareWithin(image, valid, field, 1), 0.97);
}

// The 128-beam sample is in a ground-level frame, not the sensor's: elevations are distorted,
// but every point still gets a row and a column in range.
TEST(RangeImageReal, Ouster128) {
    const fs::path path = kDataDir / "ouster128/000000.bin";
    if (!fs::exists(path)) GTEST_SKIP() << path << " not found";
    PointCloud cloud;
    readScan(path.string(), cloud, ScanFormat::KittiBin);
    const std::vector<uint8_t> valid = validByRange(cloud, 0.5, 60.0);
    RangeImage image;
    image.build(cloud, valid, paramsFor(128, "os128", "table"));
    EXPECT_EQ(image.source(), RingSource::Table);
    EXPECT_EQ(image.rows(), 128);
    expectAllInRange(image, valid);
    EXPECT_EQ(rowStats(image, cloud, valid).increasingShare(), 1.0);

    image.build(cloud, valid, paramsFor(128, "os128"));
    expectAllInRange(image, valid);
}

}  // namespace
}  // namespace travel
