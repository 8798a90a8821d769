// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// make_synthetic_scans OUT_DIR [FRAMES]: writes FRAMES (default 8) KITTI .bin scans
// OUT_DIR/000000.bin ... of the mixed synthetic scene (ramp, kerb, bumps, car, pole, wall),
// HDL-64E, the sensor 1.73 m up and 0.5 m further along x on every frame, with 2 cm range
// noise: a scan sequence for command-line tests that need no real data.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

#include "travel/io/ScanIO.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

int main(int argc, char** argv) {
    const bool help =
        argc >= 2 && (std::strcmp(argv[1], "-h") == 0 || std::strcmp(argv[1], "--help") == 0);
    if (help || argc < 2 || argc > 3 || argv[1][0] == '-') {
        std::fprintf(help ? stdout : stderr,
                     "usage: %s OUT_DIR [FRAMES (default 8)]\n"
                     "Writes FRAMES simulated HDL-64E scans of the mixed synthetic scene as\n"
                     "OUT_DIR/000000.bin ... (KITTI layout: float32 x, y, z, intensity).\n",
                     argv[0]);
        return help ? 0 : 2;
    }
    char* end = nullptr;
    const long frames = argc == 3 ? std::strtol(argv[2], &end, 10) : 8;
    if ((argc == 3 && *end != '\0') || frames < 1 || frames > 1000) {
        std::fprintf(stderr, "FRAMES must be an integer in [1, 1000], got '%s'\n", argv[2]);
        return 2;
    }
    try {
        namespace sim = travel::sim;
        std::filesystem::create_directories(argv[1]);
        const sim::Scene scene = sim::mixed();
        sim::LidarModel lidar = sim::LidarModel::hdl64();
        lidar.range_noise_sigma = 0.02;
        for (long f = 0; f < frames; ++f) {
            lidar.seed = static_cast<uint32_t>(f + 1);
            const travel::PointCloud cloud =
                sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0.5 * f, 0, 1.73, 0, 0, 0)).cloud;
            char name[32];
            std::snprintf(name, sizeof name, "%06ld.bin", f);
            travel::writeKittiBin((std::filesystem::path(argv[1]) / name).string(), cloud);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_synthetic_scans: %s\n", e.what());
        return 1;
    }
    return 0;
}
