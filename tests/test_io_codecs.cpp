// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel::io's LabelledFrame codec (the body of CObservationTravelLabels in rawlogs) and the
// rotating-scan decoder (CObservationRotatingScan -> PointCloud), without MRPT.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "travel/Errors.hpp"
#include "travel/io/LabelledFrameCodec.hpp"
#include "travel/io/RotatingScan.hpp"

namespace {

struct Buffer final : travel::io::ByteSink, travel::io::ByteSource {
    std::vector<unsigned char> bytes;
    std::size_t read_at = 0;
    void write(const void* data, std::size_t n) override {
        const auto* p = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), p, p + n);
    }
    std::size_t read(void* data, std::size_t n) override {
        n = std::min(n, bytes.size() - read_at);
        if (n > 0) std::memcpy(data, bytes.data() + read_at, n);  // data() may be null
        read_at += n;
        return n;
    }
};

travel::LabelledFrame sampleFrame() {
    travel::LabelledFrame f;
    f.x = {1.f, 2.f, 3.f}, f.y = {0.f, 1.f, 2.f}, f.z = {-1.f, 0.5f, 0.7f};
    f.intensity = {10.f, 20.f, 30.f};
    f.labels = {1, 2, 2};
    f.clusterId = {0, 1, 1};
    travel::ClusterSummary c;
    c.id = 1, c.num_points = 2, c.first_point = 1;
    c.centroid = {2.5f, 1.5f, 0.6f};
    c.ground_z = -1.7f, c.height_above_ground = 2.4f;
    c.track_id = 70001, c.velocity = {1.5f, -0.25f, 0.f}, c.velocity_sigma = {0.1f, 0.2f, 0.3f};
    c.moving = true;
    f.clusters.push_back(c);
    f.terrain.resolution = 1.f, f.terrain.cells_per_side = 2, f.terrain.origin_xy = -1.f;
    travel::TerrainNodeRecord node;
    node.index = 5, node.node_class = travel::NodeClass::Terrain, node.traversable = true;
    node.d = 1.7f, node.corner_z = {-1.7f, -1.6f, -1.8f};
    f.terrain.nodes.push_back(node);
    f.alignedRotation(0, 1) = 0.25f;
    f.timings.ttmf = 1.5;
    return f;
}

}  // namespace

TEST(LabelledFrameCodec, RoundTripsEveryField) {
    const travel::LabelledFrame f = sampleFrame();
    Buffer buffer;
    travel::io::writeLabelledFrame(buffer, f);
    // Count, 3 x (4 floats, a label, a cluster id), 1 cluster (84 bytes + 29 of tracking),
    // terrain head, 1 node, rotation, 12 timings.
    EXPECT_EQ(buffer.bytes.size(), 4 + 3 * 21 + 4 + 84 + 29 + 16 + 46 + 36 + 96);
    travel::LabelledFrame back;
    travel::io::readLabelledFrame(buffer, back, 100);
    EXPECT_EQ(back.x, f.x);
    EXPECT_EQ(back.intensity, f.intensity);
    EXPECT_EQ(back.labels, f.labels);
    EXPECT_EQ(back.clusterId, f.clusterId);
    ASSERT_EQ(back.clusters.size(), 1u);
    EXPECT_EQ(back.clusters[0].centroid, f.clusters[0].centroid);
    EXPECT_EQ(back.clusters[0].height_above_ground, 2.4f);
    EXPECT_EQ(back.clusters[0].track_id, 70001u);
    EXPECT_EQ(back.clusters[0].velocity, f.clusters[0].velocity);
    EXPECT_EQ(back.clusters[0].velocity_sigma, f.clusters[0].velocity_sigma);
    EXPECT_TRUE(back.clusters[0].moving);
    ASSERT_EQ(back.terrain.nodes.size(), 1u);
    EXPECT_EQ(back.terrain.nodes[0].index, 5u);
    EXPECT_TRUE(back.terrain.nodes[0].traversable);
    EXPECT_FALSE(back.terrain.nodes[0].refitted);
    EXPECT_EQ(back.terrain.nodes[0].corner_z, f.terrain.nodes[0].corner_z);
    EXPECT_EQ(back.terrain.cells_per_side, 2);
    EXPECT_EQ(back.alignedRotation, f.alignedRotation);
    EXPECT_EQ(back.timings.ttmf, 1.5);
    EXPECT_EQ(buffer.read_at, buffer.bytes.size());
}

TEST(LabelledFrameCodec, TruncatedOrCorruptStreamsThrowAndLeaveTheFrameEmpty) {
    Buffer whole;
    travel::io::writeLabelledFrame(whole, sampleFrame());
    for (std::size_t len = 0; len < whole.bytes.size(); ++len) {
        Buffer cut;
        cut.bytes.assign(whole.bytes.begin(), whole.bytes.begin() + long(len));
        travel::LabelledFrame back = sampleFrame();
        EXPECT_THROW(travel::io::readLabelledFrame(cut, back, 100), travel::InputError) << len;
        EXPECT_EQ(back.size(), 0u);
        EXPECT_TRUE(back.terrain.nodes.empty());
    }
    Buffer bad_label = whole;
    bad_label.bytes[4 + 3 * 16] = 7;  // first label
    travel::LabelledFrame back;
    EXPECT_THROW(travel::io::readLabelledFrame(bad_label, back, 100), travel::InputError);
    Buffer too_many = whole;
    EXPECT_THROW(travel::io::readLabelledFrame(too_many, back, 2), travel::InputError);
    Buffer sizes;
    travel::LabelledFrame uneven = sampleFrame();
    uneven.z.pop_back();
    EXPECT_THROW(travel::io::writeLabelledFrame(sizes, uneven), std::logic_error);
}

namespace {
constexpr std::size_t kTrackBytesAt = 4 + 3 * 21 + 4 + 84;  // the cluster's tracking fields
constexpr std::size_t kTrackBytes = 4 + 12 + 12 + 1;
}  // namespace

TEST(LabelledFrameCodec, ReadsLayoutZeroWithoutTrackingAsUntracked) {
    // Layout 0 is layout 1 without the cluster's tracking bytes.
    Buffer v0;
    travel::io::writeLabelledFrame(v0, sampleFrame());
    v0.bytes.erase(v0.bytes.begin() + long(kTrackBytesAt),
                   v0.bytes.begin() + long(kTrackBytesAt + kTrackBytes));
    travel::LabelledFrame back;
    travel::io::readLabelledFrame(v0, back, 100, 0);
    EXPECT_EQ(v0.read_at, v0.bytes.size());
    ASSERT_EQ(back.clusters.size(), 1u);
    const travel::ClusterSummary& c = back.clusters[0];
    EXPECT_EQ(c.height_above_ground, 2.4f);
    EXPECT_EQ(c.track_id, 0u);
    EXPECT_EQ(c.velocity, Eigen::Vector3f::Zero());
    EXPECT_EQ(c.velocity_sigma, Eigen::Vector3f::Zero());
    EXPECT_FALSE(c.moving);
    EXPECT_EQ(back.terrain.nodes.size(), 1u);
    EXPECT_EQ(back.timings.ttmf, 1.5);
}

TEST(LabelledFrameCodec, RejectsUnknownLayoutsAndBadMovingFlags) {
    Buffer whole;
    travel::io::writeLabelledFrame(whole, sampleFrame());
    travel::LabelledFrame back;
    EXPECT_THROW(
        travel::io::readLabelledFrame(whole, back, 100, travel::io::kLabelledFrameLayout + 1),
        travel::InputError);
    Buffer bad_flag = whole;
    bad_flag.bytes[kTrackBytesAt + kTrackBytes - 1] = 2;  // moving is 0 or 1
    EXPECT_THROW(travel::io::readLabelledFrame(bad_flag, back, 100), travel::InputError);
    EXPECT_EQ(back.size(), 0u);
}

TEST(LabelledFrameCodec, StringsAreLengthPrefixed) {
    Buffer buffer;
    travel::io::writeString(buffer, "velodyne");
    EXPECT_EQ(buffer.bytes.size(), 4u + 8u);
    std::string back;
    travel::io::readString(buffer, back, "label");
    EXPECT_EQ(back, "velodyne");
}

TEST(RotatingScan, RingsByElevationAndPointsInTheSensorFrame) {
    // Laser 0 looks 10 degrees up, laser 1 10 degrees down: rings 1 and 0.
    const travel::io::LaserCorrection lasers[2] = {{10.0, 0, 0, 0}, {-10.0, 0, 0, 0}};
    uint16_t ring[2];
    travel::io::ringOfLaser(lasers, 2, ring);
    EXPECT_EQ(ring[0], 1);
    EXPECT_EQ(ring[1], 0);

    // 2 x 4 image, returns in columns 0 and 1 only; a sweep of 4 columns over 360 degrees.
    const uint16_t ranges[8] = {100, 0, 0, 0, 0, 200, 0, 0};
    const uint8_t intensity[8] = {7, 0, 0, 0, 0, 9, 0, 0};
    travel::io::RangeImageScan scan;
    scan.ranges = ranges, scan.intensity = intensity;
    scan.rows = 2, scan.columns = 4, scan.columns_used = 2, scan.sweep_columns = 4;
    scan.range_resolution = 0.01;
    scan.start_azimuth = 0, scan.azimuth_span = 2 * M_PI, scan.sweep_duration = 0.1;
    travel::PointCloud cloud;
    travel::io::rangeImageToCloud(scan, lasers, cloud);
    ASSERT_EQ(cloud.size(), 2u);
    const float c10 = std::cos(10.f * float(M_PI) / 180.f),
                s10 = std::sin(10.f * float(M_PI) / 180.f);
    // Column 0, azimuth 0: straight ahead, 1 m.
    EXPECT_NEAR(cloud.x[0], c10, 1e-5f);
    EXPECT_NEAR(cloud.y[0], 0.f, 1e-5f);
    EXPECT_NEAR(cloud.z[0], s10, 1e-5f);
    // Column 1, azimuth 90 degrees clockwise: to the right (-y), 2 m, looking down.
    EXPECT_NEAR(cloud.x[1], 0.f, 1e-5f);
    EXPECT_NEAR(cloud.y[1], -2.f * c10, 1e-5f);
    EXPECT_NEAR(cloud.z[1], -2.f * s10, 1e-5f);
    EXPECT_EQ(cloud.intensity, (std::vector<float>{7.f, 9.f}));
    EXPECT_EQ(cloud.ring, (std::vector<uint16_t>{1, 0}));
    ASSERT_TRUE(cloud.hasTime());
    EXPECT_FLOAT_EQ(cloud.time[1], 0.025f);
}
