// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One loader for three sources: ini sections and YAML maps are both turned into ordered
// (key, value-text) lists, then applyAssignments() applies them with the same rules.
#include "travel_mrpt/TravelFilterOptions.hpp"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/containers/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <utility>
#include <vector>

#include "ConfigText.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace travel_mrpt {
namespace {
using config_text::exactText;
using config_text::lower;
using config_text::parseBool;
using config_text::parseNumber;

using KeyValues = std::vector<std::pair<std::string, std::string>>;

constexpr const char* kFilterKeys[] = {"preset",          "sensor_label",
                                       "use_sensor_pose", "use_robot_attitude",
                                       "velocity_source", "max_motion_age"};

bool isLibtravelKey(const std::string& key) {
    bool found = false;
    travel::Params probe;
    travel::visitParams(probe, [&](const char* name, auto&&...) { found = found || key == name; });
    return found;
}

template <class T>
std::string valueText(const T& value) {
    if constexpr (std::is_same_v<T, bool>)
        return value ? "true" : "false";
    else if constexpr (std::is_same_v<T, double>)
        return exactText(value);
    else if constexpr (std::is_same_v<T, int>)
        return std::to_string(value);
    else
        return value;
}

/// The shared rules: preset, libtravel keys, filter keys, unknown keys, validation. `source`
/// names where the keys come from ("section [travel] of x.ini"). Commits only on success.
void applyAssignments(const KeyValues& assignments, const std::string& source,
                      TravelFilterOptions& options) {
    TravelFilterOptions result = options;
    // Duplicate keys cannot come from either source here, but a preset must be applied first
    // wherever it is written.
    for (const auto& [key, value] : assignments)
        if (key == "preset") {
            try {
                result.params = travel::loadPreset(value);
            } catch (const std::exception& e) {
                throw travel::ConfigError(source + ": preset: " + e.what());
            }
        }
    for (const auto& [key, value] : assignments) {
        const std::string where = source + ": " + key;
        if (key == "preset") continue;
        if (isLibtravelKey(key)) {
            try {
                travel::applyOverride(key + "=" + value, result.params);
            } catch (const std::exception& e) {
                throw travel::ConfigError(source + ": " + e.what());
            }
        } else if (key == "sensor_label") {
            result.sensor_label = value;
        } else if (key == "use_sensor_pose") {
            result.use_sensor_pose = parseBool(value, where);
        } else if (key == "use_robot_attitude") {
            result.use_robot_attitude = parseBool(value, where);
        } else if (key == "velocity_source") {
            try {
                result.velocity_source = velocitySourceFromString(value);
            } catch (const std::exception& e) {
                throw travel::ConfigError(where + ": " + e.what());
            }
        } else if (key == "max_motion_age") {
            result.max_motion_age = parseNumber(value, where);
        } else {
            throw travel::ConfigError(source + ": unknown key '" + key +
                                      "' (neither a libtravel parameter nor a filter key)");
        }
    }
    try {
        result.params.validate();
        result.validate();
    } catch (const std::exception& e) {
        throw travel::ConfigError(source + ": " + e.what());
    }
    options = std::move(result);
}

/// A YAML scalar as text, whatever type it holds (parsed files hold strings; maps built in
/// code may hold numbers or booleans).
std::string scalarText(const mrpt::containers::yaml::node_t& node, const std::string& where) {
    if (!node.isScalar())
        throw travel::ConfigError(where + ": expected a scalar value, got " + node.typeName());
    const std::any& any = node.asScalar();
    if (const auto* s = std::any_cast<std::string>(&any)) return *s;
    if (const auto* b = std::any_cast<bool>(&any)) return *b ? "true" : "false";
    if (const auto* d = std::any_cast<double>(&any)) return exactText(*d);
    if (const auto* f = std::any_cast<float>(&any)) return exactText(*f);
    if (const auto* i = std::any_cast<int>(&any)) return std::to_string(*i);
    if (const auto* i = std::any_cast<int64_t>(&any)) return std::to_string(*i);
    if (const auto* u = std::any_cast<uint64_t>(&any)) return std::to_string(*u);
    if (const auto* u = std::any_cast<unsigned>(&any)) return std::to_string(*u);
    return node.as<std::string>();
}

std::string extensionOf(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return lower(path.substr(dot + 1));
}

}  // namespace

const char* toString(VelocitySource source) {
    switch (source) {
        case VelocitySource::Auto:
            return "auto";
        case VelocitySource::Imu:
            return "imu";
        case VelocitySource::Poses:
            return "poses";
        case VelocitySource::None:
            return "none";
    }
    return "?";
}

VelocitySource velocitySourceFromString(const std::string& text) {
    for (VelocitySource s :
         {VelocitySource::Auto, VelocitySource::Imu, VelocitySource::Poses, VelocitySource::None})
        if (text == toString(s)) return s;
    throw travel::ConfigError("velocity_source must be one of auto|imu|poses|none, got '" + text +
                              "'");
}

const char* const* TravelFilterOptions::filterKeys(std::size_t& count) {
    count = std::size(kFilterKeys);
    return kFilterKeys;
}

void TravelFilterOptions::validate() const {
    try {
        std::regex probe(sensor_label, std::regex::ECMAScript);
    } catch (const std::regex_error& e) {
        throw travel::ConfigError("sensor_label: invalid regular expression '" + sensor_label +
                                  "': " + e.what());
    }
    if (!(max_motion_age > 0) || !std::isfinite(max_motion_age))
        throw travel::ConfigError("max_motion_age must be a finite number > 0 (seconds)");
}

void TravelFilterOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                             const std::string& section) {
    std::vector<std::string> keys;
    source.getAllKeys(section, keys);
    KeyValues assignments;
    for (const std::string& key : keys)
        assignments.emplace_back(key, source.read_string(section, key, "", true));
    applyAssignments(assignments, "section [" + section + "]", *this);
}

void TravelFilterOptions::saveToConfigFile(mrpt::config::CConfigFileBase& target,
                                           const std::string& section) const {
    travel::visitParams(params, [&](const char* name, const auto& value, auto&&...) {
        target.write(section, name, valueText(value));
    });
    target.write(section, "sensor_label", sensor_label);
    target.write(section, "use_sensor_pose", valueText(use_sensor_pose));
    target.write(section, "use_robot_attitude", valueText(use_robot_attitude));
    target.write(section, "velocity_source", std::string(toString(velocity_source)));
    target.write(section, "max_motion_age", exactText(max_motion_age));
}

void TravelFilterOptions::loadFromYaml(const mrpt::containers::yaml& cfg) {
    if (cfg.isNullNode() || (cfg.isMap() && cfg.asMap().empty())) {
        applyAssignments({}, "YAML", *this);
        return;
    }
    if (!cfg.isMap()) throw travel::ConfigError("YAML: expected a map of key: value");
    const mrpt::containers::yaml::map_t* map = &cfg.asMap();
    std::string source = "YAML";
    // Optional `travel:` wrapper, as in libtravel's own files.
    if (map->size() == 1 && map->begin()->first.as<std::string>() == "travel" &&
        map->begin()->second.isMap()) {
        map = &map->begin()->second.asMap();
        source = "YAML section 'travel'";
    }
    KeyValues assignments;
    for (const auto& [key_node, value_node] : *map) {
        const std::string key = key_node.as<std::string>();
        assignments.emplace_back(key, scalarText(value_node, source + ": " + key));
    }
    applyAssignments(assignments, source, *this);
}

void TravelFilterOptions::loadFromFile(const std::string& path) {
    const std::string ext = extensionOf(path);
    try {
        if (!std::ifstream(path)) throw travel::ConfigError("cannot open the file");
        if (ext == "yaml" || ext == "yml") {
            loadFromYaml(mrpt::containers::yaml::FromFile(path));
        } else if (ext == "ini" || ext == "cfg") {
            mrpt::config::CConfigFile file(path);
            if (!file.sectionExists("travel")) throw travel::ConfigError("no [travel] section");
            loadFromConfigFile(file, "travel");
        } else {
            throw travel::ConfigError(
                "unknown extension: expected .yaml/.yml (YAML) or .ini/.cfg (section [travel])");
        }
    } catch (const std::exception& e) {
        throw travel::ConfigError(path + ": " + e.what());
    }
}

}  // namespace travel_mrpt
