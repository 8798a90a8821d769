// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TraversabilityMapOptions.hpp"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>

#include "ConfigText.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace travel_mrpt {
namespace {
using config_text::exactText;
using config_text::parseNumber;

/// One map key: its name, whether it must be an integer, and how to set / get it.
struct Key {
    const char* name;
    bool integer;
    std::function<void(TraversabilityMapOptions&, double)> set;
    std::function<double(const TraversabilityMapOptions&)> get;
};

#define TRAVEL_MAP_KEY(NAME, MEMBER, INTEGER, TYPE)                                       \
    Key {                                                                                 \
        NAME, INTEGER, [](TraversabilityMapOptions& o, double v) { o.MEMBER = TYPE(v); }, \
            [](const TraversabilityMapOptions& o) { return double(o.MEMBER); }            \
    }

const std::vector<Key>& keys() {
    static const std::vector<Key> list = {
        TRAVEL_MAP_KEY("min_x", geometry.min_x, false, double),
        TRAVEL_MAP_KEY("max_x", geometry.max_x, false, double),
        TRAVEL_MAP_KEY("min_y", geometry.min_y, false, double),
        TRAVEL_MAP_KEY("max_y", geometry.max_y, false, double),
        TRAVEL_MAP_KEY("resolution", geometry.resolution, false, double),
        TRAVEL_MAP_KEY("octomap_resolution", octomap_resolution, false, double),
        TRAVEL_MAP_KEY("octomap_prob_hit", octomap_prob_hit, false, double),
        TRAVEL_MAP_KEY("octomap_prob_miss", octomap_prob_miss, false, double),
        TRAVEL_MAP_KEY("max_ray_length", max_ray_length, false, double),
        TRAVEL_MAP_KEY("ray_stride", ray_stride, true, int),
        TRAVEL_MAP_KEY("obstacle_min_height", obstacle_min_height, false, double),
        TRAVEL_MAP_KEY("obstacle_max_height", obstacle_max_height, false, double),
        TRAVEL_MAP_KEY("logodds_obstacle", fusion.logodds_obstacle, false, float),
        TRAVEL_MAP_KEY("logodds_ground", fusion.logodds_ground, false, float),
        TRAVEL_MAP_KEY("logodds_min", fusion.logodds_min, false, float),
        TRAVEL_MAP_KEY("logodds_max", fusion.logodds_max, false, float),
        TRAVEL_MAP_KEY("obstacle_threshold", fusion.obstacle_threshold, false, float),
        TRAVEL_MAP_KEY("free_threshold", fusion.free_threshold, false, float),
        TRAVEL_MAP_KEY("min_obstacle_points", fusion.min_obstacle_points, true, int),
        TRAVEL_MAP_KEY("min_step_points", fusion.min_step_points, true, int),
        TRAVEL_MAP_KEY("max_step_height", fusion.max_step_height, false, float),
        TRAVEL_MAP_KEY("max_neighbour_step", fusion.max_neighbour_step, false, float),
        TRAVEL_MAP_KEY("max_slope_deg", fusion.max_slope_deg, false, float),
    };
    return list;
}
#undef TRAVEL_MAP_KEY

const Key* findKey(const std::string& name) {
    for (const Key& k : keys())
        if (name == k.name) return &k;
    return nullptr;
}

bool isTravelKey(const std::string& name) {
    std::size_t n = 0;
    const char* const* filter_keys = TravelFilterOptions::filterKeys(n);
    for (std::size_t i = 0; i < n; ++i)
        if (name == filter_keys[i]) return true;
    bool found = false;
    travel::Params probe;
    travel::visitParams(probe,
                        [&](const char* param, auto&&...) { found = found || name == param; });
    return found;
}

void require(bool ok, const std::string& what) {
    if (!ok) throw travel::ConfigError(what);
}

}  // namespace

const std::vector<std::string>& TraversabilityMapOptions::mapKeys() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const Key& k : keys()) v.emplace_back(k.name);
        return v;
    }();
    return names;
}

void TraversabilityMapOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                  const std::string& section) {
    const std::string where = "section [" + section + "]";
    std::vector<std::string> names;
    source.getAllKeys(section, names);
    TraversabilityMapOptions result = *this;
    std::string travel_ini = "[travel]\n";
    for (const std::string& name : names) {
        const std::string value = source.read_string(section, name, "", true);
        if (const Key* key = findKey(name)) {
            const double v = parseNumber(value, where + ": " + name);
            if (key->integer && v != std::floor(v))
                throw travel::ConfigError(where + ": " + name + ": expected an integer, got '" +
                                          value + "'");
            key->set(result, v);
        } else if (isTravelKey(name)) {
            travel_ini += name + "=" + value + "\n";
        } else {
            throw travel::ConfigError(where + ": unknown key '" + name +
                                      "' (neither a traversability-map key, a TRAVEL filter key "
                                      "nor a libtravel parameter)");
        }
    }
    // The TRAVEL keys go through the filter's own loader (preset first, range checks).
    mrpt::config::CConfigFileMemory travel_source(travel_ini);
    try {
        result.travel.loadFromConfigFile(travel_source, "travel");
        result.validate();
    } catch (const travel::ConfigError& e) {
        throw travel::ConfigError(where + ": " + e.what());
    }
    *this = std::move(result);
}

void TraversabilityMapOptions::saveToConfigFile(mrpt::config::CConfigFileBase& target,
                                                const std::string& section) const {
    // TRAVEL first, then the map's keys: a name both use (max_slope_deg) is the map's when read
    // back, as loadFromConfigFile gives such a key to the map only (before this order, the map's
    // max_slope_deg came back as libtravel's, and a serialized map changed its cell states).
    travel.saveToConfigFile(target, section);
    for (const Key& k : keys()) {
        const double v = k.get(*this);
        target.write(section, k.name, k.integer ? std::to_string(long(v)) : exactText(v));
    }
}

void TraversabilityMapOptions::validate() const {
    geometry.validate();
    fusion.validate();
    require(std::isfinite(octomap_resolution) && octomap_resolution >= 0.01,
            "octomap_resolution: must be >= 0.01 [m]");
    require(octomap_prob_hit > 0.5 && octomap_prob_hit < 1,
            "octomap_prob_hit: must be in (0.5, 1)");
    require(octomap_prob_miss > 0 && octomap_prob_miss < 0.5,
            "octomap_prob_miss: must be in (0, 0.5)");
    require(std::isfinite(max_ray_length) && max_ray_length > 0, "max_ray_length: must be > 0 [m]");
    // OctoMap keys are 16-bit: a ray longer than 32768 voxels would wrap.
    require(max_ray_length / octomap_resolution < 30000,
            "max_ray_length: longer than 30000 voxels of octomap_resolution");
    require(ray_stride >= 1, "ray_stride: must be >= 1");
    require(std::isfinite(obstacle_min_height) && obstacle_min_height >= 0,
            "obstacle_min_height: must be >= 0 [m]");
    require(std::isfinite(obstacle_max_height) && obstacle_max_height > obstacle_min_height,
            "obstacle_max_height: must be > obstacle_min_height [m]");
    travel.params.validate();
    travel.validate();
}

}  // namespace travel_mrpt
