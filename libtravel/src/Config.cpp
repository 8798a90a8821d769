// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/Config.hpp"

#include <cmath>
#include <regex>

#include "travel/ConfigFields.hpp"
#include "travel/EnumNames.hpp"
#include "travel/Errors.hpp"

namespace travel {
namespace {

constexpr EnumName<VelocitySource> kVelocitySourceNames[] = {{VelocitySource::Auto, "auto"},
                                                             {VelocitySource::Imu, "imu"},
                                                             {VelocitySource::Poses, "poses"},
                                                             {VelocitySource::None, "none"}};

void require(bool ok, const std::string& what) {
    if (!ok) throw ConfigError(what);
}

}  // namespace

const char* toString(VelocitySource source) {
    return nameOf(kVelocitySourceNames, source);
}

VelocitySource velocitySourceFromString(const std::string& text) {
    return valueFromName<ConfigError>(kVelocitySourceNames, text, "velocity_source");
}

void FilterSection::validate() const {
    checkRanges(*this);
    try {
        std::regex probe(sensor_label, std::regex::ECMAScript);
    } catch (const std::regex_error& e) {
        throw ConfigError("sensor_label: invalid regular expression '" + sensor_label +
                          "': " + e.what());
    }
    require(max_motion_age > 0, "max_motion_age must be a finite number > 0 (seconds)");
}

namespace {

// The strict and cross-key rules of each part of the map section (ranges are checked first).
void geometryRules(const GridGeometry& g) {
    require(g.min_x < g.max_x, "min_x/max_x: need min_x < max_x [m]");
    require(g.min_y < g.max_y, "min_y/max_y: need min_y < max_y [m]");
    require(
        (g.max_x - g.min_x) / g.resolution <= 16384 && (g.max_y - g.min_y) / g.resolution <= 16384,
        "resolution: the grid would exceed 16384 x 16384 cells (enlarge the resolution or "
        "shrink the extent)");
}

void fusionRules(const GridFusionParams& f) {
    require(f.logodds_obstacle > 0, "logodds_obstacle: must be > 0");
    require(f.logodds_ground < 0, "logodds_ground: must be < 0");
    require(f.logodds_min < 0, "logodds_min: must be < 0");
    require(f.logodds_max > 0, "logodds_max: must be > 0");
    require(f.obstacle_threshold < f.logodds_max,
            "obstacle_threshold/logodds_max: obstacle_threshold must be in [0, logodds_max)");
    require(f.free_threshold > f.logodds_min,
            "free_threshold/logodds_min: free_threshold must be in (logodds_min, 0]");
    require(f.max_step_height > 0, "max_step_height: must be > 0 [m]");
    require(f.max_traversable_slope_deg > 0 && f.max_traversable_slope_deg < 90,
            "max_traversable_slope_deg: must be in (0, 90) [deg]");
}

}  // namespace

int GridGeometry::sizeX() const {
    return static_cast<int>(std::ceil((max_x - min_x) / resolution - 1e-9));
}

int GridGeometry::sizeY() const {
    return static_cast<int>(std::ceil((max_y - min_y) / resolution - 1e-9));
}

void GridGeometry::validate() const {
    checkRanges(*this);
    geometryRules(*this);
}

void GridFusionParams::validate() const {
    checkRanges(*this);
    fusionRules(*this);
}

void MapSection::validate() const {
    checkRanges(*this);
    geometryRules(*this);
    require(octomap_prob_hit > 0.5 && octomap_prob_hit < 1,
            "octomap_prob_hit: must be in (0.5, 1)");
    require(octomap_prob_miss > 0 && octomap_prob_miss < 0.5,
            "octomap_prob_miss: must be in (0, 0.5)");
    require(max_ray_length > 0, "max_ray_length: must be > 0 [m]");
    // OctoMap keys are 16-bit: a ray longer than 32768 voxels would wrap.
    require(max_ray_length / octomap_resolution < 30000,
            "max_ray_length/octomap_resolution: a ray longer than 30000 voxels");
    require(obstacle_max_height > obstacle_min_height,
            "obstacle_max_height/obstacle_min_height: need obstacle_max_height > "
            "obstacle_min_height [m]");
    fusionRules(*this);
}

void NavSection::validate() const {
    checkRanges(*this);
    require(max_height > 0, "max_height: must be > 0 [m]");
}

void RegressSection::validate() const {
    checkRanges(*this);
}

void TrackingParams::validate() const {
    checkRanges(*this);
    require(moving_speed_off < moving_speed_on,
            "moving_speed_off/moving_speed_on: need moving_speed_off < moving_speed_on [m/s] "
            "(hysteresis)");
}

void Config::validate() const {
    visitSections(*this, [](const auto& section) {
        try {
            section.validate();
        } catch (const ConfigError& e) {
            throw ConfigError("section '" + std::string(sectionName(section)) + "': " + e.what());
        }
    });
}

}  // namespace travel
