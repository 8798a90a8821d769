// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Every option of TRAVEL, in six named sections of one configuration (YAML `travel:`,
// `filter:`, `map:`, `nav:`, `regress:`, `tracking:`; ini [travel], [filter], [map], [nav],
// [regress], [tracking]). Each
// section is declared once, like Params: X(type, name, default, unit, min, max, description). For
// std::string and enum options the unit slot lists the allowed values ("a|b|c"; "" = any text) and
// min/max are unused; an enum's values are listed in declaration order. Each stage receives its own
// section: the ground segmentation Params, the MRPT filter FilterSection, the map MapSection,
// the obstacle sources NavSection. Reading files is travel::config's job (ConfigIO.hpp).
#pragma once

#include <string>

#include "travel/Params.hpp"

namespace travel {

/// Where the sensor velocity used for deskew comes from.
enum class VelocitySource {
    Auto,   ///< IMU gyro, else odometry/pose differences; odometry velocity, else pose differences
    Imu,    ///< measured rates only: IMU gyro + odometry (wheel) velocities, no pose differences
    Poses,  ///< differences of consecutive robot poses (setRobotPose, odometry poses)
    None,   ///< no velocity: no deskew
};
const char* toString(VelocitySource source);
/// "auto|imu|poses|none" (exact); throws ConfigError naming the allowed values.
VelocitySource velocitySourceFromString(const std::string& text);

// The MRPT observation filter (travel_mrpt::TravelFilter), besides the Params it runs with.
#define TRAVEL_FILTER_LIST(X)                                                                     \
    X(std::string, sensor_label, ".*", "", 0, 0,                                                  \
      "ECMAScript regex; only observations whose sensorLabel matches it entirely are processed")  \
    X(bool, use_sensor_pose, true, "", 0, 1,                                                      \
      "Take the mount angles (travel.mount_*_deg) from each observation's sensorPose")            \
    X(bool, use_robot_attitude, true, "", 0, 1,                                                   \
      "Level each frame with the robot's roll/pitch (IMU or robot pose) when known")              \
    X(VelocitySource, velocity_source, VelocitySource::Auto, "auto|imu|poses|none", 0, 0,         \
      "Where the deskew velocity comes from: auto = IMU gyro, else odometry / pose differences; " \
      "imu = measured rates only; poses = pose differences; none = no deskew")                    \
    X(double, max_motion_age, 0.5, "s", 0.0, 1e6,                                                 \
      "Motion data older than this (before the LiDAR frame) is not used (must be > 0)")           \
    X(bool, track_objects, false, "", 0, 1,                                                       \
      "Track the clusters across frames (travel::Tracker, section tracking): track ids, "         \
      "velocities, moving flags; ego-motion from the robot poses / odometry, else from "          \
      "registering consecutive scans")

// The traversability map (travel_mrpt::CTraversabilityMap), in three parts so that each stage
// takes its own: the grid extent (GridGeometry), the OctoMap and obstacle heights (the map
// itself), the fusion rules (GridFusionParams, for travel::TraversabilityGrid).
#define TRAVEL_MAP_GRID_LIST(X)                                                     \
    X(double, min_x, -20.0, "m", -1e6, 1e6, "Grid extent, world frame: smallest x") \
    X(double, max_x, 20.0, "m", -1e6, 1e6, "Grid extent: largest x")                \
    X(double, min_y, -20.0, "m", -1e6, 1e6, "Grid extent: smallest y")              \
    X(double, max_y, 20.0, "m", -1e6, 1e6, "Grid extent: largest y")                \
    X(double, resolution, 0.2, "m", 1e-6, 1e4, "Side of a grid cell")

#define TRAVEL_MAP_OCTOMAP_LIST(X)                                                           \
    X(double, octomap_resolution, 0.2, "m", 0.01, 1e4, "Side of an OctoMap voxel")           \
    X(double, octomap_prob_hit, 0.7, "", 0.5, 1.0,                                           \
      "OctoMap sensor model: occupancy probability of a hit (in (0.5, 1))")                  \
    X(double, octomap_prob_miss, 0.4, "", 0.0, 0.5,                                          \
      "OctoMap sensor model: occupancy probability of a traversed voxel (in (0, 0.5))")      \
    X(double, max_ray_length, 30.0, "m", 0.0, 1e5,                                           \
      "Longer rays carve free space up to this length only and mark nothing occupied (> 0)") \
    X(int, ray_stride, 2, "", 1, 1000000,                                                    \
      "Carve free space along every n-th ground ray (obstacle rays are always cast)")        \
    X(double, obstacle_min_height, 0.25, "m", 0.0, 1e3,                                      \
      "Non-ground points at least this high above the local ground are obstacles")           \
    X(double, obstacle_max_height, 2.0, "m", 0.0, 1e3,                                       \
      "... and, for the 2-D grid, at most this high (the OctoMap keeps higher ones: overhangs)")

// Why these defaults: max_step_height 0.1 m is what outdoor (class C, EN 12184) powered
// wheelchairs and typical small wheeled robots are built to climb (a 0.15 m kerb is not).
// max_neighbour_step is off by default: on a moving, pitching robot the frames' residual attitude
// errors within a sweep (not removed by the per-frame levelling) still make cross-frame height
// differences exceed 0.1 m over large areas; set it (e.g. to max_step_height) for
// well-registered maps (see TraversabilityGrid::neighbourStep).
#define TRAVEL_MAP_FUSION_LIST(X)                                                               \
    X(float, logodds_obstacle, 0.85f, "", 0.0, 100.0,                                           \
      "Log-odds added to a cell with obstacle points in a frame (> 0)")                         \
    X(float, logodds_ground, -0.4f, "", -100.0, 0.0,                                            \
      "Log-odds added to a cell with only ground points in a frame (< 0)")                      \
    X(float, logodds_min, -2.0f, "", -100.0, 0.0, "Lower clamp of a cell's log-odds (< 0)")     \
    X(float, logodds_max, 3.5f, "", 0.0, 100.0, "Upper clamp of a cell's log-odds (> 0)")       \
    X(float, obstacle_threshold, 0.5f, "", 0.0, 100.0,                                          \
      "Log-odds above this: obstacle (below logodds_max)")                                      \
    X(float, free_threshold, -0.3f, "", -100.0, 0.0,                                            \
      "Log-odds below this: ground, traversable if flat (above logodds_min)")                   \
    X(int, min_obstacle_points, 2, "", 1, 1000000000,                                           \
      "Obstacle points a cell needs in one frame to count")                                     \
    X(int, min_step_points, 4, "", 2, 1000000000,                                               \
      "Ground points a cell needs in one frame to measure a step")                              \
    X(float, max_step_height, 0.1f, "m", 0.0, 100.0,                                            \
      "A larger step inside a cell: not traversable (> 0; 0.1 m: what outdoor wheelchairs and " \
      "small wheeled robots climb)")                                                            \
    X(float, max_neighbour_step, 0.0f, "m", 0.0, 100.0,                                         \
      "A larger step between neighbouring cells' fused ground heights: not traversable (0 = "   \
      "off; when on, each frame's ground is levelled against the map first)")                   \
    X(float, max_traversable_slope_deg, 20.0f, "deg", 0.0, 90.0,                                \
      "A cell whose terrain model is steeper than this is not traversable (in (0, 90); not "    \
      "travel.max_slope_deg, which decides what TRAVEL calls terrain)")

#define TRAVEL_MAP_LIST(X)     \
    TRAVEL_MAP_GRID_LIST(X)    \
    TRAVEL_MAP_OCTOMAP_LIST(X) \
    TRAVEL_MAP_FUSION_LIST(X)

// The obstacle sources of the reactive navigator (travel_mrpt::TravelObstacleSource, memory).
#define TRAVEL_NAV_LIST(X)                                                                         \
    X(double, max_step_height, 0.15, "m", 0.0, 100.0,                                              \
      "The robot climbs steps and bumps up to this height: lower ones are not obstacles")          \
    X(double, max_height, 2.0, "m", 0.0, 1e3,                                                      \
      "Points higher above the local ground than this are ignored (> 0)")                          \
    X(double, report_floor, 0.15, "m", 0.01, 100.0,                                                \
      "Points of too-steep nodes count from this height (the 3-D navigator drops z < 0.01)")       \
    X(double, ground_search_radius, 3.0, "m", 0.0, 1e4,                                            \
      "Nearest traversable node searched for the local ground of other nodes' points")             \
    X(double, step_min_spread, 0.05, "m", 0.0, 100.0,                                              \
      "The step rule only compares nodes whose ground points spread at least this much in "        \
      "their second direction")                                                                    \
    X(double, memory_seconds, 0.0, "s", 0.0, 1e6,                                                  \
      "How long earlier obstacles are kept (0: no memory)")                                        \
    X(double, memory_radius, 1.0, "m", 0.0, 1e6, "... while within this xy distance of the robot") \
    X(double, predict_seconds, 3.0, "s", 0.0, 60.0,                                                \
      "Objects the tracker flags moving are obstacles along their predicted path over this "       \
      "time (their box swept along the velocity; 0: only where they are; needs tracking)")

// Regression tolerances of travel-regress (a replay compared with a golden labelled rawlog,
// travel::compareFrames; docs/regression.md): within them the comparison passes (exit 0).
#define TRAVEL_REGRESS_LIST(X)                                                                   \
    X(double, min_class_agreement, 100.0, "%", 0.0, 100.0,                                       \
      "Least share of the points whose class (ground, non-ground, outlier, invalid) is the "     \
      "golden one, in every compared frame")                                                     \
    X(double, min_cluster_agreement, 100.0, "%", 0.0, 100.0,                                     \
      "Least share of the clustered points (in either run) that lie in one-to-one matched "      \
      "clusters, whatever the cluster ids, over all compared frames")                            \
    X(int, max_split_clusters, 0, "", 0, 1000000000,                                             \
      "Most golden clusters (all frames) that no cluster of the run holds a strict majority of") \
    X(int, max_merged_clusters, 0, "", 0, 1000000000,                                            \
      "Most golden clusters (all frames) that are no strict majority of their best run cluster") \
    X(int, max_changed_nodes, 0, "", 0, 1000000000,                                              \
      "Most terrain-model nodes (all frames) whose traversability changed")                      \
    X(int, max_missing_frames, 0, "", 0, 1000000000,                                             \
      "Most golden frames without a frame of the run (timestamp and sensor label)")              \
    X(int, max_extra_frames, 0, "", 0, 1000000000,                                               \
      "Most frames of the run without a golden frame")                                           \
    X(double, max_time_ratio, 0.0, "", 0.0, 1e6,                                                 \
      "Most run / golden ratio of the median TRAVEL time per frame (0 = timing not checked: it " \
      "depends on the machine)")

// The object tracker (travel::Tracker, docs/tracking.md): association gates, the constant-
// velocity Kalman filter of each track, the life of a track and the moving flag. Key names
// differ from every other section's, so `--set KEY=VALUE` needs no section.
#define TRAVEL_TRACKING_LIST(X)                                                                   \
    X(double, gate_distance, 2.0, "m", 0.01, 1e3,                                                 \
      "A cluster continues a track only if its centroid lies within this xy distance of the "     \
      "track's predicted position")                                                               \
    X(double, gate_box_margin, 0.5, "m", 0.0, 1e3,                                                \
      "... and its world-frame box overlaps the track's predicted box grown by this margin; "     \
      "an unassigned cluster centred in a matched track's box grown by it is a fragment of that " \
      "object and carries its id")                                                                \
    X(double, gate_size_ratio, 0.4, "", 0.0, 1.0,                                                 \
      "... and the smaller of the two box diagonals is at least this share of the larger")        \
    X(double, max_object_extent, 100.0, "m", 0.1, 1e4,                                            \
      "Clusters whose oriented box is longer than this (walls, rows of buildings) are not "       \
      "tracked (track_id 0)")                                                                     \
    X(double, full_box_max_length, 0.0, "m", 0.0, 1e3,                                            \
      "Tracks up to this long are located by the centre of the largest box seen, placed on the "  \
      "visible faces (the centroid moves with the view; 0 = off); longer ones by their centroid") \
    X(double, position_sigma, 0.5, "m", 1e-4, 1e3,                                                \
      "Kalman filter: 1-sigma noise of a measured centroid, per horizontal axis")                 \
    X(double, acceleration_sigma, 0.5, "m/s^2", 1e-4, 1e3,                                        \
      "Kalman filter: 1-sigma of the white-noise acceleration of the constant-velocity model")    \
    X(double, initial_velocity_sigma, 5.0, "m/s", 1e-3, 1e3,                                      \
      "Kalman filter: 1-sigma of a new track's velocity (it starts at 0)")                        \
    X(int, confirm_hits, 1, "", 1, 1000,                                                          \
      "A tentative track is confirmed (and gets its id) after this many associated frames; a "    \
      "tentative track ends at its first miss")                                                   \
    X(int, max_misses, 3, "", 1, 1000000,                                                         \
      "A confirmed track ends after this many consecutive frames without a cluster")              \
    X(double, moving_speed_on, 1.0, "m/s", 0.0, 1e3,                                              \
      "A track becomes moving when its speed exceeds this for moving_frames_on frames in a row")  \
    X(int, moving_frames_on, 5, "", 1, 1000, "... that many frames")                              \
    X(double, moving_speed_off, 0.5, "m/s", 0.0, 1e3,                                             \
      "A moving track stops moving when its speed falls below this (hysteresis: < "               \
      "moving_speed_on)")

#define TRAVEL_SECTION_MEMBER(type, name, def, unit, lo, hi, doc) type name = def;

struct FilterSection {
    TRAVEL_FILTER_LIST(TRAVEL_SECTION_MEMBER)
    /// Ranges, then the regex and max_motion_age > 0. Throws ConfigError naming the key.
    void validate() const;
};

/// The map's grid extent and cell size, world frame. Cell (ix, iy) covers
/// [min_x + ix * resolution, min_x + (ix + 1) * resolution) and likewise in y.
struct GridGeometry {
    TRAVEL_MAP_GRID_LIST(TRAVEL_SECTION_MEMBER)
    int sizeX() const;
    int sizeY() const;
    /// Ranges, min < max and at most 16384 x 16384 cells. Throws ConfigError naming the key.
    void validate() const;
};

/// How the map fuses frames into cells (travel::TraversabilityGrid).
struct GridFusionParams {
    TRAVEL_MAP_FUSION_LIST(TRAVEL_SECTION_MEMBER)
    /// Ranges, then strict signs and thresholds inside the clamps. Throws ConfigError.
    void validate() const;
};

/// The whole map section: the grid's two parts and the OctoMap / obstacle-height keys.
struct MapSection : GridGeometry, GridFusionParams {
    TRAVEL_MAP_OCTOMAP_LIST(TRAVEL_SECTION_MEMBER)
    /// The parts' rules, then the OctoMap ranges and the cross-key rules (obstacle heights,
    /// ray length in voxels). Throws ConfigError naming the key.
    void validate() const;
};

struct NavSection {
    TRAVEL_NAV_LIST(TRAVEL_SECTION_MEMBER)
    void validate() const;
};

struct RegressSection {
    TRAVEL_REGRESS_LIST(TRAVEL_SECTION_MEMBER)
    void validate() const;
};

/// The tracker's section (travel::Tracker).
struct TrackingParams {
    TRAVEL_TRACKING_LIST(TRAVEL_SECTION_MEMBER)
    /// Ranges, then moving_speed_off < moving_speed_on. Throws ConfigError naming the key.
    void validate() const;
};

#undef TRAVEL_SECTION_MEMBER

/// The whole configuration: one struct per section.
struct Config {
    Params travel;
    FilterSection filter;
    MapSection map;
    NavSection nav;
    RegressSection regress;
    TrackingParams tracking;
    /// Every section's validate(); the message names the section ("map.max_x: ...").
    void validate() const;
};

// ---- One visitor for every section: v(name, value_ref, unit, min, max, description) --------

#define TRAVEL_SECTION_VISIT(type, name, def, unit, lo, hi, doc) \
    v(#name, s.name, unit, static_cast<double>(lo), static_cast<double>(hi), doc);
#define TRAVEL_DEFINE_VISITOR(Section, LIST, NAME)    \
    template <class Visitor>                          \
    void visitFields(Section& s, Visitor&& v) {       \
        LIST(TRAVEL_SECTION_VISIT)                    \
    }                                                 \
    template <class Visitor>                          \
    void visitFields(const Section& s, Visitor&& v) { \
        LIST(TRAVEL_SECTION_VISIT)                    \
    }                                                 \
    inline const char* sectionName(const Section&) {  \
        return NAME;                                  \
    }

TRAVEL_DEFINE_VISITOR(Params, TRAVEL_PARAM_LIST, "travel")
TRAVEL_DEFINE_VISITOR(FilterSection, TRAVEL_FILTER_LIST, "filter")
TRAVEL_DEFINE_VISITOR(GridGeometry, TRAVEL_MAP_GRID_LIST, "map")
TRAVEL_DEFINE_VISITOR(GridFusionParams, TRAVEL_MAP_FUSION_LIST, "map")
TRAVEL_DEFINE_VISITOR(MapSection, TRAVEL_MAP_LIST, "map")
TRAVEL_DEFINE_VISITOR(NavSection, TRAVEL_NAV_LIST, "nav")
TRAVEL_DEFINE_VISITOR(RegressSection, TRAVEL_REGRESS_LIST, "regress")
TRAVEL_DEFINE_VISITOR(TrackingParams, TRAVEL_TRACKING_LIST, "tracking")
#undef TRAVEL_DEFINE_VISITOR
#undef TRAVEL_SECTION_VISIT

/// f(section) for each section of `config`, in file order (travel, filter, map, nav, regress,
/// tracking).
template <class C, class F>
void visitSections(C& config, F&& f) {
    f(config.travel);
    f(config.filter);
    f(config.map);
    f(config.nav);
    f(config.regress);
    f(config.tracking);
}

}  // namespace travel
