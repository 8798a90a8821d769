// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The synthetic world of the map tests: flat ground with a 10-degree ramp (up along +x, y in
// [4, 8], 6 m long, 3 m plateau, then a 1.06 m drop), a 0.15 m kerb (sidewalk for y < -7.1),
// a 2 x 1.5 x 1.2 m box on the sidewalk at (3, -9) and a 3 m pole (r 0.15 m) at (-5, 3).
// A robot with a VLP-16 1.8 m above its origin drives along y = 0 (a car in its lane, the kerb
// 7.1 m to its right: just outside the 6.7 m circle the lowest beam leaves unseen) and stops at
// 17 poses, x = -12..12 every 1.5 m, taking a static sweep at each; the sweeps are
// CObservationPointCloud (CPointsMapXYZI, sensor frame, sensorPose = the mount) 0.1 s apart.
//
// Ground-truth cell state from the scene description, for a cell [x0, x0 + r) x [y0, y0 + r):
//   obstacle     a box / pole footprint overlaps the cell, or the terrain inside the cell has a
//                step higher than max_step (jump between samples 1/5 cell apart, beyond what
//                max_slope would explain) or a slope steeper than max_slope;
//   traversable  otherwise.
// Cells whose 8 neighbours do not all share their truth are "border" cells (a cell half on a
// kerb or half under a box has no single right answer): the strict score skips them, the
// tolerant one accepts the truth of the cell or of any of its 8 neighbours.
// Used by the in-process tests and by the plugin host (which does not link travel_mrpt).
#pragma once

#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

#include "travel/sim/Scene.hpp"

namespace travel_map_test {

travel::sim::Scene mapScene();

/// Robot poses (world) of the sweeps.
std::vector<mrpt::poses::CPose3D> robotPoses();

/// The sweep taken at robotPoses()[k] (timestamp 1e9 + 0.1 k s).
mrpt::obs::CObservationPointCloud::Ptr sweep(const travel::sim::Scene& scene, std::size_t k);

enum class Truth { Traversable, Obstacle };

struct CellTruth {
    Truth truth = Truth::Traversable;
    bool border = false;
    bool box = false, pole = false;  ///< a footprint overlaps the cell
};

/// Truth of every cell of a grid with lower-left corner (min_x, min_y), nx x ny cells of side
/// `resolution`, index iy * nx + ix.
std::vector<CellTruth> cellTruth(const travel::sim::Scene& scene, double min_x, double min_y,
                                 int nx, int ny, double resolution, double max_step,
                                 double max_slope_deg);

/// The map .ini section keys shared by the tests: TRAVEL for this robot (vlp16 preset, sensor
/// 1.8 m up) and the grid geometry x in [-14, 14], y in [-12, 10], 0.25 m cells.
std::string mapIni(const std::string& section);

}  // namespace travel_map_test
