// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Velodyne .pcap captures through travel_mrpt::PcapSource (MRPT's CVelodyneScanner): MRPT's two
// sample captures (HDL-32E; VLP-16 with GPS packets) give full rotations that decode to rings and
// per-point times, and bad inputs give errors naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "TempDir.hpp"
#include "travel/Errors.hpp"
#include "travel/PointCloud.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/PcapSource.hpp"

namespace fs = std::filesystem;

namespace {

travel_mrpt::PcapSourceOptions model(const char* name) {
    travel_mrpt::PcapSourceOptions options;
    options.model = name;
    return options;
}

std::string capture(const char* name) {
    return std::string(TRAVEL_DATA_DIR) + "/velodyne_pcap/" + name;
}

#define SKIP_WITHOUT(path) \
    if (!fs::exists(path)) \
    GTEST_SKIP() << path << " is absent (real data in ../shared/data, see its README)"

struct Expected {
    const char* file;
    const char* model;
    std::size_t min_frames, lasers, min_rings, min_points, max_points;
};

void checkCapture(const Expected& e) {
    const std::string path = capture(e.file);
    SKIP_WITHOUT(path);
    EXPECT_TRUE(travel_mrpt::isPcapFile(path));
    travel_mrpt::PcapSource source(path, model(e.model));
    EXPECT_EQ(source.model(), travel_mrpt::velodyneModelName(e.model));
    travel::PointCloud cloud;
    double previous_stamp = -1;
    while (auto scan = source.next()) {
        SCOPED_TRACE("frame " + std::to_string(source.frames()));
        EXPECT_EQ(scan->sensorLabel, "VELODYNE");
        EXPECT_EQ(scan->calibration.laser_corrections.size(), e.lasers);
        const double stamp = mrpt::Clock::toDouble(scan->timestamp);
        // Frames 0.05-0.2 s apart (5-20 Hz), not the replay's wall clock.
        if (previous_stamp >= 0) {
            EXPECT_GT(stamp - previous_stamp, 0.05);
            EXPECT_LT(stamp - previous_stamp, 0.2);
        }
        previous_stamp = stamp;

        std::string why;
        ASSERT_TRUE(travel_mrpt::velodyneToTravelCloud(*scan, cloud, &why)) << why;
        EXPECT_GE(cloud.size(), e.min_points);
        EXPECT_LE(cloud.size(), e.max_points);
        ASSERT_TRUE(cloud.hasRing());
        ASSERT_TRUE(cloud.hasTime());
        std::vector<std::size_t> per_ring(e.lasers, 0);
        for (uint16_t r : cloud.ring) {
            ASSERT_LT(r, e.lasers);
            ++per_ring[r];
        }
        EXPECT_GE(std::count_if(per_ring.begin(), per_ring.end(), [](auto n) { return n > 0; }),
                  static_cast<long>(e.min_rings));
        // Per-point times (deskew): non-decreasing in firing order, one rotation long.
        for (std::size_t i = 1; i < cloud.size(); ++i)
            ASSERT_GE(cloud.time[i], cloud.time[i - 1]) << "point " << i;
        EXPECT_GE(cloud.time.front(), 0.f);
        EXPECT_GT(cloud.time.back(), 0.05f);
        EXPECT_LT(cloud.time.back(), 0.2f);
    }
    EXPECT_GE(source.frames(), e.min_frames);
    EXPECT_GE(source.droppedPartialFrames(), 1u);  // both captures start mid-rotation
}

}  // namespace

// MRPT 2.5.8 decodes only the first 16 of the 32 returns of an HDL-32E block
// (SCANS_PER_FIRING = 16 in CObservationVelodyneScan::generatePointCloud): 15-16 rings per frame.
TEST(PcapSource, Hdl32Capture) {
    checkCapture({"sample_velodyne_hdl32.pcap", "hdl32", 2, 32, 15, 15000, 80000});
}

TEST(PcapSource, Vlp16CaptureWithGps) {
    checkCapture({"sample_velodyne_vlp16_gps.pcap", "VLP-16", 3, 16, 16, 5000, 30000});
}

TEST(PcapSource, KeepsPartialFramesOnRequest) {
    const std::string path = capture("sample_velodyne_hdl32.pcap");
    SKIP_WITHOUT(path);
    travel_mrpt::PcapSourceOptions options = model("HDL32");
    options.keep_partial_frames = true;
    options.sensor_label = "LIDAR";
    travel_mrpt::PcapSource source(path, options);
    std::size_t n = 0;
    while (auto scan = source.next()) {
        EXPECT_EQ(scan->sensorLabel, "LIDAR");
        ++n;
    }
    EXPECT_EQ(source.droppedPartialFrames(), 0u);
    EXPECT_GE(n, 3u);
}

// The message of the InputError thrown by `f`, or "" when none is thrown.
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const travel::InputError& e) {
        return e.what();
    }
    return "";
}

TEST(PcapSource, ErrorsNameTheFile) {
    const travel_test::TempDir tmp("travel_test_pcap_source");
    const fs::path& dir = tmp.path;
    const std::string missing = (dir / "missing.pcap").string();
    EXPECT_EQ(errorOf([&] { travel_mrpt::PcapSource(missing, model("VLP16")); }),
              missing + ": no such file");

    const std::string text = (dir / "text.pcap").string();
    std::ofstream(text) << "this is not a capture\n";
    EXPECT_FALSE(travel_mrpt::isPcapFile((dir / "text.txt").string()));
    const std::string not_pcap = errorOf([&] { travel_mrpt::PcapSource(text, model("VLP16")); });
    EXPECT_EQ(not_pcap.rfind(text + ": not a pcap capture", 0), 0u) << not_pcap;

    // A valid pcap header without any packet.
    const std::string empty = (dir / "empty.pcap").string();
    {
        std::ofstream f(empty, std::ios::binary);
        const unsigned char header[24] = {0xd4, 0xc3, 0xb2, 0xa1, 2,    0,    4, 0, 0, 0, 0, 0,
                                          0,    0,    0,    0,    0xff, 0xff, 0, 0, 1, 0, 0, 0};
        f.write(reinterpret_cast<const char*>(header), sizeof header);
    }
    EXPECT_TRUE(travel_mrpt::isPcapFile(empty));
    const std::string no_packets = errorOf([&] { travel_mrpt::PcapSource(empty, model("VLP16")); });
    EXPECT_EQ(no_packets.rfind(empty + ": no Velodyne data packets", 0), 0u) << no_packets;

    const std::string unknown = errorOf([&] { travel_mrpt::PcapSource(empty, model("OS1-64")); });
    EXPECT_EQ(unknown, empty + ": unknown Velodyne model 'OS1-64' (allowed: VLP16, HDL32, HDL64)");

    const std::string hdl64 = errorOf([&] { travel_mrpt::PcapSource(empty, model("HDL-64E")); });
    EXPECT_NE(hdl64.find("HDL64"), std::string::npos) << hdl64;
    EXPECT_NE(hdl64.find("calibration XML"), std::string::npos) << hdl64;
}

TEST(PcapSource, ModelNames) {
    EXPECT_EQ(travel_mrpt::velodyneModelName("vlp16"), "VLP16");
    EXPECT_EQ(travel_mrpt::velodyneModelName("HDL-32E"), "HDL32");
    EXPECT_EQ(travel_mrpt::velodyneModelName("hdl64"), "HDL64");
    EXPECT_EQ(travel_mrpt::velodyneModelName("kitti"), "");
    EXPECT_EQ(travel_mrpt::velodyneModelName(""), "");
}
