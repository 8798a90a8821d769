// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One closed-loop run of travel-nav-sim: MRPT's CVehicleSimul_DiffDriven drives in x, y, yaw;
// the robot's z, roll and pitch come from the terrain under its footprint (a least-squares
// plane through the terrain heights at the footprint's corners and centre). Each step (dt):
// ray-cast a scan from the LiDAR's true 3-D pose, run TRAVEL through travel_mrpt::TravelFilter
// (levelled with the robot's attitude, as an IMU would give it), update the obstacle source with
// the filter's frame, run one step of
// CReactiveNavigationSystem3D, advance the simulator, check the footprint against the world's
// obstacles. A run ends on: the goal reached (within goal_tolerance), a collision (footprint
// overlapping an obstacle), the navigator giving up (NAV_ERROR: target blocked, not
// approaching it), or the timeout (simulated seconds).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include <memory>
#include "Progress.hpp"
#include "nav/World.hpp"

#include "travel/Config.hpp"
#include "travel/Params.hpp"
#include "travel/sim/SyntheticLidar.hpp"
#include "travel_mrpt/ObstacleSource.hpp"
#include "travel_mrpt/TravelMapNavigation.hpp"
#include "travel_mrpt/TravelObstacleSource.hpp"

namespace travel_mrpt {
class TravelFilter;
struct TravelFrame;
}  // namespace travel_mrpt

namespace travel::navsim {

enum class SourceKind { Travel, Raw, Threshold, Map };
const char* toString(SourceKind kind);
/// -s/--source: "travel", "raw", "threshold", "map", or "all" (the per-frame sources travel, raw
/// and threshold); throws std::invalid_argument listing every valid name otherwise.
std::vector<SourceKind> parseSources(const std::string& name);

enum class Outcome { Goal, Collision, NavigatorGaveUp, Timeout };
const char* toString(Outcome outcome);

struct SimOptions {
    std::string nav_config_file;  ///< reactive navigator .ini (share/configs/nav/...)
    SourceKind source = SourceKind::Travel;
    double dt = 0.1;              ///< [s] one LiDAR sweep and one navigation step
    double timeout = 60.0;        ///< [s] simulated time
    double goal_tolerance = 0.4;  ///< [m] targetAllowedDistance of the navigation request
    double sensor_height = 0.8;   ///< [m] LiDAR origin above the robot base, on its z axis
    /// A 32-beam dome-like LiDAR (-45..+15 deg), 720 columns, 20 m: cheap and it sees the
    /// ground from 0.8 m around the robot.
    sim::LidarModel lidar = defaultLidar();
    travel::Params travel;  ///< set by defaultTravelParams() unless overridden
    /// The obstacle source's keys; here with 1 s of memory within 1 m (defaultNav()).
    travel::NavSection nav = defaultNav();
    double raw_min_z = 0.03;        ///< [m] raw source: noise margin above the robot's base
    double threshold_min_z = 0.25;  ///< [m] height-threshold source
    std::string navlog_file;        ///< write the navigator's .reactivenavlog here (empty: no)
    /// Map source: plan a global path on the map and follow it as waypoints (else the goal is
    /// the navigator's only target, as with the other sources).
    bool plan = true;
    /// Track the clusters (TravelFilter's track_objects, with object clustering on): objects
    /// the tracker flags moving are handed to the navigator along their predicted path over
    /// nav.predict_seconds and kept out of the memory and the map (travel and map sources).
    bool track = false;
    travel::TrackingParams tracking;  ///< the tracker's parameters when `track`
    double map_resolution = 0.1;      ///< [m] map source: grid cell size (extent: the world's)
    /// Map source: save the map here on exit (CTraversabilityMap exports; empty: no).
    std::string map_prefix;
    /// Console: MRPT's navigator messages (travel::apps::configureMrptLogging) and the progress
    /// line (simulated time). Quiet by default (tests, library use).
    travel::apps::Verbosity verbosity = travel::apps::Verbosity::Quiet;

    static sim::LidarModel defaultLidar();
    static travel::NavSection defaultNav() {
        travel::NavSection nav;
        nav.memory_seconds = 1.0, nav.memory_radius = 1.0;
        return nav;
    }
    /// TRAVEL for this robot and LiDAR: sensor_height, ranges, 1 m cells, rings from the
    /// elevation table, no object clustering (the navigator needs points, not clusters).
    static travel::Params defaultTravelParams(const sim::LidarModel& lidar, double sensor_height);
    SimOptions() : travel(defaultTravelParams(lidar, sensor_height)) {}
};

struct TrajectorySample {
    double t = 0, x = 0, y = 0, z = 0, yaw = 0, roll = 0, pitch = 0;  ///< [s], [m], [rad]
    double v = 0, w = 0;           ///< commanded-and-simulated speeds [m/s], [rad/s]
    double clearance = 0;          ///< [m] footprint to the nearest obstacle
    double mover_clearance = 1e9;  ///< [m] footprint to the nearest mover (1e9: none)
    std::size_t obstacles = 0;     ///< points the source handed to the navigator
};

struct RunReport {
    Outcome outcome = Outcome::Timeout;
    std::string detail;  ///< what was hit, why the navigator gave up
    double time = 0, path_length = 0;
    double min_clearance = 1e9;        ///< [m] over the run
    std::string min_clearance_to;      ///< the obstacle nearest then ("kerb 1", ...)
    double min_mover_clearance = 1e9;  ///< [m] to the world's movers over the run (1e9: none)
    double final_goal_distance = 0;
    double max_height_gain = 0;  ///< [m] highest terrain z reached minus the start's
    double mean_step_ms = 0;     ///< wall time per step (scan + TRAVEL + navigation)
    std::vector<TrajectorySample> trajectory;

    // Map source only.
    double median_map_ms = 0;      ///< map update + sensing per step (wall, median)
    double median_map_cpu_ms = 0;  ///< the same in thread CPU time (less sensitive to load)
    double median_fusion_ms = 0;   ///< of which the map fusion (grid + OctoMap), wall, median
    double max_map_ms = 0;
    double mean_plan_ms = 0;  ///< planner per step (grid check, re-planning when blocked)
    std::vector<std::vector<Eigen::Vector2d>> planned_paths;  ///< every plan, in order
    /// The map at the end: geometry and, per cell, 0 unknown, 1 traversable, 2 obstacle.
    double map_min_x = 0, map_min_y = 0, map_resolution = 0;
    int map_size_x = 0, map_size_y = 0;
    std::vector<uint8_t> map_cells;
};

/// Robot base pose on the terrain (travel/sim/Scene.hpp).
using sim::robotAttitudeOnTerrain;

/// The robot's footprint from the navigator config (LEVEL1_VECTORX/Y of
/// [CReactiveNavigationSystem3D]); throws std::runtime_error naming the file.
std::vector<Eigen::Vector2d> footprintFromConfig(const std::string& nav_config_file);

/// TRAVEL in the simulator, run as every MRPT user runs it: through travel_mrpt::TravelFilter,
/// fed with the simulated scan and the robot's true pose (whose roll and pitch level the frame,
/// as an IMU would). Simulated scans are instantaneous: no deskew.
class SimTravel {
  public:
    /// Throws travel::ConfigError on invalid parameters.
    /// `track`: TravelFilter's track_objects with the `tracking` parameters (object clustering
    /// is then switched on: the tracker follows clusters).
    explicit SimTravel(const travel::Params& params, bool track = false,
                       const travel::TrackingParams& tracking = {});
    ~SimTravel();
    /// Segments `cloud`, seen at time t by the sensor at `mount` on the robot at world pose
    /// `robot`; fills frame.cloud, frame.result and frame.aligned (valid until the next call).
    void process(const travel::PointCloud& cloud, const Eigen::Isometry3d& robot,
                 const Eigen::Isometry3d& mount, double t, travel_mrpt::ObstacleFrame& frame);

  private:
    std::unique_ptr<travel_mrpt::TravelFilter> filter_;
    std::unique_ptr<travel_mrpt::TravelFrame> frame_;
};

/// The map source's chain options for `world`: TRAVEL as the other sources run it, a grid over
/// the world's extent (+1 m) at map_resolution, TRAVEL's obstacle rule with options.nav (the
/// map is the memory: no memory_seconds).
travel_mrpt::TravelMapNavigationOptions mapChainOptions(const World& world,
                                                        const SimOptions& options);

/// Runs one closed loop. Throws std::runtime_error on configuration errors.
RunReport runSimulation(const World& world, const SimOptions& options);

/// Writes the trajectory CSV (t,x,y,z,yaw_deg,roll_deg,pitch_deg,v,w,clearance,obstacles and,
/// when the world has movers, mover_clearance).
void writeTrajectoryCsv(const RunReport& report, const std::string& path);

}  // namespace travel::navsim
