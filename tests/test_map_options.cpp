// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The map's .ini keys (TraversabilityMapOptions) and in-process CMultiMetricMap creation (the
// grid on its own and the pose files: test_traversability.cpp).
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <fstream>

#include <limits>
#include <string>
#include <utility>

#include "map/MapTestScene.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/ParamsIO.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace {

using travel_mrpt::TraversabilityMapOptions;

std::string errorOf(const std::string& ini_text, const std::string& section) {
    try {
        mrpt::config::CConfigFileMemory ini(ini_text);
        TraversabilityMapOptions o;
        o.loadFromConfigFile(ini, section);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(MapOptions, KeysOfMapFilterAndLibtravelAreRead) {
    mrpt::config::CConfigFileMemory ini(
        "[m]\nresolution=0.5\nmin_x=-5\nray_stride=3\nmax_step_height=0.2\npreset=vlp16\n"
        "sensor_height=1.1\nsensor_label=VLP.*\n");
    TraversabilityMapOptions o;
    o.loadFromConfigFile(ini, "m");
    EXPECT_EQ(o.resolution, 0.5);
    EXPECT_EQ(o.min_x, -5.0);
    EXPECT_EQ(o.ray_stride, 3);
    EXPECT_FLOAT_EQ(o.max_step_height, 0.2f);
    EXPECT_EQ(o.travel.params.sensor_height, 1.1);
    EXPECT_EQ(o.travel.params.num_rings, 16) << "from the vlp16 preset";
    EXPECT_EQ(o.travel.sensor_label, "VLP.*");

    // Saved text reads back to the same values.
    mrpt::config::CConfigFileMemory saved;
    o.saveToConfigFile(saved, "s");
    mrpt::config::CConfigFileMemory reread(saved.getContent());
    TraversabilityMapOptions back;
    back.loadFromConfigFile(reread, "s");
    EXPECT_EQ(back.min_x, -5.0);
    EXPECT_EQ(back.ray_stride, 3);
    EXPECT_EQ(back.travel.params.sensor_height, 1.1);
}

TEST(MapOptions, BadKeysAreRejectedWithTheirName) {
    EXPECT_NE(errorOf("[m]\nresolutoin=0.5\n", "m").find("unknown key 'resolutoin'"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolutoin=0.5\n", "m").find("section 'm': "), std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolutoin=0.5\n", "m").find("did you mean 'resolution'"),
              std::string::npos);
    // The map's slope limit has its own name: the old one is libtravel's.
    EXPECT_NE(errorOf("[m]\nmax_traversable_slope_dg=20\n", "m").find("max_traversable_slope_deg"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolution=abc\n", "m")
                  .find("invalid value for 'resolution': 'abc' is not a finite number"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nray_stride=1.5\n", "m").find("'1.5' is not an integer"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nmin_x=5\nmax_x=1\n", "m").find("min_x"), std::string::npos);
    EXPECT_NE(errorOf("[m]\nsensor_height=-1\n", "m").find("sensor_height"), std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolution=0.0001\nmin_x=-100\nmax_x=100\n", "m").find("16384"),
              std::string::npos);
}

TEST(MapOptions, IniFileErrorsNameFileLineAndSection) {
    const std::string path = mrpt::system::getTempFileName() + "_map_options.ini";
    std::ofstream(path) << "[other]\nresolution=1\n[m]\nresolution=0.5\n  ray_strid=3\n";
    std::string message;
    try {
        mrpt::config::CConfigFile ini(path);
        TraversabilityMapOptions o;
        o.loadFromConfigFile(ini, "m");
    } catch (const std::exception& e) {
        message = e.what();
    }
    std::remove(path.c_str());
    EXPECT_NE(message.find(path + ":5:3: section 'm': unknown key 'ray_strid'"), std::string::npos)
        << message;
    EXPECT_NE(message.find("did you mean 'ray_stride'"), std::string::npos) << message;
}

// A preset in the insertion section is the base of the creation section's keys too: they keep
// their values (they were reset to the preset's when each section applied its own preset).
TEST(MapOptions, PresetInEitherMapSectionIsTheBaseOfBoth) {
    const travel::Params vlp16 = travel::loadPreset("vlp16");
    ASSERT_NE(vlp16.max_range, travel::Params().max_range) << "a preset value to see";
    const auto create = [](const std::string& creation, const std::string& insertion) {
        mrpt::config::CConfigFileMemory ini(
            "[MAP]\ntraversabilityMap_count=1\n"
            "[MAP_traversabilityMap_00_creationOpts]\n" +
            creation + "[MAP_traversabilityMap_00_insertOpts]\n" + insertion);
        mrpt::maps::TSetOfMetricMapInitializers initializers;
        initializers.loadFromConfigFile(ini, "MAP");
        mrpt::maps::CMultiMetricMap maps(initializers);
        return maps.mapByClass<travel_mrpt::CTraversabilityMap>()->options().travel.params;
    };
    for (const auto& [creation, insertion] :
         {std::pair<std::string, std::string>{"sensor_height=1.8\nmax_slope_deg=33\n",
                                              "preset=vlp16\n"},
          {"preset=vlp16\nsensor_height=1.8\n", "max_slope_deg=33\n"}}) {
        const travel::Params p = create(creation, insertion);
        EXPECT_EQ(p.sensor_height, 1.8) << creation << insertion;
        EXPECT_EQ(p.max_slope_deg, 33.0) << creation << insertion;
        EXPECT_EQ(p.max_range, vlp16.max_range) << creation << insertion;
    }
    // Two presets: which one is the base would be a guess.
    try {
        create("preset=vlp16\n", "preset=hdl32\n");
        FAIL() << "no error for two presets";
    } catch (const std::exception& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("a second preset"), std::string::npos) << message;
        EXPECT_NE(message.find("_creationOpts"), std::string::npos) << message;
        EXPECT_NE(message.find("_insertOpts"), std::string::npos) << message;
    }
}

// Quotes around a value are removed as in every other config file (the regex matched no label
// with them kept).
TEST(MapOptions, QuotedValuesAreReadWithoutTheQuotes) {
    for (const char* written : {"\"Velodyne.*\"", "'Velodyne.*'", "\"Velodyne.*\"  # a regex"}) {
        mrpt::config::CConfigFileMemory ini(std::string("[m]\nsensor_label=") + written + "\n");
        TraversabilityMapOptions o;
        o.loadFromConfigFile(ini, "m");
        EXPECT_EQ(o.travel.sensor_label, "Velodyne.*") << written;
    }
    const std::string message = errorOf("[m]\nsensor_label=\"Velodyne.*\n", "m");
    EXPECT_NE(message.find("sensor_label: unterminated quoted value"), std::string::npos)
        << message;
    // Written back (a map's options are saved as ini text when it is serialized) and read
    // again: the same text, comment characters and quotes included (quoted when needed).
    for (const char* label : {"Velodyne.*", "front#1", "a;b", "'left", "\"right", " pad"}) {
        TraversabilityMapOptions o, back;
        o.travel.sensor_label = label;
        mrpt::config::CConfigFileMemory ini;
        o.saveToConfigFile(ini, "m");
        back.loadFromConfigFile(ini, "m");
        EXPECT_EQ(back.travel.sensor_label, label);
    }
}

// Through CMultiMetricMap, MRPT's exception wrapper reads "...[x]..." as "file: [function]
// message": the message must keep its file, line, section and key whole.
TEST(MapOptions, ErrorsThroughCMultiMetricMapStayWhole) {
    const std::string path = mrpt::system::getTempFileName() + "_map_errors.ini";
    std::ofstream(path) << "[MAP]\ntraversabilityMap_count=1\n"
                           "[MAP_traversabilityMap_00_creationOpts]\nresolutoin=0.2\n";
    std::string message;
    try {
        mrpt::maps::TSetOfMetricMapInitializers initializers;
        initializers.loadFromConfigFile(mrpt::config::CConfigFile(path), "MAP");
    } catch (const std::exception& e) {
        message = e.what();
    }
    std::remove(path.c_str());
    EXPECT_NE(
        message.find(path + ":4:1: section 'MAP_traversabilityMap_00_creationOpts': unknown key "
                            "'resolutoin'"),
        std::string::npos)
        << message;
}

TEST(MapOptions, SameKeysAsTheMapSectionOfAConfigFile) {
    // A [map] section of the one configuration file gives the same options as the flat section.
    travel::Config config;
    travel::applyConfigText("[map]\nresolution = 0.5\nmax_traversable_slope_deg = 12\n", "c.ini",
                            config);
    mrpt::config::CConfigFileMemory ini("[m]\nresolution=0.5\nmax_traversable_slope_deg=12\n");
    TraversabilityMapOptions o;
    o.loadFromConfigFile(ini, "m");
    EXPECT_EQ(o.resolution, config.map.resolution);
    EXPECT_EQ(o.max_traversable_slope_deg, config.map.max_traversable_slope_deg);
    EXPECT_EQ(o.travel.params.max_slope_deg, travel::Params().max_slope_deg)
        << "travel's untouched";
}

TEST(MapOptions, CMultiMetricMapCreatesTheMapFromAnIni) {
    mrpt::config::CConfigFileMemory ini(travel_map_test::mapIni("MAP"));
    mrpt::maps::TSetOfMetricMapInitializers initializers;
    initializers.loadFromConfigFile(ini, "MAP");
    mrpt::maps::CMultiMetricMap maps(initializers);
    auto map = maps.mapByClass<travel_mrpt::CTraversabilityMap>();
    ASSERT_TRUE(map);
    EXPECT_EQ(map->grid().sizeX(), 112);  // 28 m / 0.25 m
    EXPECT_EQ(map->grid().sizeY(), 88);   // 22 m / 0.25 m
    EXPECT_EQ(map->options().travel.params.sensor_height, 1.8);
    // max_traversable_slope_deg (the map's) and max_slope_deg (libtravel's) are distinct keys:
    // value (20 in the .ini, libtravel's default 25) survives.
    mrpt::config::CConfigFileMemory saved;
    map->options().saveToConfigFile(saved, "m");
    travel_mrpt::TraversabilityMapOptions reread;
    reread.loadFromConfigFile(saved, "m");
    EXPECT_FLOAT_EQ(reread.max_traversable_slope_deg, 20.f);
    EXPECT_FLOAT_EQ(reread.max_neighbour_step, 0.1f);

    // An unknown key in the .ini fails the creation with the key and section named.
    mrpt::config::CConfigFileMemory bad(travel_map_test::mapIni("MAP") + "colour=red\n");
    mrpt::maps::TSetOfMetricMapInitializers bad_initializers;
    try {
        bad_initializers.loadFromConfigFile(bad, "MAP");
        FAIL() << "no error for an unknown key";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("colour"), std::string::npos) << e.what();
    }
}

// MRPT reads enableSaveAs3DObject, enableObservationLikelihood and enableObservationInsertion
// (TMapGenericParams) from every map's _creationOpts itself: they are no unknown keys there, and
// MRPT applies them. In _insertOpts, where nothing reads them, they stay unknown.
TEST(MapOptions, MrptsGenericMapKeysInCreationOptsAreLeftToMrpt) {
    const std::string generic = "enableSaveAs3DObject=false\nenableObservationInsertion=false\n";
    std::string ini = travel_map_test::mapIni("MAP");
    const std::string creation = "_traversabilityMap_00_creationOpts]\n";
    ini.insert(ini.find(creation) + creation.size(), generic);
    mrpt::maps::TSetOfMetricMapInitializers initializers;
    initializers.loadFromConfigFile(mrpt::config::CConfigFileMemory(ini), "MAP");
    mrpt::maps::CMultiMetricMap maps(initializers);
    auto map = maps.mapByClass<travel_mrpt::CTraversabilityMap>();
    ASSERT_TRUE(map);
    EXPECT_FALSE(map->genericMapParams.enableSaveAs3DObject);
    EXPECT_FALSE(map->genericMapParams.enableObservationInsertion);
    EXPECT_EQ(map->options().resolution, 0.25) << "the map's own keys are still read";

    const std::string in_insert = travel_map_test::mapIni("MAP") + "enableSaveAs3DObject=false\n";
    try {
        mrpt::maps::TSetOfMetricMapInitializers bad;
        bad.loadFromConfigFile(mrpt::config::CConfigFileMemory(in_insert), "MAP");
        FAIL() << "no error for MRPT's key in _insertOpts";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("unknown key 'enableSaveAs3DObject'"),
                  std::string::npos)
            << e.what();
    }
}

// A section of this map kind that CMultiMetricMap never reads (misspelt index or suffix, index
// beyond traversabilityMap_count) would lose its keys without a word: an error naming it and
// the sections that are read. Sections of other maps or other CMultiMetricMap sections, and
// empty sections, are not checked.
TEST(MapOptions, SectionsCMultiMetricMapNeverReadsAreNamed) {
    const auto errorFor = [](const std::string& ini) -> std::string {
        try {
            mrpt::maps::TSetOfMetricMapInitializers initializers;
            initializers.loadFromConfigFile(mrpt::config::CConfigFileMemory(ini), "MAP");
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    const std::string head = "[MAP]\ntraversabilityMap_count=1\n";
    for (const char* unread :
         {"MAP_traversabilityMap_0_creationOpts", "MAP_traversabilityMap_00_creationOpt",
          "MAP_traversabilityMap_01_insertOpts", "MAP_traversabilityMap_00_likelihoodOpts"}) {
        const std::string message = errorFor(head + "[" + unread + "]\nresolution=0.5\n");
        EXPECT_NE(message.find("section '" + std::string(unread) + "' is never read"),
                  std::string::npos)
            << unread << ": " << message;
        EXPECT_NE(message.find("from the sections 'MAP_traversabilityMap_00_creationOpts' and "
                               "'MAP_traversabilityMap_00_insertOpts' (traversabilityMap_count=1"),
                  std::string::npos)
            << message;
    }
    // Read: the right names in any letter case (MRPT's sections are case-insensitive), an empty
    // misnamed section, another CMultiMetricMap section's map, another map kind.
    EXPECT_EQ(errorFor(head + "[map_TRAVERSABILITYMAP_00_creationopts]\nresolution=0.5\n"), "");
    EXPECT_EQ(errorFor(head + "[MAP_traversabilityMap_0_creationOpts]\n"), "");
    EXPECT_EQ(errorFor(head + "[OTHER_traversabilityMap_00_creationOpts]\nresolution=0.5\n"), "");
    EXPECT_EQ(errorFor(head + "[MAP_octoMap_00_creationOpts]\nresolution=0.5\n"), "");
    // Two maps: both indices are read, the message names the range.
    const std::string two =
        "[MAP]\ntraversabilityMap_count=2\n[MAP_traversabilityMap_01_insertOpts]\n"
        "max_step_height=0.2\n";
    EXPECT_EQ(errorFor(two), "");
    EXPECT_NE(errorFor(two + "[MAP_traversabilityMap_02_insertOpts]\nmax_step_height=0.2\n")
                  .find("'MAP_traversabilityMap_NN_creationOpts' and "
                        "'MAP_traversabilityMap_NN_insertOpts', NN from 00 to 01"),
              std::string::npos);
}

// A robot pose with a NaN (a broken odometry) fuses nothing: insertObservation() returned true
// and counted the frame while nothing reached the map. It is refused, with the reason.
TEST(MapOptions, ANonFiniteRobotPoseIsRefusedNotSilentlyLost) {
    mrpt::maps::TSetOfMetricMapInitializers initializers;
    initializers.loadFromConfigFile(mrpt::config::CConfigFileMemory(travel_map_test::mapIni("MAP")),
                                    "MAP");
    mrpt::maps::CMultiMetricMap maps(initializers);
    auto map = maps.mapByClass<travel_mrpt::CTraversabilityMap>();
    ASSERT_TRUE(map);
    map->filter().setMinLoggingLevel(mrpt::system::LVL_ERROR);
    const auto scene = travel_map_test::mapScene();
    const auto obs = travel_map_test::sweep(scene, 0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(map->insertObservation(*obs, mrpt::poses::CPose3D(nan, 0, 0, 0, 0, 0)));
    EXPECT_NE(map->lastRejection().find("the robot pose is not finite"), std::string::npos)
        << map->lastRejection();
    EXPECT_EQ(map->framesInserted(), 0u);
    EXPECT_TRUE(map->insertObservation(*obs, travel_map_test::robotPoses().front()))
        << map->lastRejection();
    EXPECT_EQ(map->framesInserted(), 1u);
    EXPECT_GT(map->grid().observedCells(), 0u);
}

}  // namespace
