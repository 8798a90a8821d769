// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The simulator's collision check: the robot's footprint (a convex polygon in the robot frame,
// placed at the robot's x, y, yaw) against the obstacles of the world description.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "nav/World.hpp"

namespace travel::navsim {

/// Footprint polygon moved to pose (x, y, yaw).
std::vector<Eigen::Vector2d> placeFootprint(const std::vector<Eigen::Vector2d>& footprint,
                                            const Eigen::Vector3d& pose);

/// Distance between two convex polygons, 0 when they overlap or touch.
double polygonDistance(const std::vector<Eigen::Vector2d>& a,
                       const std::vector<Eigen::Vector2d>& b);

struct Clearance {
    double distance = 1e9;  ///< [m] to the nearest obstacle, 0 = overlapping (a collision)
    std::string nearest;    ///< its name ("box 1", ...), empty when there is none
};

/// Clearance of the placed footprint to every obstacle of the world (movers_only: to the
/// movers, Obstacle2D::moving, only).
Clearance clearance(const std::vector<Eigen::Vector2d>& placed_footprint, const World& world,
                    bool movers_only = false);

}  // namespace travel::navsim
