// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// Build: cmake --build build --target register_scans (beside bench_travel)
// Use:   build/tests/benchmarks/register_scans DIR/*.pcd > poses.txt
// Frame-to-frame point-to-plane ICP (travel::ScanOdometry, libtravel/tracking) over scans in
// any format the apps read -> KITTI pose file (LiDAR poses, frame 0 = identity). Points 3-50 m
// from the sensor (xy), as the committed share/bench/kitti_raw_pcd_poses.txt was made.
// Options before the scans: --target-voxel M, --source-voxel M (other ICP settings, to compare).
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "travel/io/ScanIO.hpp"
#include "travel/tracking/ScanRegistration.hpp"
#include "travel/traversability/PoseFiles.hpp"

int main(int argc, char** argv) {
    travel::RegistrationParams params;
    int a = 1;
    for (; a + 1 < argc && std::string(argv[a]).rfind("--", 0) == 0; a += 2) {
        const std::string flag = argv[a];
        const double value = std::stod(argv[a + 1]);
        if (flag == "--target-voxel") {
            params.target_voxel = value;
        } else if (flag == "--source-voxel") {
            params.source_voxel = value;
        } else {
            std::cerr << "register_scans: unknown option " << flag << "\n";
            return 1;
        }
    }
    travel::ScanOdometry odometry(params);
    travel::PointCloud cloud;
    std::vector<Eigen::Vector3d> points;
    for (; a < argc; ++a) {
        travel::readScan(argv[a], cloud);
        points.clear();
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            const Eigen::Vector3d q(cloud.x[i], cloud.y[i], cloud.z[i]);
            const double r = q.head<2>().norm();
            if (r > 3 && r < 50) points.push_back(q);
        }
        const Eigen::Isometry3d pose = odometry.add(points);
        std::fputs(travel::kittiPoseLine(pose).c_str(), stdout);
    }
}
