// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A user's program: it does NOT link travel_mrpt. It loads libtravel_mrpt_plugin.so by path,
// builds a CMultiMetricMap from an .ini naming traversabilityMap (TSetOfMetricMapInitializers),
// inserts the 17 synthetic sweeps of MapTestScene with their robot poses, and checks the map
// through the CMetricMap interface only:
//   travel_map_plugin_host <plugin.so> <work dir>
// Exit 0 when every check passes; each failure is printed.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/system/filesystem.h>
#include <mrpt/system/os.h>

#include <cmath>
#include <iostream>
#include <string>

#include "map/MapTestScene.hpp"

namespace {

constexpr const char* kClass = "travel_mrpt::CTraversabilityMap";
int failures = 0;

void check(bool ok, const std::string& what) {
    std::cout << (ok ? "  ok: " : "  FAILED: ") << what << "\n";
    failures += ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: " << argv[0] << " <plugin.so> <work dir>\n";
        return 2;
    }
    try {
        check(mrpt::rtti::findRegisteredClass(kClass) == nullptr,
              "the map class is unknown before loading the plugin");
        std::string errors;
        if (!mrpt::system::loadPluginModules(argv[1], errors)) {
            std::cerr << "cannot load plugin " << argv[1] << ": " << errors << "\n";
            return 1;
        }
        check(mrpt::rtti::findRegisteredClass(kClass) != nullptr, "the plugin registered it");

        mrpt::config::CConfigFileMemory ini(travel_map_test::mapIni("MAP"));
        mrpt::maps::TSetOfMetricMapInitializers initializers;
        initializers.loadFromConfigFile(ini, "MAP");
        check(initializers.size() == 1, "one map initializer from the .ini");
        mrpt::maps::CMultiMetricMap maps(initializers);
        check(maps.maps.size() == 1, "CMultiMetricMap holds one map");
        if (maps.maps.empty()) return 1;
        mrpt::maps::CMetricMap& map = *maps.maps.front();
        check(std::string(map.GetRuntimeClass()->className) == kClass,
              std::string("it is a ") + map.GetRuntimeClass()->className);
        check(map.isEmpty(), "empty before insertion");

        const travel::sim::Scene scene = travel_map_test::mapScene();
        const auto poses = travel_map_test::robotPoses();
        std::size_t inserted = 0;
        for (std::size_t k = 0; k < poses.size(); ++k)
            inserted += maps.insertObservation(*travel_map_test::sweep(scene, k), poses[k]);
        check(inserted == poses.size(), "every sweep inserted (" + std::to_string(inserted) + ")");
        check(!map.isEmpty(), "not empty after insertion");
        std::cout << "  " << map.asString() << "\n";

        // Obstacle points (occupied voxels): around the pole and on the box, none on the road.
        const mrpt::maps::CSimplePointsMap* points = map.getAsSimplePointsMap();
        check(points != nullptr, "getAsSimplePointsMap() gives the obstacle points");
        if (!points) return 1;
        std::size_t pole = 0, box = 0, road = 0;
        for (std::size_t i = 0; i < points->size(); ++i) {
            float x, y, z;
            points->getPoint(i, x, y, z);
            if (std::hypot(x + 5.0, y - 3.0) < 0.5 && z > 0.5) ++pole;
            if (std::abs(x - 3.0) < 1.2 && std::abs(y + 9.0) < 1.0 && z > 0.5) ++box;
            if (std::abs(y) <= 2.0 && z > 0.4) ++road;
        }
        std::cout << "  obstacle points: " << points->size() << " (pole " << pole << ", box " << box
                  << ", road " << road << ")\n";
        check(pole >= 5, "occupied voxels on the pole");
        check(box >= 20, "occupied voxels on the box");
        check(road == 0, "no occupied voxel above the road");

        const std::string prefix = std::string(argv[2]) + "/multimap";
        mrpt::system::createDirectory(argv[2]);
        map.saveMetricMapRepresentationToFile(prefix);
        for (const char* suffix : {".bt", "_grid.gridmap.gz", "_traversability.png", ".3Dscene"})
            check(mrpt::system::fileExists(prefix + suffix), "wrote " + prefix + suffix);
    } catch (const std::exception& e) {
        std::cerr << "FAILED: exception: " << e.what() << "\n";
        return 1;
    }
    std::cout << (failures ? "FAILED\n" : "passed\n");
    return failures ? 1 : 0;
}
