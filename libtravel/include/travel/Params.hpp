// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// All parameters of libtravel, in one flat struct (KISS-ICP / Patchwork++ style).
// Each parameter is declared exactly once, in TRAVEL_PARAM_LIST below: its type, name, default
// (HDL-64E on KITTI), unit, valid range and meaning, with the paper's symbol where it has one.
// The struct members, the YAML/ini loader, the key validation and the documentation dump are all
// generated from this list, so a parameter cannot exist in one place and be missing in another.
#pragma once

#include <string>

namespace travel {

/// A real parameter that may also be `auto` (sensor_height, mount_roll_deg, mount_pitch_deg):
/// then the Pipeline estimates it from the first frame(s) (MountEstimator.hpp) and keeps the
/// estimate. `value` is the configured number, or with `auto` the fallback used until an
/// estimate exists (the value it had before `auto` was set, e.g. the preset's). In files and
/// --set, `auto` keeps the value before it as the fallback and `auto(1.2)` sets it; printed
/// configurations write `auto(FALLBACK)`, so that they read back identically without the preset.
/// It reads as a double (its value) so that code which only needs a number stays unchanged.
struct AutoReal {
    double value = 0.0;
    bool automatic = false;

    AutoReal() = default;
    AutoReal(double v) : value(v) {}  // NOLINT: implicit, `params.sensor_height = 1.73`
    static AutoReal makeAuto(double fallback) {
        AutoReal a(fallback);
        a.automatic = true;
        return a;
    }
    bool isAuto() const { return automatic; }
    operator double() const { return value; }  // NOLINT: implicit on purpose, see above
};

// X(type, name, default, unit, min, max, description)
// Types: double, AutoReal (a double or `auto`), int, bool, std::string. Angles are in degrees in
// files; the code converts once. For std::string parameters the `unit` slot lists the allowed
// values ("a|b|c") and min/max are unused (0).
#define TRAVEL_PARAM_LIST(X)                                                                      \
    /* ---- Sensor and pre-processing (paper Sec. III-A) ---- */                                  \
    X(AutoReal, sensor_height, 1.73, "m", 0.0, 100.0,                                             \
      "Height of the sensor origin above the ground under the vehicle (h_s); auto = estimated "   \
      "from the first frame by a robust ground-plane fit")                                        \
    X(double, min_range, 2.7, "m", 0.0, 1000.0,                                                   \
      "Points closer than this (3-D range) are invalid: returns from the vehicle itself (with "   \
      "a self_box, only the sensor head's own blind zone: 1 m in the hdl64 preset)")              \
    X(double, self_box_min_x, 0.0, "m", -1000.0, 1000.0,                                          \
      "Self filter box: rear end (-x). Points strictly inside [self_box_min_*, self_box_max_*] "  \
      "are invalid: returns from the own vehicle's body. Vehicle axes (the sensor's after "       \
      "mount_*), origin at the sensor; an empty box (min = max, the default) filters nothing")    \
    X(double, self_box_max_x, 0.0, "m", -1000.0, 1000.0, "Self filter box: front end (+x)")       \
    X(double, self_box_min_y, 0.0, "m", -1000.0, 1000.0, "Self filter box: right side (-y)")      \
    X(double, self_box_max_y, 0.0, "m", -1000.0, 1000.0, "Self filter box: left side (+y)")       \
    X(double, self_box_min_z, 0.0, "m", -1000.0, 1000.0, "Self filter box: bottom (-z)")          \
    X(double, self_box_max_z, 0.0, "m", -1000.0, 1000.0, "Self filter box: top (+z)")             \
    X(double, max_range, 80.0, "m", 0.1, 2000.0,                                                  \
      "Points farther than this (3-D range) are invalid; also sets the tri-grid extent R")        \
    X(AutoReal, mount_roll_deg, 0.0, "deg", -180.0, 180.0,                                        \
      "Roll of the sensor in the vehicle frame (extrinsic); auto = from the first frame's "       \
      "ground plane (the vehicle standing level)")                                                \
    X(AutoReal, mount_pitch_deg, 0.0, "deg", -90.0, 90.0,                                         \
      "Pitch of the sensor in the vehicle frame (extrinsic); auto = as mount_roll_deg")           \
    X(double, mount_yaw_deg, 0.0, "deg", -180.0, 180.0,                                           \
      "Yaw of the sensor in the vehicle frame (extrinsic); the tri-grid is aligned with the "     \
      "vehicle frame")                                                                            \
    X(bool, align_attitude, true, "", 0, 1,                                                       \
      "Rotate each frame upright with the vehicle roll/pitch when the caller provides it")        \
    X(bool, deskew, true, "", 0, 1,                                                               \
      "Undo the motion during the sweep when per-point times and a velocity are provided")        \
    /* ---- Tri-grid field (Sec. III-B) ---- */                                                   \
    X(double, tgf_resolution, 4.0, "m", 0.25, 100.0,                                              \
      "r: side of a tri-grid cell; each cell holds 4 triangular nodes (paper: 8; 4 is better "    \
      "on SemanticKITTI, see README)")                                                            \
    X(int, max_grid_cells_per_side, 512, "", 1, 8192,                                             \
      "Safety limit on 2 R / r; a larger grid is a configuration error, never an allocation. "    \
      "512 cells per side is about 207 MB (1 km at r = 4 m fits)")                                \
    /* ---- Node-wise terrain model (Sec. III-B) ---- */                                          \
    X(int, lpr_num_points, 5, "", 1, 64,                                                          \
      "Number of lowest points whose mean z is the node's lowest point representative (LPR)")     \
    X(double, seed_margin_above_lpr, 0.2, "m", 0.0, 10.0,                                         \
      "Initial plane seeds: z < LPR + this (reference 0.5; 0.2 keeps the foot of steep slopes "   \
      "and kerbs out of the ground plane, and scores higher on SemanticKITTI)")                   \
    X(double, seed_margin_below_lpr, 0.3, "m", 0.0, 10.0, "Initial plane seeds: z >= LPR - this") \
    X(double, plane_inlier_dist, 0.05, "m", 0.0, 10.0,                                            \
      "PCA refit: points with signed distance to the plane below this are re-selected "           \
      "(reference 0.125; 0.05 keeps the bases of objects from lifting the plane)")                \
    X(int, plane_fit_iterations, 3, "", 1, 100, "Number of PCA fits per node")                    \
    X(int, node_min_points, 5, "", 3, 1000000,                                                    \
      "Nodes with fewer points are 'unknown' (no terrain model). Reference 10; 5 keeps far "      \
      "nodes crossed by a single ring")                                                           \
    X(double, line_node_ratio, 0.01, "", 0.0, 1.0,                                                \
      "A node whose PCA has l2 < this * l1 is a line (typically one ring crossing it): its "      \
      "normal is taken perpendicular to the line and as level as possible")                       \
    X(double, max_slope_deg, 25.0, "deg", 0.0, 90.0,                                              \
      "theta: a node is terrain when its normal is within this angle of vertical (paper 30, "     \
      "reference code 20: 25 keeps 20-degree ramps and rejects 30-degree ones with margin)")      \
    /* ---- Breadth-first traversable graph search (Sec. III-C, eq. 2) ---- */                    \
    X(double, seed_search_radius, 10.0, "m", 0.0, 10000.0,                                        \
      "The search starts from the best terrain node whose mean is within this xy distance of "    \
      "the sensor (metres, so it does not depend on the cell size)")                              \
    X(double, seed_height_tolerance, 1.0, "m", 0.0, 100.0,                                        \
      "A start node's mean z must be within this of -sensor_height (plausible ground)")           \
    X(double, eps1, 0.03, "rad", 0.0, 3.2,                                                        \
      "epsilon_1: local convexity/concavity, |s_i.d| < |d| sin(eps1) and |s_j.d| < |d| "          \
      "sin(eps1) for the displacement d between node means")                                      \
    X(double, eps2, 0.1, "rad/m", 0.0, 3.2,                                                       \
      "epsilon_2: normal similarity, |s_i.s_j| > 1 - sin(|d| eps2)")                              \
    X(double, reseed_max_height_diff, 0.3, "m", 0.0, 100.0,                                       \
      "A node unreached by the search starts a new search only if its mean is within this of "    \
      "the plane of the nearest accepted node")                                                   \
    X(double, reseed_max_distance, 24.0, "m", 0.0, 10000.0,                                       \
      "... and that accepted node is at most this far (xy) from it")                              \
    X(double, reseed_min_weight_ratio, 0.0, "", 0.0, 1.0,                                         \
      "... and its weight is at least this fraction of the start node's weight")                  \
    /* ---- TTMF and point labels (Sec. III-D, eq. 5) ---- */                                     \
    X(bool, ttmf, true, "", 0, 1,                                                                 \
      "Traversable terrain model fitting: refit every node from corner heights")                  \
    X(double, ground_dist, 0.13, "m", 0.0, 10.0,                                                  \
      "epsilon_3: a point of a traversable node is ground when its signed distance to the "       \
      "refitted plane is below this (paper 0.1; 0.13 keeps road points beside cars out of "       \
      "their clusters, see README)")                                                              \
    X(bool, label_with_node_plane, true, "", 0, 1,                                                \
      "A point of a node the search accepted (eq. 2) is also ground when it lies within eps3 "    \
      "of the node's own plane, if the node is clear (own_plane_clearance): keeps verges and "    \
      "both sides of kerbs that TTMF's corner averaging smooths away")                            \
    X(double, own_plane_clearance, 0.5, "m", 0.0, 100.0,                                          \
      "A node is clear when none of its points stands this high or higher above its own "         \
      "plane: no car body, wall, fence, trunk or bush, whose bases must not join the ground; "    \
      "grass, verges and kerbs stay below. Leave-one-out over the dev frames: 0.5")               \
    X(double, clearance_radius, 0.5, "m", 0.0, 2.0,                                               \
      "In a reached node that is not clear, a point is still labelled against the node's own "    \
      "plane (label_with_node_plane) when no point of the node or its neighbours within this xy " \
      "distance stands own_plane_clearance or more above that plane: verges beside posts, "       \
      "trees and signs; the bases of such objects lie under them. 0 = the whole node must be "    \
      "clear")                                                                                    \
    X(double, vertical_face_min_rise, 0.0, "m", 0.0, 100.0,                                       \
      "A ground point from which its range-image column climbs steeper than 45 deg by more "      \
      "than this, up to a non-ground point, is the foot of a wall, fence, trunk or bush face: "   \
      "NonGround (extends eq. 5). 0 = off (roads: +10 % CPU, see docs); 0.25 (above kerbs) in "   \
      "the os64 preset")                                                                          \
    X(double, vertical_face_min_length, 6.0, "m", 0.0, 1000.0,                                    \
      "Scope of the face rule when on: only under object clusters whose xy box has a side at "    \
      "least this long (walls, fences, hedges: longer than any car, 5.6 m at most from any "      \
      "side), after the object segmentation, each foot joining its face's cluster; 0 = under "    \
      "every ground point, in the ground stage (the os64 preset, off-road)")                      \
    X(int, vertical_face_max_gap, 2, "rings", 0, 16,                                              \
      "The face rule's climb steps over up to this many consecutive rings without a return "      \
      "(foliage, mesh fences and dark paint return part of the rays): a porous face keeps its "   \
      "foot. 0 = an empty ring ends the climb")                                                   \
    X(double, vertical_face_max_thickness, 0.03, "m", 0.0, 100.0,                                 \
      "Walls scope only: a foot is taken only under a thin face, half of the returns of its "     \
      "column from the face up (8 rings) within this of their median xy range: a wall or fence "  \
      "is one vertical plane (range noise), a hedge scatters its returns through its depth "      \
      "(SemanticKITTI: vegetation). 0 = no test")                                                 \
    X(double, vertical_face_min_foot_height, 0.0, "m", 0.0, 100.0,                                \
      "A face foot stands at least this high above its ground plane (eq. 5's signed "             \
      "distance): lower points are on the ground as far as range noise tells (SemanticKITTI's "   \
      "road before car sills and tyres); 0 = every ground point may be a foot")                   \
    X(bool, cluster_face_feet, false, "", 0, 1,                                                   \
      "Each face foot joins the object cluster of its face (else it is left unclustered: on "     \
      "SemanticKITTI the feet at car sills are often labelled road/parking, see docs)")           \
    X(double, outlier_dist, 0.3, "m", 0.0, 100.0,                                                 \
      "Points more than this below the refitted plane are outliers (below-ground noise), "        \
      "unless the own plane of their reached node makes them ground (a ditch's bottom)")          \
    /* ---- Range image (Sec. IV-A) ---- */                                                       \
    X(std::string, ring_source, "auto", "auto|field|scan_order|table", 0, 0,                      \
      "Where a point's ring comes from: the input's ring field, the scan order (a ring ends "     \
      "where the azimuth wraps around, KITTI .bin files), the elevation table; auto = the "       \
      "first of these that works")                                                                \
    X(std::string, elevation_table, "hdl64", "hdl64|hdl32|vlp16|os128|uniform", 0, 0,             \
      "Beam elevations used when rings come from the table: a sensor's (non-uniform for the "     \
      "HDL-64E) or num_rings uniform bins in [min_elevation_deg, max_elevation_deg]")             \
    X(int, num_rings, 64, "", 1, 1024, "Rows of the range image (laser rings)")                   \
    X(int, num_columns, 2048, "", 16, 65536,                                                      \
      "Columns of the range image (azimuth bins); beams x num_columns at most 2,097,152")         \
    X(int, scan_points, 0, "points", 0, 16777216,                                                 \
      "Points per scan the buffers are sized for when the pipeline is built (their pages are "    \
      "mapped then, not on the first frame); 0 = beams x num_columns. A larger scan still "       \
      "works: its first frame grows the buffers")                                                 \
    X(double, min_elevation_deg, -24.9, "deg", -90.0, 90.0,                                       \
      "Lowest beam elevation, for elevation_table: uniform")                                      \
    X(double, max_elevation_deg, 2.0, "deg", -90.0, 90.0,                                         \
      "Highest beam elevation, for elevation_table: uniform")                                     \
    /* ---- Above-ground object segmentation (Sec. IV) ---- */                                    \
    X(bool, cluster_objects, true, "", 0, 1,                                                      \
      "Run the above-ground object segmentation (the face rule's walls scope builds its runs "    \
      "either way, and then reports no cluster)")                                                 \
    X(double, horizontal_merge_dist, 0.4, "m", 0.0, 100.0,                                        \
      "T_horz: neighbouring points of a ring closer than this (3-D) form one run")                \
    X(int, horizontal_skip_runs, 5, "", 0, 10000,                                                 \
      "T_skip: a run also merges with the next runs up to this many ahead on its ring when "      \
      "their facing end points are closer than T_horz (bridges occlusions)")                      \
    X(double, occlusion_max_gap, 1.0, "m", 0.0, 100.0,                                            \
      "Skipped linkage across an occlusion: a point continues an open run across a gap up to "    \
      "this wide when every point seen in between is nearer to the sensor (by T_horz) and the "   \
      "two ends' ranges differ by less than T_horz")                                              \
    X(double, see_through_depth, 2.5, "m", 0.0, 100.0,                                            \
      "Windows: a cluster seen only through gaps (<= occlusion_max_gap) of one nearer cluster, "  \
      "closed above or below by it (a hole, not a fence slot), and at most this far behind it, "  \
      "joins it: a vehicle's seats and far side (2.5 m = the widest road vehicles); a cluster "   \
      "with a run seen through a gap farther behind it than this never joins (an object "         \
      "beyond, e.g. a car parked behind a car). 0 = off")                                         \
    X(double, see_through_width, 1.8, "m", 0.0, 100.0,                                            \
      "Windows: a cluster with a run seen through a gap whose deepest point lies farther than "   \
      "this behind the gap's frame (measured across it, in xy) never joins the enclosing "        \
      "cluster: it is beyond that vehicle's far side (a child or a car right behind a car). "     \
      "0 = off")                                                                                  \
    X(double, set_back_depth, 1.7, "m", 0.0, 100.0,                                               \
      "Set-back tops: a cluster standing on a nearer one (each run of its lowest row has that "   \
      "cluster's points in front in the row below), within its columns and at least half as "     \
      "wide, whose nearest point is at most this behind that cluster's, joins it: a car's cabin " \
      "behind its boot or bonnet, seen end on (1.7 m: passenger-car bonnets reach 1.0-1.6 m, "    \
      "a car parked behind another side on is 1.8 m or more behind it). 0 = off")                 \
    X(double, seam_max_shift, 3.0, "m", 0.0, 100.0,                                               \
      "Runs of a ring facing each other across the column where the sweep started (0.1 s "        \
      "apart in time) merge when their facing ends are closer than this: a car moving at up to "  \
      "30 m/s relative to the sensor (oncoming urban traffic, 2 x 54 km/h) shifts 3 m in a "      \
      "10 Hz sweep. 0 = off")                                                                     \
    X(int, vertical_ring_span, 3, "", 1, 1024,                                                    \
      "T_ring: a run is compared with the runs of this many rings below it")                      \
    X(double, vertical_merge_dist, 0.5, "m", 0.0, 100.0,                                          \
      "T_vert: runs of different rings merge when their closest points are nearer than "          \
      "sqrt(T_vert^2 + (R dtheta)^2): T_vert beyond the spacing R dtheta of one ring at the "     \
      "upper point's range R (0.15-0.22 m at 25 m on an HDL-64E)")                                \
    X(int, vertical_column_extension, 5, "", 0, 65536,                                            \
      "T_ext: columns by which a run's span is widened when looking for runs on other rings")     \
    X(int, min_cluster_size, 10, "", 1, 100000000,                                                \
      "Clusters with fewer points keep class nonground with cluster id 0")                        \
    X(int, max_cluster_size, 100000000, "", 1, 2000000000,                                        \
      "Clusters with more points keep class nonground with cluster id 0")

struct Params {
#define TRAVEL_DECLARE_PARAM(type, name, def, unit, lo, hi, doc) type name = def;
    TRAVEL_PARAM_LIST(TRAVEL_DECLARE_PARAM)
#undef TRAVEL_DECLARE_PARAM

    /// Throws ConfigError naming the first parameter out of its documented range or
    /// inconsistent with another one (e.g. min_range >= max_range, or a range image of more
    /// than kMaxRangeImageCells beams x num_columns cells).
    void validate() const;

    /// The largest range image (beams x num_columns cells) accepted: 1024 x 2048, 128 x 16384.
    static constexpr double kMaxRangeImageCells = 2097152;
};

/// Visit every parameter: v(name, value_ref, unit, min, max, description).
template <class P, class Visitor>
void visitParams(P& p, Visitor&& v) {
#define TRAVEL_VISIT_PARAM(type, name, def, unit, lo, hi, doc) \
    v(#name, p.name, unit, static_cast<double>(lo), static_cast<double>(hi), doc);
    TRAVEL_PARAM_LIST(TRAVEL_VISIT_PARAM)
#undef TRAVEL_VISIT_PARAM
}

}  // namespace travel
