// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// travel::viz (raster primitives, bird's-eye picture), the MotionEstimator's IMU / odometry
// input and travel::io::velodyneModelFor: the MRPT-free pieces the MRPT layer converts to.
#include <gtest/gtest.h>

#include <cmath>

#include "travel/MotionEstimator.hpp"
#include "travel/io/VelodyneModels.hpp"
#include "travel/viz/BirdsEye.hpp"

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
