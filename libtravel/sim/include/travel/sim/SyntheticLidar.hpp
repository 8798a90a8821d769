// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A spinning multi-beam LiDAR ray-cast over a Scene, with exact per-point ground truth.
//
//   Scene world = flatGround();
//   Scan s = scan(world, LidarModel::vlp16(), sensorPoseAt(world, 0, 0, 1.73, 0, 0, 0));
//   // s.cloud is in the sensor frame; s.gt.cls[i], s.gt.instance[i] describe point i.
#pragma once

#include "travel/PointCloud.hpp"
#include "travel/sim/Scene.hpp"

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace travel::sim {

/// Order of the points in the output cloud.
enum class PointOrder {
    ColumnMajor,  ///< firing order: for each column (azimuth), every ring from 0 up
    RingMajor,    ///< like KITTI .bin files: for each ring from 0 up, a full revolution
};

/// Sensor intrinsics. Sensor frame: x forward, y left, z up. Column c fires at azimuth
/// 2 pi c / columns (0 = +x, counter-clockwise) and at time c / columns * sweep_period.
struct LidarModel {
    /// Beam elevations [deg], any order. A beam's ring is its rank by ascending elevation.
    std::vector<double> elevations_deg;
    int columns = 1800;              ///< azimuth steps per revolution
    double min_range = 0.5;          ///< [m] closer hits are no-returns
    double max_range = 120.0;        ///< [m]
    double range_noise_sigma = 0.0;  ///< [m] Gaussian noise along the ray
    double sweep_period = 0.1;       ///< [s] one revolution
    bool emit_no_returns = false;    ///< true: rays without a hit give (0,0,0), NoReturn
    PointOrder order = PointOrder::RingMajor;
    uint32_t seed = 1;  ///< std::mt19937 seed of the range noise
    /// true: column c fires at azimuth -2 pi c / columns (clockwise seen from above, like a
    /// Velodyne); false (default): counter-clockwise as documented above.
    bool clockwise = false;

    std::size_t numBeams() const { return elevations_deg.size(); }
    /// Elevations [deg] indexed by ring (ascending).
    std::vector<double> elevationsByRing() const;
    /// Throws std::invalid_argument on an empty beam table, columns < 1, bad ranges, etc.
    void validate() const;

    /// Velodyne HDL-64E: two linear blocks, +2.0..-8.33 deg and -8.83..-24.33 deg, 32 beams each.
    static LidarModel hdl64(int columns = 2083);
    /// Velodyne HDL-32E: 32 beams uniform in [-30.67, +10.67] deg.
    static LidarModel hdl32(int columns = 1084);
    /// Velodyne VLP-16: 16 beams, -15..+15 deg in 2 deg steps.
    static LidarModel vlp16(int columns = 1800);
    /// Ouster OS1-128: 128 beams uniform in [-22.5, +22.5] deg.
    static LidarModel os128(int columns = 1024);
    /// n_beams uniform in [lo_deg, hi_deg] (a single beam sits at lo_deg).
    static LidarModel uniform(int n_beams, double lo_deg, double hi_deg, int columns);
};

/// Ground-truth class of a simulated point. Same numbers as travel::PointClass.
enum GtClass : uint8_t {
    NoReturn = 0,   ///< the ray hit nothing within [min_range, max_range]; point is (0,0,0)
    Ground = 1,     ///< terrain (vertical kerb/step faces included) no steeper than the limit
    NonGround = 2,  ///< an object (instance = its id), or too-steep terrain (instance 0)
    /// A ray mirrored by a puddle's water (Scene::puddles): reported below the water, where
    /// no surface is (SemanticKITTI: outlier; not ground, nor an object)
    Reflection = 3,
};

/// Per-point ground truth, parallel to the cloud.
struct GroundTruth {
    std::vector<uint8_t> cls;        ///< GtClass
    std::vector<uint32_t> instance;  ///< object id, 0 for terrain and no-returns
    /// Noise-free hit z minus terrain height at the hit's xy [m]; NaN for no-returns.
    /// A hit on a vertical face is placed on its lower side, so this is in [0, face height].
    std::vector<float> height_above_ground;

    std::size_t size() const { return cls.size(); }
    void clear() { cls.clear(), instance.clear(), height_above_ground.clear(); }
};

struct Scan {
    travel::PointCloud cloud;  ///< sensor frame, with ring and time
    GroundTruth gt;
};

/// Ray-casts one revolution. Throws std::invalid_argument on an invalid model or scene.
Scan scan(const Scene& scene, const LidarModel& model,
          const Eigen::Isometry3d& sensor_pose_in_world);

/// Same, reusing the buffers of `out`.
void scan(const Scene& scene, const LidarModel& model,
          const Eigen::Isometry3d& sensor_pose_in_world, Scan& out);

/// One revolution during which the sensor moves: column c is fired from column_poses[c], the
/// sensor pose in the world at that column's time (c / columns * sweep_period). Each point is
/// in the sensor frame of its own column, as a real spinning LiDAR reports it (the skew that
/// deskewing undoes). Throws std::invalid_argument unless column_poses.size() == columns.
void scanMoving(const Scene& scene, const LidarModel& model,
                const std::vector<Eigen::Isometry3d>& column_poses, Scan& out);

}  // namespace travel::sim
