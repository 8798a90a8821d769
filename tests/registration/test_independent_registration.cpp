// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Issue 19's acceptance, pose file: travel-kitti --track writes OUT/poses.txt (the ego-motion
// of its ICP on the non-ground points, travel::ScanOdometry); its end point must lie within 5 %
// of the distance driven from that of an independent registration of the same drive: MRPT's
// ICP (CicpOdometry.hpp), which shares no code with ours; it is planar, so the end points are
// compared in xy (the 3-D gap is printed). Built only when mrpt-slam is found.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../TempDir.hpp"
#include "CicpOdometry.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel/io/ScanList.hpp"
#include "travel/traversability/PoseFiles.hpp"

namespace fs = std::filesystem;

TEST(IndependentRegistration, TrackPosesEndWithin5PercentOfMrptIcp) {
    const fs::path dir = fs::path(TRAVEL_DATA_DIR) / "kitti_raw_pcd";
    if (!fs::exists(dir)) GTEST_SKIP() << dir << " not found (../shared/data): nothing to register";
    travel_test::TempDir out("independent_registration");
    const std::string command = std::string(TRAVEL_KITTI_EXE) + " -i " + dir.string() + " -o " +
                                (out.path / "labels").string() + " --track -q";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const travel::PoseTrajectory ours =
        travel::readKittiPoses((out.path / "labels" / "poses.txt").string());

    const travel::ScanList scans = travel::listScans(dir.string());
    ASSERT_EQ(ours.size(), scans.files.size());
    travel::test::CicpOdometry cicp;
    travel::PointCloud cloud;
    Eigen::Isometry3d end = Eigen::Isometry3d::Identity();
    Eigen::Vector3d last = end.translation();
    double driven = 0;
    for (const std::string& file : scans.files) {
        travel::readScan(file, cloud);
        end = cicp.add(cloud);
        driven += (end.translation() - last).norm();
        last = end.translation();
    }
    const Eigen::Vector3d gap = ours.poses.back().translation() - end.translation();
    std::printf(
        "kitti_raw_pcd: travel-kitti --track end point %.3f m from MRPT's ICP (xy %.3f m) after "
        "%.2f m driven (%.2f %%, xy %.2f %%)\n",
        gap.norm(), gap.head<2>().norm(), driven, 100 * gap.norm() / driven,
        100 * gap.head<2>().norm() / driven);
    EXPECT_GT(driven, 10.0);  // the drive is ~17 m: a registration that stalls is no reference
    // MRPT's 2-D ICP measures x, y and yaw only: the end points are compared in xy.
    EXPECT_LT(gap.head<2>().norm(), 0.05 * driven);
}
