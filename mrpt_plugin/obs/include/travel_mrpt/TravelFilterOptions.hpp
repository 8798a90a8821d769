// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Options of travel_mrpt::TravelFilter: every libtravel parameter (travel::Params, same names)
// plus the filter's own keys. Loaded from an ini section (CLoadableOptions), a YAML map
// (mrpt::containers::yaml) or a file chosen by extension, always with the same rules:
//   1. `preset: NAME` (optional) first: travel::loadPreset(NAME);
//   2. every libtravel key, through travel::applyOverride (so libtravel checks ranges/choices);
//   3. the filter keys below;
//   4. an unknown key is an error naming the key and the section; then Params::validate().
// Errors are travel::ConfigError (a std::runtime_error).
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>

#include "travel/Params.hpp"

namespace mrpt::containers {
class yaml;
}

namespace travel_mrpt {

/// Where the sensor velocity used for deskew comes from.
enum class VelocitySource {
    Auto,   ///< IMU gyro, else odometry/pose differences; odometry velocity, else pose differences
    Imu,    ///< measured rates only: IMU gyro + odometry (wheel) velocities, no pose differences
    Poses,  ///< differences of consecutive robot poses (setRobotPose, odometry poses)
    None,   ///< no velocity: no deskew
};

const char* toString(VelocitySource source);
/// "auto|imu|poses|none" (exact); throws travel::ConfigError naming the allowed values.
VelocitySource velocitySourceFromString(const std::string& text);

struct TravelFilterOptions : public mrpt::config::CLoadableOptions {
    travel::Params params;  ///< libtravel parameters (deskew is params.deskew)

    /// ECMAScript regex; only observations whose sensorLabel matches it entirely are processed.
    std::string sensor_label = ".*";
    /// Mount angles (params.mount_*_deg) from each observation's sensorPose.
    bool use_sensor_pose = true;
    /// Level each frame with the robot's roll/pitch (IMU or robot pose) when known.
    bool use_robot_attitude = true;
    VelocitySource velocity_source = VelocitySource::Auto;
    /// Motion data older than this (before the LiDAR frame) is not used [s].
    double max_motion_age = 0.5;

    /// Names of the filter's own keys (not libtravel parameters), plus "preset".
    static const char* const* filterKeys(std::size_t& count);

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                            const std::string& section) override;
    /// Writes every key (libtravel parameters then filter keys), doubles exactly.
    void saveToConfigFile(mrpt::config::CConfigFileBase& target,
                          const std::string& section) const override;

    /// Same keys and rules from a YAML map (keys at the root, or under a `travel:` map).
    void loadFromYaml(const mrpt::containers::yaml& cfg);
    /// .yaml/.yml -> YAML; .ini/.cfg -> ini section [travel]. Errors name the file.
    void loadFromFile(const std::string& path);

    /// Throws travel::ConfigError if a filter key is invalid (bad regex, negative age...).
    void validate() const;
};

}  // namespace travel_mrpt
