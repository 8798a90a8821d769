// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "TempDir.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/Params.hpp"
#include "travel/ParamsIO.hpp"

namespace fs = std::filesystem;
using travel::ConfigError;
using travel::Params;

namespace {

// The message of the ConfigError thrown by f, or "" if none was thrown.
template <class F>
std::string configErrorOf(F&& f) {
    try {
        f();
    } catch (const ConfigError& e) {
        return e.what();
    }
    return {};
}

#define EXPECT_CONTAINS(haystack, needle) \
    EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

using ParamValue = std::variant<double, std::string>;

std::vector<ParamValue> valuesOf(const Params& p) {
    std::vector<ParamValue> values;
    travel::visitParams(p,
                        [&](const char*, const auto& v, const char*, double, double, const char*) {
                            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) {
                                values.emplace_back(v);
                            } else {
                                values.emplace_back(static_cast<double>(v));
                            }
                        });
    return values;
}

Params fromText(const std::string& text) {
    Params p;
    travel::applyParamsText(text, "test.yaml", p);
    return p;
}

using travel_test::TempDir;

}  // namespace

// ---- Params::validate ------------------------------------------------------------------------

TEST(ParamsValidate, DefaultsAreValid) {
    EXPECT_NO_THROW(Params().validate());
}

TEST(ParamsValidate, OutOfRangeNamesParameterValueAndRange) {
    Params p;
    p.tgf_resolution = 0.1;
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "tgf_resolution");
    EXPECT_CONTAINS(msg, "0.1");
    EXPECT_CONTAINS(msg, "0.25");
    EXPECT_CONTAINS(msg, "100");
}

TEST(ParamsValidate, IntOutOfRange) {
    Params p;
    p.node_min_points = 2;
    EXPECT_CONTAINS(configErrorOf([&] { p.validate(); }), "node_min_points");
}

TEST(ParamsValidate, RejectsNaNAndInf) {
    Params p;
    p.eps1 = std::numeric_limits<double>::quiet_NaN();
    EXPECT_CONTAINS(configErrorOf([&] { p.validate(); }), "eps1");
    p = Params();
    p.max_range = std::numeric_limits<double>::infinity();
    EXPECT_CONTAINS(configErrorOf([&] { p.validate(); }), "max_range");
}

TEST(ParamsValidate, SelfBoxMinMustNotExceedMax) {
    Params p;
    p.self_box_min_y = 1.6, p.self_box_max_y = -1.6;
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "self_box_min_y");
    EXPECT_CONTAINS(msg, "self_box_max_y");
}

TEST(ParamsValidate, MinRangeMustBeBelowMaxRange) {
    Params p;
    p.min_range = 80.0;
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "min_range");
    EXPECT_CONTAINS(msg, "max_range");
}

TEST(ParamsValidate, StringNotAnAllowedValue) {
    Params p;
    p.ring_source = "laser";
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "ring_source");
    EXPECT_CONTAINS(msg, "'laser'");
    EXPECT_CONTAINS(msg, "auto|field|scan_order|table");
    p = Params();
    p.elevation_table = "Hdl64";  // validate() wants the exact spelling; the loader fixes case
    EXPECT_CONTAINS(configErrorOf([&] { p.validate(); }), "elevation_table");
}

TEST(ParamsValidate, ElevationBoundsOrdered) {
    Params p;
    p.min_elevation_deg = 5.0;
    p.max_elevation_deg = 5.0;
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "min_elevation_deg");
    EXPECT_CONTAINS(msg, "max_elevation_deg");
}

TEST(ParamsValidate, ClusterSizesOrdered) {
    Params p;
    p.min_cluster_size = 50;
    p.max_cluster_size = 49;
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "min_cluster_size");
    EXPECT_CONTAINS(msg, "max_cluster_size");
    p.max_cluster_size = 50;  // equal is allowed: exactly one size
    EXPECT_NO_THROW(p.validate());
}

TEST(ParamsValidate, GridSizeLimit) {
    Params p;
    p.max_range = 1000.0;
    p.tgf_resolution = 1.0;  // 2000 cells per side > 1024
    const std::string msg = configErrorOf([&] { p.validate(); });
    EXPECT_CONTAINS(msg, "max_grid_cells_per_side");
    EXPECT_CONTAINS(msg, "tgf_resolution");
    EXPECT_CONTAINS(msg, "max_range");
    p.max_grid_cells_per_side = 2000;  // exactly enough
    EXPECT_NO_THROW(p.validate());
}

// ---- applyParamsText: syntax -----------------------------------------------------------------

TEST(ParamsText, YamlAndComments) {
    const Params p = fromText(
        "# a comment\n"
        "---\n"
        "\n"
        "tgf_resolution: 4      # trailing comment\n"
        "node_min_points: 7\n"
        "ttmf: false\n");
    EXPECT_EQ(p.tgf_resolution, 4.0);
    EXPECT_EQ(p.node_min_points, 7);
    EXPECT_FALSE(p.ttmf);
    EXPECT_EQ(p.max_range, Params().max_range);  // untouched keys keep their defaults
}

TEST(ParamsText, IniWithSection) {
    const Params p = fromText(
        "; ini comment\n"
        "[travel]\n"
        "tgf_resolution = 2.5\r\n"  // CRLF
        "  deskew = off\n");
    EXPECT_EQ(p.tgf_resolution, 2.5);
    EXPECT_FALSE(p.deskew);
    // A comment after a value, '#' or ';' alike (';' was part of the value: "not a number");
    // an empty section name is an error (it was read as [travel]).
    const Params commented = fromText("[travel]\ntgf_resolution = 3 ; metres\neps1 = 0.1 # x\n");
    EXPECT_EQ(commented.tgf_resolution, 3.0);
    EXPECT_EQ(commented.eps1, 0.1);
    EXPECT_CONTAINS(configErrorOf([] { fromText("[]\ntgf_resolution = 3\n"); }),
                    "test.yaml:1:1: empty section name '[]'");
}

TEST(ParamsText, YamlTravelWrapper) {
    const Params p = fromText(
        "travel:\n"
        "  tgf_resolution: 3\n"
        "  sensor_height: 0.5\n");
    EXPECT_EQ(p.tgf_resolution, 3.0);
    EXPECT_EQ(p.sensor_height, 0.5);
}

TEST(ParamsText, QuotedValues) {
    const Params p = fromText("tgf_resolution: \"4.5\"  # q\nttmf: 'no'\n");
    EXPECT_EQ(p.tgf_resolution, 4.5);
    EXPECT_FALSE(p.ttmf);
    EXPECT_CONTAINS(configErrorOf([] { fromText("tgf_resolution: \"4.5\n"); }), "test.yaml:");
}

TEST(ParamsText, Strings) {
    EXPECT_EQ(fromText("ring_source: table").ring_source, "table");
    EXPECT_EQ(fromText("ring_source: \"scan_order\"  # q").ring_source, "scan_order");
    EXPECT_EQ(fromText("[travel]\nelevation_table = 'vlp16'\n").elevation_table, "vlp16");
    EXPECT_EQ(fromText("elevation_table: OS128").elevation_table, "os128");  // stored as listed
    EXPECT_EQ(fromText("ring_source: field # comment").ring_source, "field");
    for (const char* bad : {"laser", "\"\"", "'table '", "table x", "scan-order"}) {
        const std::string msg =
            configErrorOf([&] { fromText(std::string("\nring_source: ") + bad); });
        EXPECT_CONTAINS(msg, "test.yaml:2:") << bad;
        EXPECT_CONTAINS(msg, "'ring_source'");
        EXPECT_CONTAINS(msg, "auto|field|scan_order|table");
    }
    EXPECT_CONTAINS(configErrorOf([] { fromText("ring_source: laser"); }), "'laser'");
    EXPECT_CONTAINS(configErrorOf([] { fromText("ring_source:"); }), "missing value");
}

TEST(ParamsText, Booleans) {
    for (const char* t : {"true", "TRUE", "Yes", "on", "1"}) {
        EXPECT_TRUE(fromText(std::string("ttmf: ") + t).ttmf) << t;
    }
    for (const char* f : {"false", "False", "NO", "off", "0"}) {
        EXPECT_FALSE(fromText(std::string("ttmf: ") + f).ttmf) << f;
    }
    EXPECT_CONTAINS(configErrorOf([] { fromText("ttmf: maybe"); }), "test.yaml:1:");
    EXPECT_CONTAINS(configErrorOf([] { fromText("ttmf: 2"); }), "boolean");
}

TEST(ParamsText, Numbers) {
    EXPECT_EQ(fromText("eps1: 1e-2").eps1, 0.01);
    EXPECT_EQ(fromText("eps1: +0.5").eps1, 0.5);
    EXPECT_EQ(fromText("mount_yaw_deg: -90").mount_yaw_deg, -90.0);
    EXPECT_EQ(fromText("node_min_points: 12.0").node_min_points, 12);
    for (const char* bad :
         {"1.5m", "abc", "", "nan", "inf", "-inf", "1e999", "1.5 2", "++1", "0x10", "1,5"}) {
        const std::string msg = configErrorOf([&] { fromText(std::string("eps1: ") + bad); });
        EXPECT_CONTAINS(msg, "test.yaml:1:") << "value " << bad;
        EXPECT_CONTAINS(msg, "eps1");
    }
}

TEST(ParamsText, Integers) {
    EXPECT_CONTAINS(configErrorOf([] { fromText("node_min_points: 8.5"); }), "integer");
    EXPECT_CONTAINS(configErrorOf([] { fromText("node_min_points: 3000000000"); }), "int");
    // Out of the parameter's own range, reported with the line.
    const std::string msg = configErrorOf([] { fromText("\n\nnode_min_points: 2"); });
    EXPECT_CONTAINS(msg, "test.yaml:3:");
    EXPECT_CONTAINS(msg, "[3, 1000000]");
}

TEST(ParamsText, UnknownKeySuggestsClosest) {
    const std::string msg = configErrorOf([] { fromText("\ntgf_resolutoin: 4\n"); });
    EXPECT_CONTAINS(msg, "test.yaml:2:");
    EXPECT_CONTAINS(msg, "unknown key 'tgf_resolutoin'");
    EXPECT_CONTAINS(msg, "did you mean 'tgf_resolution'");
    EXPECT_CONTAINS(configErrorOf([] { fromText("resolution: 4"); }), "'tgf_resolution'");
    // No suggestion when nothing is close.
    const std::string far = configErrorOf([] { fromText("completely_unrelated: 4"); });
    EXPECT_CONTAINS(far, "unknown key 'completely_unrelated'");
    EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
}

TEST(ParamsText, DuplicateKey) {
    const std::string msg = configErrorOf([] { fromText("eps1: 0.1\neps2: 0.1\n\neps1: 0.2\n"); });
    EXPECT_CONTAINS(msg, "test.yaml:4:");
    EXPECT_CONTAINS(msg, "duplicate key 'eps1'");
    EXPECT_CONTAINS(msg, "line 1");
}

TEST(ParamsText, SectionErrors) {
    EXPECT_CONTAINS(configErrorOf([] { fromText("[other]\neps1 = 1\n"); }),
                    "unknown section 'other'");
    EXPECT_CONTAINS(configErrorOf([] { fromText("travel:\n  eps1: 1\ntravel:\n  eps2: 1\n"); }),
                    "twice");
    EXPECT_CONTAINS(configErrorOf([] { fromText("[travel\n"); }), "malformed section");
    EXPECT_CONTAINS(configErrorOf([] { fromText("ros:\n  eps1: 1\n"); }), "unknown section 'ros'");
    EXPECT_CONTAINS(configErrorOf([] { fromText("mapp:\n  resolution: 1\n"); }),
                    "did you mean 'map'");
}

TEST(ParamsText, StructureErrors) {
    EXPECT_CONTAINS(configErrorOf([] { fromText("just text"); }), "expected 'key: value'");
    EXPECT_CONTAINS(configErrorOf([] { fromText("- eps1: 1"); }), "expected 'key: value'");
    EXPECT_CONTAINS(configErrorOf([] { fromText("eps1:\n"); }), "missing value for 'eps1'");
    // Indented keys are only accepted under `travel:`.
    EXPECT_CONTAINS(configErrorOf([] { fromText("eps1: 0.1\n  eps2: 0.1\n"); }), "test.yaml:");
    EXPECT_CONTAINS(configErrorOf([] { fromText("travel:\n eps1: 0.1\neps2: 0.1\n  ttmf: 0\n"); }),
                    "test.yaml:4:");
    // A second YAML document was ignored, keys, typos and out-of-range values alike; an
    // explicit start marker and an empty document after an end marker are still one.
    const std::string second = configErrorOf([] { fromText("eps1: 0.1\n---\nfoo: 1\n"); });
    EXPECT_CONTAINS(second, "test.yaml:3:");
    EXPECT_CONTAINS(second, "a second YAML document");
    EXPECT_DOUBLE_EQ(fromText("---\neps1: 0.25\n...\n").eps1, 0.25);
    EXPECT_DOUBLE_EQ(fromText("eps1: 0.25\n---\n").eps1, 0.25);
}

// ---- Files, presets, overrides ---------------------------------------------------------------

TEST(ParamsFile, MissingFile) {
    Params p;
    const std::string msg =
        configErrorOf([&] { travel::applyParamsFile("/nonexistent/x.yaml", p); });
    EXPECT_CONTAINS(msg, "/nonexistent/x.yaml");
}

TEST(ParamsFile, ValidatesAfterwardsWithFileName) {
    TempDir dir;
    const std::string path = dir.write("bad.yaml", "min_range: 50\nmax_range: 40\n");
    Params p;
    const std::string msg = configErrorOf([&] { travel::applyParamsFile(path, p); });
    EXPECT_EQ(msg.rfind(path + ":1: ", 0), 0u) << msg;  // the line of the key the rule names
    EXPECT_CONTAINS(msg, "min_range");
}

// A binary file given as a configuration (a scan, by mistake) is named as such, not echoed; a
// value of thousands of characters is quoted in part, with its size.
TEST(ConfigFile, BinaryFilesAndHugeValuesGiveShortMessages) {
    TempDir dir;
    travel::Config config;
    const std::string scan = dir.write("scan.bin", std::string("\x12\x34\0\0\xFF\xFE key: 1", 12));
    const std::string binary = configErrorOf([&] { travel::applyConfigFile(scan, config); });
    EXPECT_CONTAINS(binary, scan + ": not a text file (byte 0x12 at offset 0)");
    const std::string huge =
        dir.write("huge.yaml", "travel:\n  ground_dist: " + std::string(5000, 'x') + "\n");
    const std::string message = configErrorOf([&] { travel::applyConfigFile(huge, config); });
    EXPECT_CONTAINS(message, huge + ":2");
    EXPECT_CONTAINS(message, "... (5000 bytes) is not a finite number");
    EXPECT_LT(message.size(), 300u) << message;
    const std::string line = dir.write("line.ini", "[travel]\n" + std::string(3000, 'y') + "\n");
    const std::string no_equals = configErrorOf([&] { travel::applyConfigFile(line, config); });
    EXPECT_CONTAINS(no_equals, "... (3000 bytes)");
    EXPECT_LT(no_equals.size(), 300u) << no_equals;
}

TEST(ConfigFile, RuleErrorsNameTheLineOfTheirKey) {
    TempDir dir;
    travel::Config config;
    // A rule beyond the key's range (max_motion_age > 0), in a section, ini and YAML.
    const std::string ini = dir.write("f.ini", "[filter]\nsensor_label = .*\nmax_motion_age = 0\n");
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyConfigFile(ini, config); }),
                    ini + ":3: section 'filter': max_motion_age");
    const std::string yaml = dir.write("f.yaml", "filter:\n  max_motion_age: 0\n");
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyConfigFile(yaml, config); }),
                    yaml + ":2: section 'filter': max_motion_age");
    // A rule on two keys names the first of them that the file set.
    const std::string map = dir.write("m.yaml", "map:\n  resolution: 0.5\n  max_x: -30\n");
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyConfigFile(map, config); }),
                    map + ":3: section 'map': min_x/max_x");
    const std::string tracking =
        dir.write("t.yaml", "tracking:\n  moving_speed_on: 0.1\n");  // off (0.5) >= on
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyConfigFile(tracking, config); }),
                    tracking + ":2: section 'tracking': moving_speed_off/moving_speed_on");
    // A rule naming its keys in its sentence: the line of the one the file set.
    const std::string clusters = dir.write("c.yaml", "travel:\n  max_cluster_size: 2\n");
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyConfigFile(clusters, config); }),
                    clusters + ":2: section 'travel': ");
}

TEST(ParamsFile, LineErrorsNameTheFile) {
    TempDir dir;
    const std::string path = dir.write("typo.ini", "[travel]\ntgf_resolutoin = 4\n");
    Params p;
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyParamsFile(path, p); }), path + ":2:");
}

TEST(Presets, AllShippedPresetsLoad) {
    const auto names = travel::availablePresets();
    for (const char* expected : {"hdl32", "hdl64", "os128", "vlp16"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    }
    for (const auto& name : names) {
        EXPECT_NO_THROW(travel::loadPreset(name).validate()) << name;
    }
}

TEST(Presets, Values) {
    // hdl64 = the defaults plus the KITTI car: its self-filter box and the small sphere left.
    Params kitti_car;
    kitti_car.min_range = 1.0;
    kitti_car.self_box_min_x = -2.2, kitti_car.self_box_max_x = 2.8;
    kitti_car.self_box_min_y = -1.6, kitti_car.self_box_max_y = 1.6;
    kitti_car.self_box_min_z = -1.73, kitti_car.self_box_max_z = 0.0;
    EXPECT_EQ(valuesOf(travel::loadPreset("hdl64")), valuesOf(kitti_car));
    // No vehicle known for the other presets: no box, today's behaviour.
    for (const char* name : {"hdl32", "vlp16", "os64", "os128"}) {
        const Params p = travel::loadPreset(name);
        EXPECT_EQ(p.self_box_min_x, p.self_box_max_x) << name;
    }
    const Params hdl32 = travel::loadPreset("hdl32");
    EXPECT_EQ(hdl32.sensor_height, 1.84);
    EXPECT_EQ(hdl32.mount_yaw_deg, -90.0);
    EXPECT_EQ(hdl32.tgf_resolution, 4.0);
    const Params vlp16 = travel::loadPreset("vlp16");
    EXPECT_EQ(vlp16.node_min_points, 5);
    EXPECT_EQ(vlp16.max_range, 60.0);
    const Params os128 = travel::loadPreset("os128");
    EXPECT_EQ(os128.sensor_height, 0.0);
    // Buffers for the OS1-128's densest mode (128 x 2048), not the 1024-column range image.
    EXPECT_EQ(os128.scan_points, 128 * 2048);
    EXPECT_EQ(hdl32.scan_points, 0);
}

TEST(Presets, UnknownPresetListsAvailableAndSearched) {
    const std::string msg = configErrorOf([] { travel::loadPreset("nope"); });
    EXPECT_CONTAINS(msg, "'nope'");
    EXPECT_CONTAINS(msg, "hdl64");
    EXPECT_CONTAINS(msg, "presets");
    // Names only, no paths.
    EXPECT_CONTAINS(configErrorOf([] { travel::findPresetFile("../presets/hdl64"); }), "not found");
}

TEST(Presets, PresetKeyThenOverrides) {
    const Params p = fromText("# my robot\npreset: vlp16\nsensor_height: 0.8\n");
    EXPECT_EQ(p.sensor_height, 0.8);
    EXPECT_EQ(p.node_min_points, 5);
    EXPECT_EQ(p.tgf_resolution, 4.0);
    EXPECT_EQ(fromText("travel:\n  preset: \"hdl32\"\n").mount_yaw_deg, -90.0);
    EXPECT_CONTAINS(configErrorOf([] { fromText("eps1: 0.1\npreset: vlp16\n"); }),
                    "'preset' must come before");
    EXPECT_CONTAINS(configErrorOf([] { fromText("preset: nope\n"); }),
                    "test.yaml:1:1: preset 'nope'");
}

TEST(Presets, EnvironmentDirectoryComesFirst) {
    TempDir dir;
    dir.write("presets/vlp16.yaml", "sensor_height: 0.42\n");
    dir.write("presets/mine.yaml", "preset: vlp16\neps1: 0.05\n");
    dir.write("presets/loop.yaml", "preset: loop\n");
    ::setenv("TRAVEL_SHARE_DIR", dir.path.c_str(), 1);
    EXPECT_EQ(travel::shareSearchDirs().front(), dir.path.string());
    EXPECT_EQ(travel::findShareDir(), dir.path.string());
    EXPECT_EQ(travel::loadPreset("vlp16").sensor_height, 0.42);
    const Params mine = travel::loadPreset("mine");
    EXPECT_EQ(mine.sensor_height, 0.42);
    EXPECT_EQ(mine.eps1, 0.05);
    EXPECT_CONTAINS(configErrorOf([] { travel::loadPreset("loop"); }), "cycle");
    const auto names = travel::availablePresets();
    EXPECT_NE(std::find(names.begin(), names.end(), "mine"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "hdl64"), names.end());
    ::unsetenv("TRAVEL_SHARE_DIR");
    EXPECT_EQ(travel::loadPreset("vlp16").sensor_height, 0.5);
}

TEST(Overrides, Apply) {
    Params p;
    travel::applyOverride("tgf_resolution=4", p);
    travel::applyOverride(" ttmf = no ", p);
    EXPECT_EQ(p.tgf_resolution, 4.0);
    EXPECT_FALSE(p.ttmf);
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyOverride("tgf_resolution", p); }),
                    "key=value");
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyOverride("tgf_resolutoin=4", p); }),
                    "did you mean 'tgf_resolution'");
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyOverride("tgf_resolution=0.01", p); }),
                    "tgf_resolution");
    EXPECT_EQ(p.tgf_resolution, 4.0);  // a rejected override changes nothing
}

TEST(Overrides, Strings) {
    Params p;
    travel::applyOverride("ring_source=table", p);
    EXPECT_EQ(p.ring_source, "table");
    travel::applyOverride("elevation_table = 'uniform'", p);
    EXPECT_EQ(p.elevation_table, "uniform");
    const std::string msg = configErrorOf([&] { travel::applyOverride("ring_source=ring", p); });
    EXPECT_CONTAINS(msg, "ring_source");
    EXPECT_CONTAINS(msg, "'ring'");
    EXPECT_CONTAINS(msg, "auto|field|scan_order|table");
    EXPECT_EQ(p.ring_source, "table");
}

// ---- paramsToYaml ----------------------------------------------------------------------------

TEST(ParamsYaml, RoundTripsExactly) {
    Params p;
    p.eps1 = 0.1 + 0.2;  // not representable by a short decimal
    p.sensor_height = 1.0 / 3.0;
    p.max_range = 100.0;
    p.node_min_points = 123;
    p.deskew = false;
    p.mount_yaw_deg = -90.0;
    p.ring_source = "scan_order";
    p.elevation_table = "uniform";
    const std::string yaml = travel::paramsToYaml(p);
    const Params back = fromText(yaml);
    EXPECT_EQ(valuesOf(back), valuesOf(p));
    EXPECT_EQ(travel::paramsToYaml(back), yaml);
}

TEST(ParamsYaml, EveryKeyWithCommentedUnitAndRange) {
    const std::string yaml = travel::paramsToYaml(Params());
    EXPECT_CONTAINS(yaml, "# [m] Height of the sensor origin");
    EXPECT_CONTAINS(yaml, "(range [0, 100] or auto)\nsensor_height: 1.73\n");
    EXPECT_CONTAINS(yaml, "\nmax_range: 80.0\n");
    EXPECT_CONTAINS(yaml, "(true/false)\nttmf: true\n");
    EXPECT_CONTAINS(yaml, "\nmax_grid_cells_per_side: 512\n");
    EXPECT_CONTAINS(yaml, "(one of auto|field|scan_order|table)\nring_source: auto\n");
    EXPECT_CONTAINS(yaml, "(one of hdl64|hdl32|vlp16|os128|uniform)\nelevation_table: hdl64\n");
    const Params defaults;
    std::istringstream lines(yaml);
    for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 100u) << line;
    travel::visitParams(
        defaults, [&](const char* name, const auto&, const char*, double, double, const char*) {
            EXPECT_CONTAINS(yaml, "\n" + std::string(name) + ": ");
        });
}

// ---- `auto` mount values (sensor_height, mount_roll_deg, mount_pitch_deg) ---------------------

TEST(ParamsAuto, YamlIniAndOverrideAcceptAutoAndKeepTheFallback) {
    const Params yaml = fromText("preset: vlp16\nsensor_height: auto\nmount_pitch_deg: Auto\n");
    EXPECT_TRUE(yaml.sensor_height.isAuto());
    EXPECT_EQ(yaml.sensor_height.value, 0.5);  // the preset's value is the fallback
    EXPECT_TRUE(yaml.mount_pitch_deg.isAuto());
    EXPECT_FALSE(yaml.mount_roll_deg.isAuto());
    EXPECT_NO_THROW(yaml.validate());

    const Params ini = fromText("[travel]\nsensor_height = auto\nmount_roll_deg = AUTO\n");
    EXPECT_TRUE(ini.sensor_height.isAuto());
    EXPECT_EQ(ini.sensor_height.value, 1.73);
    EXPECT_TRUE(ini.mount_roll_deg.isAuto());

    Params p;
    travel::applyOverride("sensor_height=auto", p);
    EXPECT_TRUE(p.sensor_height.isAuto());
    travel::applyOverride("sensor_height=2.24", p);  // a number again: no longer auto
    EXPECT_FALSE(p.sensor_height.isAuto());
    EXPECT_EQ(p.sensor_height, 2.24);
}

TEST(ParamsAuto, PrintedBackAndReadAgain) {
    Params p;
    travel::applyOverride("sensor_height=auto", p);
    travel::applyOverride("mount_pitch_deg=auto", p);
    const std::string yaml = travel::paramsToYaml(p);
    EXPECT_CONTAINS(yaml, "\nsensor_height: auto(1.73)\n");  // the fallback is kept
    EXPECT_CONTAINS(yaml, "\nmount_pitch_deg: auto(0.0)\n");
    EXPECT_CONTAINS(yaml, "\nmount_roll_deg: 0.0\n");
    const Params back = fromText(yaml);
    EXPECT_TRUE(back.sensor_height.isAuto());
    EXPECT_TRUE(back.mount_pitch_deg.isAuto());
    EXPECT_FALSE(back.mount_roll_deg.isAuto());
    EXPECT_EQ(travel::paramsToYaml(back), yaml);
}

// --print-config of a preset with `auto` reads back, without the preset, with the preset's
// fallback (vlp16: 0.5 m, not the default 1.73 m).
TEST(ParamsAuto, PrintedConfigKeepsThePresetsFallback) {
    const Params preset = fromText("preset: vlp16\nsensor_height: auto\n");
    ASSERT_EQ(preset.sensor_height.value, 0.5);
    const std::string yaml = travel::paramsToYaml(preset);
    EXPECT_EQ(yaml.find("\npreset:"), std::string::npos);  // no preset line to rely on
    const Params back = fromText(yaml);
    EXPECT_TRUE(back.sensor_height.isAuto());
    EXPECT_EQ(back.sensor_height.value, 0.5);
    EXPECT_EQ(travel::paramsToYaml(back), yaml);
    // auto(FALLBACK) is also accepted by hand, range-checked like the number.
    const Params hand = fromText("[travel]\nsensor_height = Auto(2.5)\n");
    EXPECT_TRUE(hand.sensor_height.isAuto());
    EXPECT_EQ(hand.sensor_height.value, 2.5);
    EXPECT_CONTAINS(configErrorOf([] { fromText("sensor_height: auto(-1)\n"); }), "sensor_height");
    EXPECT_CONTAINS(configErrorOf([] { fromText("sensor_height: auto(x)\n"); }), "auto(FALLBACK)");
}

TEST(ParamsAuto, OnlyMountValuesAcceptAuto) {
    EXPECT_CONTAINS(configErrorOf([] { fromText("mount_yaw_deg: auto\n"); }), "mount_yaw_deg");
    EXPECT_CONTAINS(configErrorOf([] { fromText("tgf_resolution: auto\n"); }),
                    "is not a finite number");
    EXPECT_CONTAINS(configErrorOf([] { fromText("sensor_height: automatic\n"); }), "(or auto)");
    EXPECT_CONTAINS(configErrorOf([] { fromText("sensor_height: -1\n"); }), "sensor_height");
}

// ---------------------------------------------------------------- one configuration, sections

namespace {
travel::Config configFrom(const std::string& text) {
    travel::Config c;
    travel::applyConfigText(text, "c.yaml", c);
    c.validate();
    return c;
}
}  // namespace

TEST(ConfigSections, YamlAndIniSections) {
    const travel::Config y = configFrom(
        "travel:\n  tgf_resolution: 3\nfilter:\n  velocity_source: none\nmap:\n  resolution: 0.5\n"
        "  max_traversable_slope_deg: 15\nnav:\n  max_step_height: 0.2\n");
    EXPECT_EQ(y.travel.tgf_resolution, 3.0);
    EXPECT_EQ(y.filter.velocity_source, travel::VelocitySource::None);
    EXPECT_EQ(y.map.resolution, 0.5);
    EXPECT_FLOAT_EQ(y.map.max_traversable_slope_deg, 15.f);
    EXPECT_EQ(y.nav.max_step_height, 0.2);
    const travel::Config i = configFrom(
        "[travel]\ntgf_resolution = 3\n[filter]\nvelocity_source = none\n[map]\nresolution = 0.5\n"
        "max_traversable_slope_deg = 15\n[nav]\nmax_step_height = 0.2\n");
    EXPECT_EQ(travel::configToYaml(i), travel::configToYaml(y));
}

TEST(ConfigSections, ErrorsNameLineColumnSectionAndNearestKey) {
    const std::string msg =
        configErrorOf([] { configFrom("map:\n  resolution: 1\n  resolutoin: 2\n"); });
    EXPECT_CONTAINS(msg, "c.yaml:3:3: section 'map': unknown key 'resolutoin'");
    EXPECT_CONTAINS(msg, "did you mean 'resolution'");
    EXPECT_CONTAINS(configErrorOf([] { configFrom("nav:\n  max_height: -1\n"); }),
                    "c.yaml:2:3: section 'nav': 'max_height' = -1.0 is outside its allowed range");
    EXPECT_CONTAINS(configErrorOf([] { configFrom("[mapp]\nresolution = 1\n"); }),
                    "did you mean 'map'");
    EXPECT_CONTAINS(configErrorOf([] { configFrom("[map]\n\n  colour = red\n"); }), "c.yaml:3:3:");
    EXPECT_CONTAINS(configErrorOf([] { configFrom("map:\n  min_x: 5\n  max_x: 1\n"); }), "min_x");
    EXPECT_CONTAINS(configErrorOf([] { configFrom("filter: 3\n"); }), "must be a map");
}

TEST(ConfigSections, OverridesWithAndWithoutSection) {
    travel::Config c;
    travel::applyConfigOverride("map.resolution=0.4", c);
    travel::applyConfigOverride("velocity_source=imu", c);  // only the filter has it
    EXPECT_EQ(c.map.resolution, 0.4);
    EXPECT_EQ(c.filter.velocity_source, travel::VelocitySource::Imu);
    // max_step_height is a map key and a nav key: the section must be named.
    EXPECT_CONTAINS(configErrorOf([&] { travel::applyConfigOverride("max_step_height=1", c); }),
                    "map.max_step_height=...");
}

TEST(ConfigSections, PrintedConfigLoadsBackIdentically) {
    travel::Config c;
    c.travel = travel::loadPreset("vlp16");
    c.travel.ground_dist = 0.1 + 0.02;
    c.filter.sensor_label = "VLP 'front'.*";
    c.filter.velocity_source = travel::VelocitySource::Poses;
    c.map.logodds_ground = -0.37f;
    c.map.max_traversable_slope_deg = 17.5f;
    c.nav.memory_seconds = 1.0 / 3.0;
    const std::string printed = travel::configToYaml(c);
    const travel::Config back = configFrom(printed);
    EXPECT_EQ(travel::configToYaml(back), printed);
    EXPECT_EQ(back.travel.ground_dist, c.travel.ground_dist);
    EXPECT_EQ(back.filter.sensor_label, c.filter.sensor_label);
    EXPECT_EQ(back.nav.memory_seconds, c.nav.memory_seconds);
    EXPECT_CONTAINS(printed, "# [deg] A cell whose terrain model is steeper");
    // Texts that YAML reads as null when bare.
    for (const char* text : {"null", "Null", "NULL"}) {
        c.filter.sensor_label = text;
        EXPECT_EQ(configFrom(travel::configToYaml(c)).filter.sensor_label, text);
    }
}

namespace {
struct CommaDecimal : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
};
}  // namespace

TEST(ConfigSections, NumbersIgnoreTheGlobalLocale) {
    // A global locale whose decimal separator is ',' (C++ streams; and C's strtod/printf when a
    // German locale is installed) must not change what "0.5" means or how it is written.
    const std::locale previous =
        std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
    const bool c_locale_changed = std::setlocale(LC_NUMERIC, "de_DE.UTF-8") != nullptr;
    const travel::Config c = configFrom("map:\n  resolution: 0.5\nnav:\n  max_height: 1e3\n");
    const std::string printed = travel::configToYaml(c);
    const std::string error = configErrorOf([] { configFrom("map:\n  resolution: 0,5\n"); });
    std::locale::global(previous);
    std::setlocale(LC_NUMERIC, "C");
    EXPECT_EQ(c.map.resolution, 0.5);
    EXPECT_EQ(c.nav.max_height, 1000.0);
    EXPECT_CONTAINS(printed, "resolution: 0.5\n");
    EXPECT_CONTAINS(printed, "(range [1e-06, 10000])");
    EXPECT_CONTAINS(error, "'0,5' is not a finite number");
    if (!c_locale_changed) std::cout << "(de_DE.UTF-8 not installed: C locale part not run)\n";
}
