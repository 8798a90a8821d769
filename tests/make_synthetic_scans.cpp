// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// make_synthetic_scans OUT_DIR [FRAMES]: writes FRAMES (default 8) KITTI .bin scans
// OUT_DIR/000000.bin ... of the mixed synthetic scene (ramp, kerb, bumps, car, pole, wall),
// HDL-64E, the sensor 1.73 m up and 0.5 m further along x on every frame, with 2 cm range
// noise: a scan sequence for command-line tests that need no real data.
// make_synthetic_scans --scenes OUT_DIR: one scan of every scene in travel/sim/Scenes.hpp (the
// geometry the unit tests check thresholds on, though not every pose, sensor and parameter set
// they try): HDL-64E from a level mount 1.73 m up, the off-road scenes with an OS1-64 1.3 m up,
// the mixed scene also from a tilted mount (the tilt not given to the pipeline) and with an
// OS1-128; OUT_DIR/scenes.txt names each file's scene.
// The Release-vs-sanitizer label comparison (tests/cli/test_same_labels_across_builds.cmake)
// replays them in both builds.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "travel/io/ScanIO.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace {

namespace sim = travel::sim;

struct CatalogueScan {
    std::string name;
    sim::Scene scene;
    sim::LidarModel lidar;
    double height = sim::kSensorHeight;  // of the sensor above the terrain under it [m]
    double roll_deg = 0, pitch_deg = 0;
};

// Every scene of Scenes.hpp once; parameterised scenes with values the unit tests use.
std::vector<CatalogueScan> catalogue() {
    const sim::LidarModel hdl64 = sim::LidarModel::hdl64();
    std::vector<CatalogueScan> c;
    const auto add = [&](std::string name, sim::Scene scene, sim::LidarModel lidar = {},
                         double height = sim::kSensorHeight, double roll = 0, double pitch = 0) {
        if (lidar.elevations_deg.empty()) lidar = hdl64;
        c.push_back({std::move(name), std::move(scene), std::move(lidar), height, roll, pitch});
    };
    add("flatGround", sim::flatGround());
    add("slope(20)", sim::slope(20));
    add("kerbsAndSteps", sim::kerbsAndSteps());
    add("bumpyTerrain", sim::bumpyTerrain());
    add("urbanObjects", sim::urbanObjects());
    add("mixed", sim::mixed());
    add("mixed, mount rolled 3 deg, pitched 5 deg", sim::mixed(), hdl64, sim::kSensorHeight, 3, 5);
    add("mixed, OS1-128", sim::mixed(), sim::LidarModel::os128());
    add("fencesAndWalls", sim::fencesAndWalls());
    add("meshFencesOnRoughVerges", sim::meshFencesOnRoughVerges());
    add("grassVerges", sim::grassVerges());
    add("vergesWithStreetFurniture", sim::vergesWithStreetFurniture());
    // OS1-64 (share/presets/os64.yaml) 1.3 m up, as the off-road tests use it.
    const sim::LidarModel os64 = sim::LidarModel::uniform(64, -16.6, 16.6, 2048);
    const double off_road = sim::kOffRoadSensorHeight;
    add("offRoadMeadow, OS1-64", sim::offRoadMeadow(), os64, off_road);
    add("offRoadTallGrassAndRocks, OS1-64", sim::offRoadTallGrassAndRocks(), os64, off_road);
    add("offRoadFenceLines, OS1-64", sim::offRoadFenceLines(), os64, off_road);
    add("offRoadTrackWithDitchesRutsAndPuddles, OS1-64",
        sim::offRoadTrackWithDitchesRutsAndPuddles(), os64, off_road);
    add("offRoadHillside(20), OS1-64", sim::offRoadHillside(20), os64, off_road);
    add("carBesideSensor(2)", sim::carBesideSensor(2));
    add("realisticCarBesideSensor(2)", sim::realisticCarBesideSensor(2));
    add("realisticCarBesideEgoVehicle(2)", sim::realisticCarBesideEgoVehicle(2));
    add("parkedCarsAt20To25Metres", sim::parkedCarsAt20To25Metres());
    add("movingCarAcrossSweepStart(22, 0, (8, 0))",
        sim::movingCarAcrossSweepStart(22, 0, Eigen::Vector2d(8, 0)));
    add("personBesideCar(8, 0.3)", sim::personBesideCar(8, 0.3));
    add("parkedCarRow(8, 0.4)", sim::parkedCarRow(8, 0.4));
    add("carBeforeHedge(8, 0.3, 1.5)", sim::carBeforeHedge(8, 0.3, 1.5));
    add("objectBehindParkedCar(8, 0.5, car)", sim::objectBehindParkedCar(8, 0.5, true));
    add("objectBehindParkedCar(8, 0.5, child)", sim::objectBehindParkedCar(8, 0.5, false));
    return c;
}

void writeCatalogue(const std::filesystem::path& dir) {
    std::ofstream index(dir / "scenes.txt");
    if (!index) throw std::runtime_error("cannot write " + (dir / "scenes.txt").string());
    std::vector<CatalogueScan> scans = catalogue();
    for (std::size_t i = 0; i < scans.size(); ++i) {
        CatalogueScan& s = scans[i];
        s.lidar.range_noise_sigma = 0.02;
        s.lidar.seed = static_cast<uint32_t>(i + 1);
        const travel::PointCloud cloud =
            sim::scan(s.scene, s.lidar,
                      sim::sensorPoseAt(s.scene, 0, 0, s.height, s.roll_deg, s.pitch_deg, 0))
                .cloud;
        char name[32];
        std::snprintf(name, sizeof name, "%06zu.bin", i);
        travel::writeKittiBin((dir / name).string(), cloud);
        index << name << ' ' << s.name << '\n';
    }
}

}  // namespace

int main(int argc, char** argv) {
    const bool help =
        argc >= 2 && (std::strcmp(argv[1], "-h") == 0 || std::strcmp(argv[1], "--help") == 0);
    const bool scenes = argc == 3 && std::strcmp(argv[1], "--scenes") == 0;
    if (help || (!scenes && (argc < 2 || argc > 3 || argv[1][0] == '-'))) {
        std::fprintf(
            help ? stdout : stderr,
            "usage: %s OUT_DIR [FRAMES (default 8)]\n"
            "       %s --scenes OUT_DIR\n"
            "Writes FRAMES simulated HDL-64E scans of the mixed synthetic scene as\n"
            "OUT_DIR/000000.bin ... (KITTI layout: float32 x, y, z, intensity).\n"
            "--scenes: one scan of every scene the unit tests use, and OUT_DIR/scenes.txt\n"
            "naming each file's scene.\n",
            argv[0], argv[0]);
        return help ? 0 : 2;
    }
    char* end = nullptr;
    const long frames = argc == 3 && !scenes ? std::strtol(argv[2], &end, 10) : 8;
    if (!scenes && ((argc == 3 && *end != '\0') || frames < 1 || frames > 1000)) {
        std::fprintf(stderr, "FRAMES must be an integer in [1, 1000], got '%s'\n", argv[2]);
        return 2;
    }
    try {
        const std::filesystem::path out = argv[scenes ? 2 : 1];
        std::filesystem::create_directories(out);
        if (scenes) {
            writeCatalogue(out);
            return 0;
        }
        const sim::Scene scene = sim::mixed();
        sim::LidarModel lidar = sim::LidarModel::hdl64();
        lidar.range_noise_sigma = 0.02;
        for (long f = 0; f < frames; ++f) {
            lidar.seed = static_cast<uint32_t>(f + 1);
            const travel::PointCloud cloud =
                sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0.5 * f, 0, 1.73, 0, 0, 0)).cloud;
            char name[32];
            std::snprintf(name, sizeof name, "%06ld.bin", f);
            travel::writeKittiBin((out / name).string(), cloud);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_synthetic_scans: %s\n", e.what());
        return 1;
    }
    return 0;
}
