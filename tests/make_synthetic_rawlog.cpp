// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// make_synthetic_rawlog OUT.rawlog [FRAMES] [--sensory-frames | --odometry-actions]: writes the
// moving, tilted robot rawlog of SyntheticRawlog.hpp (VLP-16 rotating scans + IMU + odometry),
// for command-line tests, in the observations format (default) or the SensoryFrame format
// (empty actions; with --odometry-actions each CActionCollection holds a
// CActionRobotMovement2D with the true planar pose increment since the previous LiDAR frame).
// --unusable-frames (observations format): after the 2nd and the 4th LiDAR frame an observation
// of the same sensor label without any point (an empty CObservationPointCloud), as a driver
// that lost a sweep writes; the tools skip such frames and say so.
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "SyntheticRawlog.hpp"

int main(int argc, char** argv) {
    bool sensory_frames = false, odometry_actions = false, unusable_frames = false;
    if (argc >= 3 && std::string(argv[argc - 1]) == "--unusable-frames") {
        unusable_frames = true;
        --argc;
    } else if (argc >= 3 && std::string(argv[argc - 1]) == "--sensory-frames") {
        sensory_frames = true;
        --argc;
    } else if (argc >= 3 && std::string(argv[argc - 1]) == "--odometry-actions") {
        sensory_frames = odometry_actions = true;
        --argc;
    }
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr,
                     "usage: %s OUT.rawlog [FRAMES (default 10)] [--sensory-frames | "
                     "--odometry-actions | --unusable-frames]\n",
                     argv[0]);
        return 2;
    }
    try {
        travel_test::SyntheticRawlogOptions options;
        if (argc == 3) {
            char* end = nullptr;
            const long frames = std::strtol(argv[2], &end, 10);
            if (*end != '\0' || frames < 1 || frames > 10000) {
                std::fprintf(stderr, "FRAMES must be an integer in [1, 10000], got '%s'\n",
                             argv[2]);
                return 2;
            }
            options.frames = static_cast<int>(frames);
        }
        travel_test::SyntheticRawlog rawlog = travel_test::makeSyntheticRawlog(options);
        if (unusable_frames) {
            auto& records = rawlog.records;
            int lidar = 0;
            for (auto it = records.begin(); it != records.end(); ++it) {
                const auto scan =
                    std::dynamic_pointer_cast<mrpt::obs::CObservationRotatingScan>(*it);
                if (!scan || (++lidar != 2 && lidar != 4)) continue;
                auto empty = mrpt::obs::CObservationPointCloud::Create();
                empty->sensorLabel = scan->sensorLabel;
                empty->timestamp = scan->timestamp;
                empty->sensorPose = scan->sensorPose;
                empty->pointcloud = mrpt::maps::CSimplePointsMap::Create();
                it = records.insert(std::next(it), empty);
            }
        }
        if (sensory_frames)
            travel_test::writeSensoryFrameRawlog(rawlog, argv[1], odometry_actions);
        else
            travel_test::writeRawlog(rawlog, argv[1]);
        std::printf("%s: %zu records (%d LiDAR frames)\n", argv[1], rawlog.records.size(),
                    options.frames);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_synthetic_rawlog: %s\n", e.what());
        return 1;
    }
    return 0;
}
