// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The sensor's mount from the ground it sees: a robust plane fit of one frame gives the height of
// the sensor origin above the ground (sensor_height) and the roll/pitch that make the ground
// level (mount_roll_deg, mount_pitch_deg). Used by the Pipeline for `auto` values and to check
// configured ones (MountNote).
//
// Fit (deterministic): the lowest point of each polar bin around the sensor (2 deg x 1 m, up to
// 40 m) is a ground candidate (the foot of a wall or a car is ground, its top is not); RANSAC
// with a fixed seed picks the plane through 3 candidates, within 30 deg of the prior up
// direction and below the sensor (or less than kBaseFrameMaxHeight above its origin: a base
// frame, which the check reports), that holds the most candidates within 0.1 m; then two
// least-squares (PCA) refits on ALL points within 0.1 m, then 0.06 m, of the plane remove the
// downward bias of taking minima (about 1-2 sigma of the range noise).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"

namespace travel {

struct GroundPlaneEstimate {
    bool found = false;
    /// Unit normal of the ground plane in the sensor frame, pointing to the sensor's side.
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    /// Distance of the sensor origin above the plane [m]; down to -kBaseFrameMaxHeight (the
    /// origin of a base frame, just under its ground).
    double height = 0.0;
    double roll_deg = 0.0;   ///< mount roll that makes the plane level (vehicle standing level)
    double pitch_deg = 0.0;  ///< mount pitch, likewise
    std::size_t num_candidates = 0;  ///< lowest points of the polar bins
    std::size_t num_inliers = 0;     ///< points on the final plane (within 0.06 m)
    std::size_t stride = 1;          ///< every stride-th point was used (estimate's `stride`)
};

class MountEstimator {
  public:
    /// Fits the ground plane of `cloud` (sensor frame). `prior_up`: the expected up direction in
    /// the sensor frame (unit; planes more than 30 deg from it are rejected). Points outside
    /// [min_range, max_range] (3-D) are not used, nor points i with excluded[i] != 0 when
    /// `excluded` is given (the own vehicle's returns: markSelfReturns). `stride` > 1 uses only
    /// the points 0, stride, 2 stride, ... (a check of configured values needs less precision
    /// than an estimate: Pipeline). found = false when fewer than 100 / stride of the used points
    /// lie on the best plane.
    GroundPlaneEstimate estimate(const PointCloud& cloud, const Eigen::Vector3d& prior_up,
                                 double min_range, double max_range,
                                 const uint8_t* excluded = nullptr, std::size_t stride = 1);
    /// Sizes (and maps) the buffers for an estimate that uses `points` points (the frame's
    /// points / stride), so the first estimate pays no page faults for them.
    void reserve(std::size_t points);

  private:
    std::vector<int32_t> bin_point_;  // lowest point of each bin, -1 = none
    std::vector<float> bin_height_;
    std::vector<Eigen::Vector3d> candidates_;
    std::vector<double> candidate_x_, candidate_y_, candidate_z_;  // candidates_ as arrays
    std::vector<int32_t> point_bin_;  // per used point: its bin, or kNoBin / kExactBin
    std::vector<int32_t> selected_;   // points within a refit's band
};

/// Roll and pitch [deg] of a mount R = Rz(yaw) Ry(pitch) Rx(roll) under which the sensor-frame
/// normal `n` points straight up (n = R^T e_z = (-sin p, sin r cos p, cos r cos p)).
void mountAnglesFromNormal(const Eigen::Vector3d& n, double& roll_deg, double& pitch_deg);

/// What the Pipeline found out about the mount on one frame (empty on most frames).
struct MountNote {
    enum class Kind : uint8_t {
        None,       ///< nothing new
        Estimated,  ///< `auto` values were estimated (and are kept from now on)
        NotFound,   ///< `auto` values could not be estimated in the first frames: fallbacks kept
        /// configured values disagree with the ground (> 0.3 m or 5 deg), or the ground lies
        /// within kBaseFrameMaxHeight of the origin (a base frame); also an estimate (as
        /// Estimated) whose check found either
        Mismatch,
    };
    Kind kind = Kind::None;
    std::size_t frame = 0;  ///< index of the frame (0 = first processed by this pipeline)
    GroundPlaneEstimate ground;
    /// One line for the user, e.g. "sensor_height auto: 2.24 m (from frame 0, 12,345 ground
    /// points)" or "sensor_height is 0.50 m but the ground is 2.24 m below the sensor: set
    /// sensor_height: 2.24 or auto". Empty when kind == None.
    std::string message;
    explicit operator bool() const { return kind != Kind::None; }
    /// Mismatch and NotFound ask the user to act; Estimated is information.
    bool isWarning() const { return kind == Kind::Mismatch || kind == Kind::NotFound; }
};

/// Where fixed mount_roll_deg / mount_pitch_deg come from, for the advice of a tilt Mismatch.
/// Empty `name` (default): the configuration ("set mount_roll_deg: R, mount_pitch_deg: P or
/// auto"). A caller that sets the angles itself names their source and its remedy (TravelFilter:
/// the observation's sensorPose), since the configured keys would then change nothing.
struct MountAnglesSource {
    std::string name;    ///< e.g. "the sensorPose of 'VELO'"
    std::string remedy;  ///< the other way out, e.g. how to ignore that source
};

/// A configured mount farther than this from the measured ground draws a MountNote::Mismatch.
constexpr double kMountHeightTolerance = 0.3;  // m
constexpr double kMountTiltToleranceDeg = 5.0;
/// A ground nearer than this below the points' origin (or above it) draws a MountNote::Mismatch
/// whatever sensor_height says: a spinning LiDAR stands higher on any vehicle, so the cloud is
/// in a base frame, and the object stage measures ranges and ring elevations from the origin
/// (docs/input-contract.md, "Coordinate frame": its clusters split).
constexpr double kBaseFrameMaxHeight = 0.2;  // m

/// The sensor_height an `auto` value takes from `ground`: its height, 0 when a base frame's
/// origin lies under its ground (the check reports the base frame).
inline double autoSensorHeight(const GroundPlaneEstimate& ground) {
    return ground.height > 0.0 ? ground.height : 0.0;
}

/// The note for the `auto` values of `configured`, estimated as `ground` on `frame`.
MountNote estimatedMountNote(const Params& configured, const GroundPlaneEstimate& ground,
                             std::size_t frame);
/// The note when no frame up to `frame` gave a ground plane: the `auto` values keep their
/// fallbacks.
MountNote notFoundMountNote(const Params& configured, std::size_t frame);
/// Kind::Mismatch when a fixed value of `configured` is farther than the tolerances from
/// `ground` (height: distance to the plane; tilt: angle between the plane's normal taken by
/// `sensor_to_aligned` and vertical), or when the ground is within kBaseFrameMaxHeight of the
/// origin, else Kind::None. `angles` names where the fixed angles
/// come from (MountAnglesSource).
MountNote checkedMountNote(const Params& configured, const GroundPlaneEstimate& ground,
                           const Eigen::Matrix3d& sensor_to_aligned, std::size_t frame,
                           const MountAnglesSource& angles = {});

/// The smallest seed_search_radius that reaches the first ground ring: a sensor at height h whose
/// lowest beam points `lowest_elevation_deg` (< 0) below the horizon sees no ground nearer than
/// h / tan(-elevation); half a cell more reaches the means of the nodes that ring crosses (their
/// points lie on the ring and up to a cell beyond it). 0 when the lowest beam does not point
/// down.
double firstGroundRingRadius(double sensor_height, double lowest_elevation_deg,
                             double tgf_resolution);

}  // namespace travel
