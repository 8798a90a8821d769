// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// Build: cmake --build build --target register_scans_mrpt (needs libmrpt-slam-dev)
// Use:   build/tests/register_scans_mrpt DIR/*.pcd > poses.txt
// MRPT's ICP (mrpt::slam::CICP, CicpOdometry.hpp) frame to frame over scans in any format the
// apps read -> KITTI pose file (LiDAR poses, frame 0 = identity; planar). The independent
// registration travel-kitti --track's poses.txt is compared with (test_independent_registration).
#include <cstdio>

#include "CicpOdometry.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel/traversability/PoseFiles.hpp"

int main(int argc, char** argv) {
    travel::test::CicpOdometry odometry;
    travel::PointCloud cloud;
    for (int a = 1; a < argc; ++a) {
        travel::readScan(argv[a], cloud);
        std::fputs(travel::kittiPoseLine(odometry.add(cloud)).c_str(), stdout);
    }
}
