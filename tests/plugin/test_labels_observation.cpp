// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// CObservationTravelLabels in one process: filling from real and synthetic TRAVEL results,
// serialization round trips, corrupt streams, description text and 3-D view.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/opengl/CArrow.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/rtti/CObject.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include "SampleLabelling.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/Registration.hpp"

using travel::PointClass;
using travel_mrpt::CObservationTravelLabels;

namespace {

const std::string kConfig =
    std::string(TRAVEL_SHARE_DIR_FOR_TESTS) + "/configs/mrpt_sample_vlp16.yaml";

// Labels of the first Velodyne scan of MRPT's VLP-16 sample (null when the file is absent).
CObservationTravelLabels::Ptr labelVlp16Sample() {
    if (!travel_test::fileExists(travel_test::kVlp16Rawlog)) return nullptr;
    mrpt::obs::CObservationVelodyneScan::Ptr scan;
    travel_test::forEachObservation(travel_test::kVlp16Rawlog, [&](const auto& obs) {
        if (!scan) scan = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(obs);
    });
    if (!scan) return nullptr;
    travel_test::SampleLabeller labeller(kConfig);
    auto labels = CObservationTravelLabels::Create();
    if (!labeller.label(*scan, *labels)) return nullptr;
    return labels;
}

#define SKIP_WITHOUT_SAMPLE(obs)                                \
    if (!(obs))                                                 \
    GTEST_SKIP() << "MRPT sample " << travel_test::kVlp16Rawlog \
                 << " not found (Debian package mrpt-common): nothing to check"

// Urban scene (cars, poles, walls) seen by a synthetic VLP-16 with no-returns.
CObservationTravelLabels::Ptr labelSyntheticScan() {
    travel::sim::LidarModel lidar = travel::sim::LidarModel::vlp16();
    lidar.emit_no_returns = true;
    lidar.range_noise_sigma = 0.01;
    lidar.seed = 7;
    const travel::sim::Scene scene = travel::sim::urbanObjects();
    const travel::sim::Scan scan = travel::sim::scan(
        scene, lidar, travel::sim::sensorPoseAt(scene, 0, 0, travel::sim::kSensorHeight, 0, 0, 0));
    travel::Params params;
    params.sensor_height = travel::sim::kSensorHeight;
    travel::Pipeline pipeline(params);
    travel::Result result;
    pipeline.process(scan.cloud, {}, result);
    auto labels = CObservationTravelLabels::Create();
    labels->assign(scan.cloud, result, pipeline.aligned().rotation);
    labels->sensorPose = mrpt::poses::CPose3D(0.1, -0.2, 1.8, 0.3, 0.02, -0.01);
    labels->sourceClass = "travel::sim::Scan";
    labels->sensorLabel = "SIM_VLP16";
    labels->timestamp = mrpt::Clock::fromDouble(1700000000.25);
    return labels;
}

// A small hand-made observation (6 points, 2 clusters, 2 terrain nodes): the content of the
// version-0 fixture tests/plugin/data/travel_labels_v0.bin, written by the version-0 code.
CObservationTravelLabels::Ptr smallObservation() {
    auto o = CObservationTravelLabels::Create();
    o->sensorLabel = "SMALL";
    o->sourceClass = "mrpt::obs::CObservationPointCloud";
    o->timestamp = mrpt::Clock::fromDouble(1700000001.5);
    o->sensorPose = mrpt::poses::CPose3D(0.5, 0.0, 1.2, 0.1, 0.0, 0.0);
    o->x = {1.f, 2.f, 3.f, 4.f, 5.f, 6.f};
    o->y = {0.f, 0.5f, 1.f, -1.f, -2.f, 0.f};
    o->z = {-1.2f, 0.2f, 0.4f, 0.3f, 0.5f, 0.f};
    o->intensity = {10.f, 20.f, 30.f, 40.f, 50.f, 0.f};
    o->labels = {1, 2, 2, 2, 3, 0};
    o->clusterId = {0, 1, 1, 2, 0, 0};
    for (uint32_t k = 1; k <= 2; ++k) {
        travel::ClusterSummary& c = o->clusters.emplace_back();
        c.id = k;
        c.num_points = k == 1 ? 2 : 1;
        c.first_point = k == 1 ? 1 : 3;
        c.centroid = {2.5f * k, 0.75f - k, 0.3f};
        c.aabb_min = c.centroid - Eigen::Vector3f(0.5f, 0.4f, 0.3f);
        c.aabb_max = c.centroid + Eigen::Vector3f(0.5f, 0.4f, 0.3f);
        c.obb_yaw = 0.25f * k;
        c.obb_center = c.centroid;
        c.obb_extent = {1.f, 0.8f, 0.6f};
        c.ground_z = -1.2f;
        c.height_above_ground = 1.5f;
    }
    o->terrain.resolution = 4.f;
    o->terrain.cells_per_side = 2;
    o->terrain.origin_xy = -4.f;
    for (uint32_t index : {0u, 5u}) {
        travel::TerrainNodeRecord& n = o->terrain.nodes.emplace_back();
        n.index = index;
        n.node_class = travel::NodeClass::Terrain;
        n.traversable = index == 0;
        n.refitted = true;
        n.d = 1.2f;
        n.corner_z = {-1.2f, -1.1f, -1.3f};
        n.mean = {1.f, 1.f, -1.2f};
    }
    o->timings.ground_total = 1.25;
    o->timings.objects_total = 2.5;
    return o;
}

// smallObservation() as the tracker leaves it: cluster 1 a moving track, cluster 2 a parked one.
CObservationTravelLabels::Ptr smallTrackedObservation(uint32_t moving_track = 70001,
                                                      uint32_t parked_track = 42) {
    auto o = smallObservation();
    travel::ClusterSummary &moving = o->clusters[0], &parked = o->clusters[1];
    moving.track_id = moving_track;
    moving.velocity = {4.f, -1.f, 0.f};
    moving.velocity_sigma = {0.2f, 0.3f, 0.05f};
    moving.moving = true;
    parked.track_id = parked_track;
    parked.velocity = {0.02f, 0.f, 0.f};
    parked.velocity_sigma = {0.1f, 0.1f, 0.1f};
    return o;
}

std::vector<uint8_t> serialize(const CObservationTravelLabels& obs) {
    mrpt::io::CMemoryStream mem;
    auto out = mrpt::serialization::archiveFrom(mem);
    out << obs;
    const auto* p = static_cast<const uint8_t*>(mem.getRawBufferData());
    return {p, p + mem.getTotalBytesCount()};
}

// Reads one object back; throws whatever the reader throws.
CObservationTravelLabels::Ptr deserialize(const std::vector<uint8_t>& bytes) {
    mrpt::io::CMemoryStream mem;
    mem.assignMemoryNotOwn(bytes.data(), bytes.size());
    auto in = mrpt::serialization::archiveFrom(mem);
    auto object = in.ReadObject();
    auto obs = std::dynamic_pointer_cast<CObservationTravelLabels>(object);
    if (!obs) throw std::runtime_error("not a CObservationTravelLabels");
    return obs;
}

// Bitwise equality: NaNs (unknown corner heights) compare equal to themselves.
template <typename T>
bool sameBits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}
template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || !std::memcmp(a.data(), b.data(), a.size() * sizeof(T)));
}

void expectSameObservation(const CObservationTravelLabels& a, const CObservationTravelLabels& b) {
    EXPECT_EQ(a.sensorLabel, b.sensorLabel);
    EXPECT_EQ(a.timestamp, b.timestamp);
    EXPECT_EQ(a.sourceClass, b.sourceClass);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(a.sensorPose[i], b.sensorPose[i]) << "pose " << i;
    EXPECT_TRUE(sameBits(a.x, b.x));
    EXPECT_TRUE(sameBits(a.y, b.y));
    EXPECT_TRUE(sameBits(a.z, b.z));
    EXPECT_TRUE(sameBits(a.intensity, b.intensity));
    EXPECT_EQ(a.labels, b.labels);
    EXPECT_EQ(a.clusterId, b.clusterId);
    ASSERT_EQ(a.clusters.size(), b.clusters.size());
    for (std::size_t k = 0; k < a.clusters.size(); ++k) {
        const auto &p = a.clusters[k], &q = b.clusters[k];
        EXPECT_TRUE(p.id == q.id && p.num_points == q.num_points &&
                    p.first_point == q.first_point && sameBits(p.centroid, q.centroid) &&
                    sameBits(p.aabb_min, q.aabb_min) && sameBits(p.aabb_max, q.aabb_max) &&
                    sameBits(p.obb_yaw, q.obb_yaw) && sameBits(p.obb_center, q.obb_center) &&
                    sameBits(p.obb_extent, q.obb_extent) && sameBits(p.ground_z, q.ground_z) &&
                    sameBits(p.height_above_ground, q.height_above_ground) &&
                    p.track_id == q.track_id && sameBits(p.velocity, q.velocity) &&
                    sameBits(p.velocity_sigma, q.velocity_sigma) && p.moving == q.moving)
            << "cluster " << k;
    }
    EXPECT_EQ(a.terrain.resolution, b.terrain.resolution);
    EXPECT_EQ(a.terrain.cells_per_side, b.terrain.cells_per_side);
    EXPECT_EQ(a.terrain.origin_xy, b.terrain.origin_xy);
    ASSERT_EQ(a.terrain.nodes.size(), b.terrain.nodes.size());
    for (std::size_t k = 0; k < a.terrain.nodes.size(); ++k) {
        const auto &p = a.terrain.nodes[k], &q = b.terrain.nodes[k];
        EXPECT_TRUE(p.index == q.index && p.node_class == q.node_class &&
                    p.traversable == q.traversable && p.refitted == q.refitted &&
                    sameBits(p.normal, q.normal) && sameBits(p.d, q.d) &&
                    sameBits(p.corner_z, q.corner_z) && sameBits(p.mean, q.mean))
            << "node " << k;
    }
    EXPECT_TRUE(sameBits(a.alignedRotation, b.alignedRotation));
    EXPECT_TRUE(sameBits(a.timings, b.timings));
}

// The invariants deserialization promises when it does not throw.
void expectConsistent(const CObservationTravelLabels& o) {
    const std::size_t n = o.labels.size();
    ASSERT_EQ(o.x.size(), n);
    ASSERT_EQ(o.y.size(), n);
    ASSERT_EQ(o.z.size(), n);
    ASSERT_EQ(o.intensity.size(), n);
    ASSERT_EQ(o.clusterId.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_LE(o.labels[i], 3);
        ASSERT_LE(o.clusterId[i], o.clusters.size());
    }
    for (std::size_t k = 0; k < o.clusters.size(); ++k) ASSERT_EQ(o.clusters[k].id, k + 1);
    const uint64_t max_nodes =
        4ull * static_cast<uint64_t>(o.terrain.cells_per_side) * o.terrain.cells_per_side;
    for (const auto& node : o.terrain.nodes) ASSERT_LT(node.index, max_nodes);
}

void checkFilledFromResult(const CObservationTravelLabels& obs, std::size_t expected_points) {
    ASSERT_EQ(obs.size(), expected_points);
    EXPECT_GT(obs.count(PointClass::Ground), expected_points / 10);
    EXPECT_GT(obs.count(PointClass::NonGround), 0u);
    EXPECT_FALSE(obs.clusters.empty());
    EXPECT_GT(obs.terrain.numTraversable(), 0u);
    EXPECT_GT(obs.timings.ground_total, 0.0);
    expectConsistent(obs);
}

// Offset of the point count: the uint32 `n` immediately followed by x[0].
std::size_t pointCountOffset(const std::vector<uint8_t>& bytes, const CObservationTravelLabels& o) {
    uint8_t pattern[8];
    const uint32_t n = static_cast<uint32_t>(o.size());
    std::memcpy(pattern, &n, 4);
    std::memcpy(pattern + 4, &o.x[0], 4);
    for (std::size_t i = 0; i + 8 <= bytes.size(); ++i)
        if (!std::memcmp(&bytes[i], pattern, 8)) return i;
    return bytes.size();
}

}  // namespace

TEST(LabelsObservation, RegistrationIsIdempotentAndByName) {
    travel_mrpt::registerClasses();
    travel_mrpt::registerClasses();
    const auto* id = mrpt::rtti::findRegisteredClass("travel_mrpt::CObservationTravelLabels");
    ASSERT_NE(id, nullptr);
    auto object = id->createObject();
    EXPECT_NE(std::dynamic_pointer_cast<CObservationTravelLabels>(object), nullptr);
}

TEST(LabelsObservation, FilledFromVlp16SampleAndRoundTripsExactly) {
    travel_mrpt::registerClasses();
    const auto obs = labelVlp16Sample();
    SKIP_WITHOUT_SAMPLE(obs);
    checkFilledFromResult(*obs, 11305);
    EXPECT_EQ(obs->sourceClass, "mrpt::obs::CObservationVelodyneScan");
    const std::vector<uint8_t> bytes = serialize(*obs);
    const auto back = deserialize(bytes);
    expectSameObservation(*obs, *back);
    std::cout << "[ measured ] VLP-16 sample: " << obs->size() << " points, ground "
              << obs->count(PointClass::Ground) << ", non-ground "
              << obs->count(PointClass::NonGround) << ", outliers "
              << obs->count(PointClass::Outlier) << ", invalid " << obs->count(PointClass::Invalid)
              << ", " << obs->clusters.size() << " clusters, " << obs->terrain.nodes.size()
              << " nodes (" << obs->terrain.numTraversable() << " traversable), " << bytes.size()
              << " bytes serialized\n";
}

TEST(LabelsObservation, FilledFromSyntheticScanAndRoundTripsExactly) {
    travel_mrpt::registerClasses();
    const auto obs = labelSyntheticScan();
    checkFilledFromResult(*obs, 16u * 1800u);
    EXPECT_GT(obs->count(PointClass::Invalid), 0u);  // no-returns kept, indices match the scan
    expectSameObservation(*obs, *deserialize(serialize(*obs)));
}

TEST(LabelsObservation, AssignReusesCapacityAndRejectsMismatchedSizes) {
    const auto synthetic = labelSyntheticScan();
    travel::PointCloud cloud;
    cloud.push_back(1, 2, 3, 4);
    travel::Result result;
    CObservationTravelLabels obs;
    EXPECT_THROW(obs.assign(cloud, result, Eigen::Matrix3f::Identity()), std::invalid_argument);
    result.labels = {PointClass::Ground};
    obs.assign(cloud, result, Eigen::Matrix3f::Identity());
    EXPECT_EQ(obs.clusterId, std::vector<uint32_t>{0u});  // no clustering: all 0
    EXPECT_EQ(obs.count(PointClass::Ground), 1u);
    obs.labels.reserve(100);
    const uint8_t* before = obs.labels.data();
    obs.assign(cloud, result, Eigen::Matrix3f::Identity());
    EXPECT_EQ(obs.labels.data(), before);
}

TEST(LabelsObservation, EmptyObservationRoundTrips) {
    travel_mrpt::registerClasses();
    CObservationTravelLabels empty;
    const auto back = deserialize(serialize(empty));
    EXPECT_EQ(back->size(), 0u);
    EXPECT_TRUE(back->clusters.empty());
    EXPECT_TRUE(back->terrain.nodes.empty());
}

TEST(LabelsObservation, TruncatedStreamsThrow) {
    travel_mrpt::registerClasses();
    const auto obs = labelSyntheticScan();
    const std::vector<uint8_t> bytes = serialize(*obs);
    // Every length in the first and last 300 bytes (headers, clusters, terrain, timings), and
    // 300 lengths spread over the point arrays.
    std::vector<std::size_t> lengths;
    for (std::size_t k = 0; k < 300; ++k) {
        lengths.push_back(k);
        lengths.push_back(bytes.size() - 1 - k);
        lengths.push_back(k * bytes.size() / 300);
    }
    std::size_t thrown = 0;
    for (const std::size_t len : lengths) {
        const std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + len);
        try {
            deserialize(cut);
        } catch (const std::exception&) {
            ++thrown;
        }
    }
    EXPECT_EQ(thrown, lengths.size()) << "a truncated stream was accepted";
}

TEST(LabelsObservation, CorruptCountsThrowWithoutHugeAllocations) {
    travel_mrpt::registerClasses();
    const auto obs = labelSyntheticScan();
    const std::vector<uint8_t> bytes = serialize(*obs);
    const std::size_t at = pointCountOffset(bytes, *obs);
    ASSERT_LT(at, bytes.size()) << "point count not found in the stream";
    for (const uint32_t bad : {40'000'000u, 60'000'000u, 0xFFFFFFFFu}) {
        std::vector<uint8_t> corrupt = bytes;
        std::memcpy(&corrupt[at], &bad, 4);
        try {
            deserialize(corrupt);
            ADD_FAILURE() << "point count " << bad << " accepted";
        } catch (const std::exception& e) {
            // MRPT wraps our std::runtime_error; its message still says what was wrong.
            const std::string what = e.what();
            EXPECT_NE(what.find("CObservationTravelLabels"), std::string::npos) << what;
        }
    }
}

TEST(LabelsObservation, BitFlippedStreamsThrowOrGiveConsistentObjects) {
    travel_mrpt::registerClasses();
    const auto obs = labelSyntheticScan();
    const std::vector<uint8_t> bytes = serialize(*obs);
    // Where the counts and ids live: the head (names, pose, point count) and the tail (clusters,
    // terrain, rotation, timings: everything after the per-point arrays).
    const std::size_t head = pointCountOffset(bytes, *obs) + 4;
    const std::size_t tail_begin = head + obs->size() * (4 * sizeof(float) + 1 + 4);
    ASSERT_LT(tail_begin, bytes.size());
    std::mt19937 rng(20260101);
    std::size_t thrown = 0, consistent = 0;
    const int variants = 400;
    for (int v = 0; v < variants; ++v) {
        std::vector<uint8_t> corrupt = bytes;
        const int flips = 1 + static_cast<int>(rng() % 4);
        for (int f = 0; f < flips; ++f) {
            std::size_t pos;
            switch (v % 3) {
                case 0:
                    pos = rng() % head;
                    break;
                case 1:
                    pos = tail_begin + rng() % (bytes.size() - tail_begin);
                    break;
                default:
                    pos = rng() % bytes.size();
            }
            corrupt[pos] ^= static_cast<uint8_t>(1u << (rng() % 8));
        }
        CObservationTravelLabels::Ptr back;
        try {
            back = deserialize(corrupt);
        } catch (const std::exception&) {
            ++thrown;
            continue;
        }
        expectConsistent(*back);
        // A consistent object is also safe to describe and draw.
        std::ostringstream text;
        back->getDescriptionAsText(text);
        mrpt::opengl::CSetOfObjects view;
        back->getVisualizationInto(view);
        ++consistent;
    }
    std::cout << "[ measured ] " << variants << " bit-flipped streams: " << thrown << " threw, "
              << consistent << " read as consistent objects\n";
    EXPECT_EQ(thrown + consistent, static_cast<std::size_t>(variants));
    EXPECT_GT(thrown, 0u);
}

TEST(LabelsObservation, DescriptionMentionsCountsClustersAndTimings) {
    const auto obs = labelSyntheticScan();
    std::ostringstream text;
    obs->getDescriptionAsText(text);
    const std::string s = text.str();
    EXPECT_NE(s.find("ClassName: travel_mrpt::CObservationTravelLabels"), std::string::npos) << s;
    EXPECT_NE(s.find("Points: " + std::to_string(obs->size())), std::string::npos) << s;
    for (PointClass c : {PointClass::Ground, PointClass::NonGround, PointClass::Invalid}) {
        const std::string name = travel::toString(c), count = std::to_string(obs->count(c));
        const auto at = s.find(name);
        ASSERT_NE(at, std::string::npos) << name;
        EXPECT_NE(s.find(count, at), std::string::npos) << name << " count " << count;
    }
    EXPECT_NE(s.find("Clusters: " + std::to_string(obs->clusters.size())), std::string::npos);
    EXPECT_NE(s.find(std::to_string(obs->terrain.numTraversable()) + " traversable"),
              std::string::npos);
    EXPECT_NE(s.find("Timings [ms]"), std::string::npos);
    EXPECT_NE(s.find("SIM_VLP16"), std::string::npos);  // the base class's part (sensor label)
}

TEST(LabelsObservation, VisualizationDrawsValidPointsInClassColours) {
    const auto obs = labelSyntheticScan();
    mrpt::opengl::CSetOfObjects view;
    obs->getVisualizationInto(view);
    const auto points = view.getByClass<mrpt::opengl::CPointCloudColoured>();
    ASSERT_NE(points, nullptr);
    const std::size_t valid = obs->size() - obs->count(PointClass::Invalid);
    ASSERT_EQ(points->size(), valid);
    const mrpt::math::TPose3D placed = points->getPose();
    EXPECT_NEAR(placed.x, obs->sensorPose.x(), 1e-9);
    EXPECT_NEAR(placed.z, obs->sensorPose.z(), 1e-9);
    EXPECT_NEAR(placed.yaw, obs->sensorPose.yaw(), 1e-9);

    // Drawn points are the valid ones in input order: check the first of each kind.
    const auto rgb = [](const mrpt::img::TColor& c) {
        return (uint32_t(c.R) << 16) | (uint32_t(c.G) << 8) | c.B;
    };
    bool seen_ground = false, seen_cluster = false, seen_unclustered = false;
    std::size_t drawn = 0, checked = 0;
    for (std::size_t i = 0; i < obs->size(); ++i) {
        const auto c = static_cast<PointClass>(obs->labels[i]);
        if (c == PointClass::Invalid) continue;
        const std::size_t k = drawn++;
        uint32_t expected = 0;
        bool check = false;
        if (c == PointClass::Ground && !seen_ground) {
            seen_ground = check = true;
            expected = travel_mrpt::kGroundColour;
        } else if (c == PointClass::NonGround && obs->clusterId[i] != 0 && !seen_cluster) {
            seen_cluster = check = true;
            expected = travel_mrpt::clusterColour(obs->clusterId[i]);
        } else if (c == PointClass::NonGround && obs->clusterId[i] == 0 && !seen_unclustered) {
            seen_unclustered = check = true;
            expected = travel_mrpt::kUnclusteredColour;
        }
        if (!check) continue;
        ++checked;
        EXPECT_EQ(rgb(points->getPointColor(k)), expected) << "point " << i;
        const auto& p = points->getPoint3Df(k);
        EXPECT_EQ(p.x, obs->x[i]);
        EXPECT_EQ(p.y, obs->y[i]);
        EXPECT_EQ(p.z, obs->z[i]);
    }
    EXPECT_TRUE(seen_ground && seen_cluster);
    EXPECT_GE(checked, 2u);

    // One translucent triangle per traversable node, one box per cluster.
    const auto triangles = view.getByClass<mrpt::opengl::CSetOfTriangles>();
    ASSERT_NE(triangles, nullptr);
    EXPECT_EQ(triangles->getTrianglesCount(), obs->terrain.numTraversable());
    mrpt::opengl::TTriangle first;
    triangles->getTriangle(0, first);
    EXPECT_LT(first.a(0), 255);  // translucent
}

// ---------------------------------------------------------------- tracking (issue 19)

TEST(LabelsObservation, DescriptionListsMovingTracksOnlyWhenTracked) {
    std::ostringstream plain, tracked;
    smallObservation()->getDescriptionAsText(plain);
    EXPECT_EQ(plain.str().find("tracked"), std::string::npos) << plain.str();
    smallTrackedObservation()->getDescriptionAsText(tracked);
    EXPECT_NE(tracked.str().find("tracked: 2 clusters, 1 moving"), std::string::npos)
        << tracked.str();
    EXPECT_NE(tracked.str().find("#1 -> 70001 (4.00, -1.00)"), std::string::npos) << tracked.str();
}

TEST(LabelsObservation, TracksRoundTripExactlyInVersion1) {
    travel_mrpt::registerClasses();
    const auto obs = smallTrackedObservation();
    const std::vector<uint8_t> bytes = serialize(*obs);
    // MRPT's object header: class-name length byte (| 0x80), the name, the version byte.
    const std::string name = "travel_mrpt::CObservationTravelLabels";
    ASSERT_GT(bytes.size(), name.size() + 1);
    EXPECT_EQ(bytes[1 + name.size()], 1) << "serialization version";
    const auto back = deserialize(bytes);
    expectSameObservation(*obs, *back);
    EXPECT_EQ(back->clusters[0].track_id, 70001u);
    EXPECT_TRUE(back->clusters[0].moving);
    EXPECT_EQ(back->clusters[1].velocity, obs->clusters[1].velocity);
}

TEST(LabelsObservation, ReadsVersion0FilesWithTrackingFieldsZero) {
    // Written by the version-0 code (before tracking) from smallObservation().
    travel_mrpt::registerClasses();
    std::ifstream file(std::string(TRAVEL_PLUGIN_TEST_DATA) + "/travel_labels_v0.bin",
                       std::ios::binary);
    ASSERT_TRUE(file) << "fixture missing";
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(file), {}};
    ASSERT_EQ(bytes[1 + std::string("travel_mrpt::CObservationTravelLabels").size()], 0);
    const auto back = deserialize(bytes);
    expectSameObservation(*smallObservation(), *back);  // tracking fields compared: all zero
    for (const auto& c : back->clusters) {
        EXPECT_EQ(c.track_id, 0u);
        EXPECT_FALSE(c.moving);
    }
    // An unknown newer version is refused with a message naming the class.
    std::vector<uint8_t> future = bytes;
    future[1 + std::string("travel_mrpt::CObservationTravelLabels").size()] = 9;
    try {
        deserialize(future);
        ADD_FAILURE() << "version 9 accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("unknown version 9"), std::string::npos) << e.what();
    }
}

namespace {

std::vector<mrpt::opengl::CArrow::Ptr> velocityArrows(mrpt::opengl::CSetOfObjects& view) {
    std::vector<mrpt::opengl::CArrow::Ptr> arrows;
    const auto aligned = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
        view.getByName("travel_aligned_frame"));
    if (!aligned) return arrows;
    const auto set = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
        aligned->getByName("travel_velocity_arrows"));
    if (!set) return arrows;
    for (const auto& object : *set)
        if (auto arrow = std::dynamic_pointer_cast<mrpt::opengl::CArrow>(object))
            arrows.push_back(arrow);
    return arrows;
}

uint32_t rgbOf(const mrpt::img::TColor& c) {
    return (uint32_t(c.R) << 16) | (uint32_t(c.G) << 8) | c.B;
}

// Colour of the first drawn point of cluster `id` (drawn points: the valid ones, in order).
uint32_t drawnClusterColour(const CObservationTravelLabels& o,
                            const mrpt::opengl::CSetOfObjects& view, uint32_t id) {
    const auto points = view.getByClass<mrpt::opengl::CPointCloudColoured>();
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < o.size(); ++i) {
        if (o.labels[i] == 0) continue;
        if (o.clusterId[i] == id) return rgbOf(points->getPointColor(drawn));
        ++drawn;
    }
    return 0xFFFFFFFF;
}

}  // namespace

TEST(LabelsObservation, ViewDrawsOneArrowPerMovingClusterAndTrackColours) {
    // Untracked: no arrow, cluster colours by cluster id (unchanged from before tracking).
    mrpt::opengl::CSetOfObjects plain;
    const auto untracked = smallObservation();
    untracked->getVisualizationInto(plain);
    EXPECT_TRUE(velocityArrows(plain).empty());
    EXPECT_EQ(drawnClusterColour(*untracked, plain, 1), travel_mrpt::clusterColour(1));

    // Frame A: cluster 1 = moving track 70001, cluster 2 = parked track 42 (no arrow: slow).
    const auto a = smallTrackedObservation(70001, 42);
    mrpt::opengl::CSetOfObjects view_a;
    a->getVisualizationInto(view_a);
    const auto arrows_a = velocityArrows(view_a);
    ASSERT_EQ(arrows_a.size(), 1u);
    EXPECT_EQ(arrows_a[0]->getName(), "track 70001");
    EXPECT_EQ(rgbOf(arrows_a[0]->getColor_u8()), travel_mrpt::clusterColour(70001));

    // Frame B: the same two tracks, now under swapped cluster ids, and the parked one slowly
    // moving (0.5 m/s): an arrow each.
    auto b = smallTrackedObservation(42, 70001);
    std::swap(b->clusters[0].velocity, b->clusters[1].velocity);  // 70001 still moves
    std::swap(b->clusters[0].moving, b->clusters[1].moving);
    b->clusters[0].velocity = {0.5f, 0.f, 0.f};
    mrpt::opengl::CSetOfObjects view_b;
    b->getVisualizationInto(view_b);
    EXPECT_EQ(velocityArrows(view_b).size(), 2u);

    // Same track -> same colour in both frames, for points, boxes and arrows; different tracks
    // differ.
    EXPECT_EQ(drawnClusterColour(*a, view_a, 1), drawnClusterColour(*b, view_b, 2));  // 70001
    EXPECT_EQ(drawnClusterColour(*a, view_a, 2), drawnClusterColour(*b, view_b, 1));  // 42
    EXPECT_NE(drawnClusterColour(*a, view_a, 1), drawnClusterColour(*a, view_a, 2));
    EXPECT_EQ(drawnClusterColour(*a, view_a, 1), travel_mrpt::clusterColour(70001));
    const auto boxColours = [](mrpt::opengl::CSetOfObjects& view) {
        std::vector<uint32_t> colours;
        const auto aligned = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
            view.getByName("travel_aligned_frame"));
        for (const auto& object : *aligned)
            if (auto box = std::dynamic_pointer_cast<mrpt::opengl::CBox>(object))
                colours.push_back(rgbOf(box->getColor_u8()));
        return colours;
    };
    const auto boxes_a = boxColours(view_a), boxes_b = boxColours(view_b);
    ASSERT_EQ(boxes_a.size(), 2u);
    ASSERT_EQ(boxes_b.size(), 2u);
    EXPECT_EQ(boxes_a[0], boxes_b[1]);
    EXPECT_EQ(boxes_a[1], boxes_b[0]);
}
