// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Pre-processing (paper Sec. III-A): validity, range window, attitude alignment and deskew.
// Output is a structure-of-arrays working copy in the aligned frame (origin at the sensor,
// z up against gravity, x along the vehicle heading) plus a validity flag per point.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/TerrainModel.hpp"

namespace travel {

/// Per-frame information the caller may know about the platform. Everything is optional.
struct FrameInput {
    /// Vehicle attitude: rotation from the vehicle frame to a gravity-aligned frame (only roll
    /// and pitch matter; yaw is removed). Typically from an IMU or the robot pose. Not used
    /// unless it is a rotation (finite, orthonormal within 1e-3, determinant > 0).
    std::optional<Eigen::Matrix3d> vehicle_attitude;
    /// Alternative to vehicle_attitude: the gravity direction measured in the sensor frame
    /// (e.g. an accelerometer at rest reads -gravity). Any finite length > 0; else not used.
    std::optional<Eigen::Vector3d> gravity_in_sensor;
    /// Constant velocity of the sensor during the sweep, in the sensor frame at the reference
    /// time: linear [m/s] and angular [rad/s]. Used with per-point times for deskew.
    std::optional<Eigen::Vector3d> linear_velocity;
    std::optional<Eigen::Vector3d> angular_velocity;
    /// Time [s] (same clock as PointCloud::time) to which the sweep is deskewed.
    double reference_time = 0.0;
};

/// Working buffers, reused across frames (no per-frame allocation once warmed up).
struct AlignedCloud {
    std::vector<float> x, y, z;
    std::vector<uint8_t> valid;  ///< 1 = valid point, 0 = invalid (label Invalid)
    std::size_t num_valid = 0;
    Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();  ///< applied sensor->aligned
    /// Tri-grid node of every point on `node_grid` (NodeLocator: numNodes() for invalid points
    /// and points off the grid), when preprocess() was given a grid; else empty. Computed while
    /// the point is in registers, so TriGridField::embed does not read x and y again.
    std::vector<uint32_t> node;
    TriGridGeometry node_grid;
};

/// Rotation from the sensor frame to the vehicle frame, from mount_{yaw,pitch,roll}_deg:
/// Rz(yaw) Ry(pitch) Rx(roll) (MRPT's CPose3D convention).
Eigen::Matrix3d mountRotation(const Params& params);

/// Whether `R` may be used as FrameInput::vehicle_attitude: finite, orthonormal within 1e-3,
/// determinant > 0 (not a reflection). Another matrix is ignored by alignmentRotation.
bool isUsableAttitude(const Eigen::Matrix3d& R);

/// Whether `g` may be used as FrameInput::gravity_in_sensor: finite, not zero (any length: only
/// its direction is used). Another vector is ignored by alignmentRotation.
bool isUsableGravity(const Eigen::Vector3d& g);

/// Rotation from the sensor frame to the aligned frame for this frame's parameters and input:
/// R = R_level * R_mount, where R_mount comes from mount_{roll,pitch,yaw}_deg and R_level
/// removes the vehicle's roll and pitch (or the measured gravity tilt).
Eigen::Matrix3d alignmentRotation(const Params& params, const FrameInput& input);

/// Fill 'out' from 'cloud': invalid points (non-finite, exactly zero, outside
/// [min_range, max_range] in 3-D range, inside the self_box: the own vehicle, tested in the
/// vehicle frame before deskew) are flagged and never read again; valid points are
/// deskewed (if params.deskew and times + velocity are given) then rotated. With a `grid`, also
/// out.node (locateNodes()); without, out.node is emptied.
void preprocess(const PointCloud& cloud, const Params& params, const FrameInput& input,
                AlignedCloud& out, const TriGridGeometry* grid = nullptr);

/// node[i] = the node of aligned point i on `grid` (NodeLocator), for cloud.x, y and valid.
void locateNodes(const TriGridGeometry& grid, const AlignedCloud& cloud,
                 std::vector<uint32_t>& node);

/// Whether params' self_box holds any volume (min < max on every axis): otherwise it is off.
bool hasSelfBox(const Params& params);

/// The self filter alone, as preprocess() applies it: is_self[i] = 1 where point i lies inside
/// the self_box (the own vehicle, vehicle frame), else 0; empty when the box is. For the
/// steps that read the raw cloud before preprocess() (the mount estimate).
void markSelfReturns(const PointCloud& cloud, const Params& params, std::vector<uint8_t>& is_self);

}  // namespace travel
