// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// travel::viz (raster primitives, bird's-eye picture), the MotionEstimator's IMU / odometry
// input and travel::io::velodyneModelFor: the MRPT-free pieces the MRPT layer converts to.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "FileSizeLimit.hpp"
#include "TempDir.hpp"
#include "travel/MotionEstimator.hpp"
#include "travel/io/VelodyneModels.hpp"
#include "travel/viz/BirdsEye.hpp"
#include "travel/viz/PngFile.hpp"
#include "travel/viz/TrackPicture.hpp"

using travel::viz::Raster;
using travel::viz::Rgb;

namespace {
constexpr Rgb kWhite{255, 255, 255}, kInk{10, 20, 30};
bool inked(const Raster& r, int u, int v) {
    const Rgb c = r.at(u, v);
    return c.r == kInk.r && c.g == kInk.g && c.b == kInk.b;
}
}  // namespace

TEST(Raster, LineIsEightConnectedAndClipped) {
    Raster r;
    r.reset(20, 10, kWhite);
    r.line(-5, 2, 30, 7, kInk);  // both ends outside: clipped, one pixel per column
    for (int u = 0; u < r.width; ++u) {
        int n = 0;
        for (int v = 0; v < r.height; ++v) n += inked(r, u, v);
        EXPECT_EQ(n, 1) << "column " << u;
    }
    r.reset(20, 10, kWhite);
    r.line(3, 8, 3, 1, kInk);  // vertical, ends included
    for (int v = 1; v <= 8; ++v) EXPECT_TRUE(inked(r, 3, v));
    EXPECT_FALSE(inked(r, 3, 0));
    EXPECT_FALSE(inked(r, 3, 9));
}

TEST(Raster, CircleIsSymmetricAndFillRectClips) {
    Raster r;
    r.reset(21, 21, kWhite);
    r.circle(10, 10, 7, kInk);
    for (int v = 0; v < 21; ++v)
        for (int u = 0; u < 21; ++u) {
            EXPECT_EQ(inked(r, u, v), inked(r, 20 - u, v));
            EXPECT_EQ(inked(r, u, v), inked(r, v, u));
        }
    EXPECT_TRUE(inked(r, 17, 10) && inked(r, 3, 10) && inked(r, 10, 3));
    r.fillRect(-3, -3, 1, 1, kInk);
    EXPECT_TRUE(inked(r, 0, 0) && inked(r, 1, 1));
    EXPECT_FALSE(inked(r, 2, 2));
}

TEST(BirdsEye, PointsAndTextLabels) {
    const float x[] = {5.f, -5.f}, y[] = {0.f, 3.f};
    const std::vector<travel::PointClass> labels = {travel::PointClass::Ground,
                                                    travel::PointClass::NonGround};
    travel::viz::BirdsEyeOptions opt;
    opt.size_px = 200;
    opt.title = "t";
    opt.legend = false;  // it would cover the point at x = 5 m
    const travel::viz::Picture p = travel::viz::renderBirdsEye(x, y, 2, labels, {}, nullptr, opt);
    ASSERT_EQ(p.raster.width, 200);
    const Rgb ground =
        p.raster.at(100, static_cast<int>(std::lround(100 - 5 / opt.metres_per_pixel)));
    EXPECT_EQ(travel::viz::pointColour(travel::PointClass::Ground, 0, false),
              (uint32_t{ground.r} << 16) | (uint32_t{ground.g} << 8) | ground.b);
    ASSERT_FALSE(p.text.empty());
    EXPECT_EQ(p.text.front().text, "t");
    EXPECT_EQ(travel::viz::pointColour(travel::PointClass::NonGround, 7, true),
              travel::viz::clusterColour(7));
    EXPECT_EQ(travel::viz::pointColour(travel::PointClass::Invalid, 0, false), 0u);
    EXPECT_THROW(travel::viz::renderBirdsEye(x, y, 2, {}, {}, nullptr, opt), std::invalid_argument);
}

TEST(MotionEstimator, ImuRollPitchAndPlanarOdometry) {
    travel::MotionEstimator m;
    travel::ImuReading imu;
    imu.roll = 0.1;
    imu.pitch = -0.2;
    imu.angular_velocity = Eigen::Vector3d(0, 0, 0.5);
    m.addImu(1.0, Eigen::Matrix3d::Identity(), imu);
    m.addPlanarOdometry(1.0, 2.0, 0.0, 0.0, Eigen::Vector3d(1.5, 0, 0.5));
    const travel::MotionEstimate e = m.estimateAt(1.0);
    ASSERT_TRUE(e.attitude && e.linear_velocity && e.angular_velocity);
    EXPECT_TRUE(e.attitude->isApprox(travel::yawPitchRoll(0, -0.2, 0.1)));
    EXPECT_NEAR(e.linear_velocity->x(), 1.5, 1e-12);
    EXPECT_NEAR(e.angular_velocity->z(), 0.5, 1e-12);
}

TEST(VelodyneModels, ModelStringsAndRowFallback) {
    EXPECT_STREQ(travel::io::velodyneModelFor("VLP-16", 0)->name, "VLP16");
    EXPECT_STREQ(travel::io::velodyneModelFor("puck lite", 0)->name, "VLP16");
    EXPECT_STREQ(travel::io::velodyneModelFor("HDL-32E", 0)->name, "HDL32");
    EXPECT_STREQ(travel::io::velodyneModelFor("", 32)->name, "HDL32");
    EXPECT_FALSE(travel::io::velodyneModelFor("OS1-64", 64));
}

// ---------------------------------------------------------------- tracks picture, PNG file

TEST(TrackPicture, DrawsTracksInTheirColourAndTheEgoPath) {
    std::vector<travel::viz::TrackFrame> frames(3);
    for (int k = 0; k < 3; ++k) {
        frames[k].ego_x = float(k);
        frames[k].tracks.push_back({7u, 10.f, float(k), 0.f, 10.f, k == 2});
    }
    travel::viz::TrackPictureOptions options;
    options.size_px = 200;
    const travel::viz::Raster r = travel::viz::renderTracks(frames, options);
    ASSERT_EQ(r.width, 200);
    const uint32_t colour = travel::viz::clusterColour(7);
    const travel::viz::Rgb want{uint8_t(colour >> 16), uint8_t(colour >> 8), uint8_t(colour)};
    int track_pixels = 0, black = 0;
    for (int v = 0; v < r.height; ++v)
        for (int u = 0; u < r.width; ++u) {
            const travel::viz::Rgb c = r.at(u, v);
            track_pixels += c.r == want.r && c.g == want.g && c.b == want.b;
            black += c.r == 0 && c.g == 0 && c.b == 0;
        }
    EXPECT_GT(track_pixels, 10);
    EXPECT_GT(black, 5);
}

TEST(PngFile, WritesAValidStoredPng) {
    travel::viz::Raster r;
    r.reset(300, 250, {10, 20, 30});  // > 65535 bytes of scanlines: several stored blocks
    const std::string path = ::testing::TempDir() + "/travel_png_test.png";
    travel::viz::writePng(r, path);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 8u + 25u + 12u);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    EXPECT_EQ(bytes.substr(12, 4), "IHDR");
    const std::size_t raw = 250 * (1 + 3 * 300), blocks = (raw + 65534) / 65535;
    EXPECT_EQ(bytes.size(), 8 + 25 + (12 + 2 + 5 * blocks + raw + 4) + 12);
    EXPECT_THROW(travel::viz::writePng(r, "/nonexistent/dir/x.png"), std::runtime_error);
}

// A picture that cannot be written whole (a file size limit, as a full disk) is an error naming
// it; the picture written before under the name stays as it was, and no part file is left.
TEST(PngFile, AFailedWriteKeepsThePreviousPicture) {
    const travel_test::TempDir tmp("travel_png_failure");
    const std::string path = tmp.file("tracks.png");
    const auto contents = [&] {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    travel::viz::Raster r;
    r.reset(4, 4, {10, 20, 30});
    travel::viz::writePng(r, path);
    const std::string before = contents();
    ASSERT_LT(before.size(), 200u);
    // 10 x 10 pixels stay in the stream's buffer until the close; 300 x 300 fail while written.
    for (const int side : {10, 300}) {
        r.reset(side, side, {40, 50, 60});
        std::string message = "no error";
        {
            const travel_test::FileSizeLimit limit(200);
            try {
                travel::viz::writePng(r, path);
            } catch (const std::runtime_error& e) {
                message = e.what();
            }
        }
        EXPECT_EQ(message, path + ": cannot write (File too large)") << side;
        EXPECT_TRUE(contents() == before) << side;  // not printed: binary
        EXPECT_FALSE(std::filesystem::exists(path + ".part")) << side;
    }
}
