// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A travel-nav-sim world: a travel::sim::Scene (terrain + objects the LiDAR sees), the start
// pose, the goal, and the obstacles of the collision check, read from a small text file
// (share/worlds/*.world). One item per line, '#' starts a comment, metres and degrees:
//
//   name      NAME
//   start     X Y YAW_DEG
//   goal      X Y
//   bounds    XMIN YMIN XMAX YMAX                        picture extent (default: fitted)
//   ramp      X Y DIR_DEG LENGTH WIDTH SLOPE_DEG [PLATEAU]  X Y = centre of the bottom edge
//   step      X Y DIR_DEG HEIGHT [LENGTH WIDTH]          terrain only: X Y = rising edge centre
//   kerb      X Y YAW_DEG LENGTH DEPTH HEIGHT            raised strip centred on X Y, long
//                                                        axis along YAW; an obstacle
//   bump      X Y AMPLITUDE SIGMA
//   roughness AMPLITUDE WAVELENGTH
//   box       X Y YAW_DEG LENGTH WIDTH HEIGHT            an obstacle
//   pole      X Y RADIUS HEIGHT                          an obstacle
//   wall      X1 Y1 X2 Y2 THICKNESS HEIGHT               an obstacle
//   mover     X Y YAW_DEG LENGTH WIDTH HEIGHT VX VY      a box at X Y at t = 0, moving at the
//                                                        constant velocity VX VY [m/s]; an
//                                                        obstacle where it is at each scan
//
// Obstacles of the collision check: boxes, poles, walls and kerbs (a kerb is a step the robot
// must not climb). Ramps, steps and bumps are terrain.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "travel/sim/Scene.hpp"
#include "travel/sim/TrafficSequence.hpp"

namespace travel::navsim {

/// A convex polygon (counter-clockwise) or a circle (radius > 0, one vertex = the centre).
struct Obstacle2D {
    std::string what;  ///< "box 1", "kerb 2", ... for reports
    std::vector<Eigen::Vector2d> polygon;
    double radius = 0.0;
    double height = 0.0;  ///< [m] above the terrain
    bool moving = false;  ///< a mover's: polygon where it is now (placeMovers)
};

/// A box moving at constant velocity: its motion, its box in World::scene.boxes (what the
/// LiDAR sees) and its polygon in World::obstacles (the collision check).
struct Mover {
    sim::MovingBox motion;  ///< motion.box: where it is at t = 0
    std::size_t box = 0, obstacle = 0;
};

struct World {
    std::string name = "world";
    std::string source;  ///< file it came from (for messages)
    travel::sim::Scene scene;
    Eigen::Vector3d start{0.0, 0.0, 0.0};  ///< x, y [m], yaw [rad]
    Eigen::Vector2d goal{10.0, 0.0};
    Eigen::Vector4d bounds{0, 0, 0, 0};  ///< xmin, ymin, xmax, ymax; all 0 = fit
    std::vector<Obstacle2D> obstacles;
    std::vector<std::size_t> kerb_steps;  ///< indices into scene.steps that are kerbs
    std::vector<Mover> movers;
};

/// Places every mover of `world` where it is at time t [s] (its scene box and its obstacle).
void placeMovers(World& world, double t);

/// Parses a world; throws std::runtime_error naming `source_name`, the line and what was
/// expected.
World parseWorld(const std::string& text, const std::string& source_name);
/// Reads and parses a file; throws std::runtime_error naming the file.
World loadWorld(const std::string& path);
/// A seeded variant of `world` (seed 0: unchanged): every kerb moved by one random xy shift and
/// every box by another, every mover's start by a third (its path and timing), each coordinate
/// uniform in [-amplitude, amplitude] (std::mt19937). Moves the kerbs' terrain steps and the
/// boxes the LiDAR sees along with their obstacles.
World shiftedObstacles(const World& world, unsigned seed, double amplitude = 0.3);
/// The picture extent: `bounds`, or everything in the world plus a margin.
Eigen::Vector4d worldExtent(const World& world);

}  // namespace travel::navsim
