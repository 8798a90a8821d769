// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// An analytic world for the synthetic LiDAR: a terrain height field h(x, y) built from simple
// features, plus objects standing on it. Everything is in world coordinates (z up, metres).
// The terrain is unbounded: features are local, the base height extends to infinity.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace travel::sim {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;  ///< the scene's angles (slope_deg, yaw_deg) are degrees

/// An inclined strip: the height rises linearly along `direction` from the start line for
/// `length` metres, then stays at the top height for `plateau_length` metres (a raised level).
/// Outside |across| <= width / 2 it contributes nothing, so its sides are vertical faces.
struct Ramp {
    Eigen::Vector2d start{0.0, 0.0};      ///< centre of the start (bottom) edge
    Eigen::Vector2d direction{1.0, 0.0};  ///< uphill direction; normalised on use
    double length = 10.0;                 ///< [m] along direction
    double width = 10.0;                  ///< [m] across direction
    double slope_deg = 10.0;              ///< negative slopes lead down
    double plateau_length = kInfinity;    ///< [m] flat top beyond the end

    double topHeight() const;
};

/// A region raised by `height` with vertical faces: kerbs, stair steps, sidewalks.
/// With the default infinite length and width it is a half-plane beyond the start line.
struct Step {
    Eigen::Vector2d start{0.0, 0.0};      ///< centre of the rising edge
    Eigen::Vector2d direction{1.0, 0.0};  ///< towards the raised side; normalised on use
    double height = 0.15;                 ///< [m], negative for a drop
    double length = kInfinity;            ///< [m] depth of the raised region along direction
    double width = kInfinity;             ///< [m] across direction
};

/// Gaussian bump: amplitude * exp(-|p - centre|^2 / (2 sigma^2)).
struct Bump {
    Eigen::Vector2d centre{0.0, 0.0};
    double amplitude = 0.3;  ///< [m], negative for a dip
    double sigma = 3.0;      ///< [m]
};

/// Sinusoidal roughness everywhere: amplitude * sin(k x) * cos(k y), k = 2 pi / wavelength.
struct Roughness {
    double amplitude = 0.0;   ///< [m], 0 disables it
    double wavelength = 1.5;  ///< [m]
};

/// Oriented box standing on the terrain, e.g. a car. Top = h(centre) + clearance + height.
struct Box {
    uint32_t id = 1;  ///< instance id, > 0
    Eigen::Vector2d centre{0.0, 0.0};
    double yaw_deg = 0.0;  ///< rotation of the length axis from +x, counter-clockwise
    double length = 4.5;
    double width = 1.8;
    double height = 1.5;
    double clearance = 0.0;  ///< [m] gap under the box; 0 = rests on (and sinks into) the ground
    /// [m/s] in xy: the box moves during the sweep, its centre at centre + velocity * t for the
    /// column fired at time t (so a moving car is seen skewed, as by a real spinning LiDAR).
    Eigen::Vector2d velocity{0.0, 0.0};
    /// Share of the rays hitting the box that return (dark paint, tyres: < 1); the others give
    /// no return. Which rays drop is a fixed hash of (ring, column, id): deterministic.
    double return_fraction = 1.0;
};

/// Vertical cylinder standing on the terrain. Top = h(centre) + height.
struct Pole {
    uint32_t id = 1;
    Eigen::Vector2d centre{0.0, 0.0};
    double radius = 0.1;
    double height = 4.0;
};

/// Thin box between two ground points. Top = h(midpoint) + height.
struct Wall {
    uint32_t id = 1;
    Eigen::Vector2d a{0.0, 0.0};
    Eigen::Vector2d b{1.0, 0.0};
    double thickness = 0.2;
    double height = 2.0;
};

/// Grass or other horizontally spreading low vegetation on a rectangle of the terrain (axis
/// aligned, [lo, hi]): SemanticKITTI's
/// "terrain" class (grass, soil), so its returns are ground truth Ground, instance 0, whatever
/// their height in the canopy (isolated bushes and shrubs are "vegetation": model them as Boxes
/// with a return_fraction). A ray crossing the canopy returns from a blade with probability
/// `return_fraction`, at a depth uniform in [0, height] below the canopy's top (a fixed hash of
/// ring, column and cover: deterministic); the other rays reach the soil.
struct GroundCover {
    Eigen::Vector2d lo{-5.0, -5.0};  ///< [m] corner with the smallest x and y
    Eigen::Vector2d hi{5.0, 5.0};    ///< [m] corner with the largest x and y
    double height = 0.3;             ///< [m] canopy top above the terrain
    double return_fraction = 0.6;    ///< share of the rays returned by the blades
};

/// A puddle: a bowl pressed `depth` metres into the terrain at its centre (0 at the rim,
/// `radius` away) filled with water up to `rim_height` below the unpressed terrain at the
/// centre. Water reflects specularly: a ray that reaches it returns nothing, except a share
/// `mirror_fraction` (a fixed hash) that the surface reflects onto what lies beyond (terrain,
/// objects); the sensor reports those at the range of the whole path along the original ray,
/// below the water: ground truth Reflection, instance 0.
struct Puddle {
    Eigen::Vector2d centre{0.0, 0.0};
    double radius = 1.5;           ///< [m]
    double depth = 0.15;           ///< [m] of the bowl at its centre
    double rim_height = 0.03;      ///< [m] water level below the unpressed terrain at the centre
    double mirror_fraction = 0.3;  ///< share of the rays reaching the water that are mirrored
};

/// World z range occupied by a placed object.
struct ZRange {
    double bottom = 0.0;
    double top = 0.0;
};

struct Scene {
    // ---- Terrain: h = base + sum of all feature contributions ----
    double base_height = 0.0;
    std::vector<Ramp> ramps;
    std::vector<Step> steps;
    std::vector<Bump> bumps;
    Roughness roughness;
    std::vector<Puddle> puddles;      ///< their bowls are part of h; their water is not
    std::vector<GroundCover> covers;  ///< above h: not part of it

    // ---- Objects ----
    std::vector<Box> boxes;
    std::vector<Pole> poles;
    std::vector<Wall> walls;

    /// Terrain steeper than this is not traversable: ground truth NonGround, instance 0.
    double max_ground_slope_deg = 25.0;

    double terrainHeight(double x, double y) const;
    /// Analytic gradient of h; vertical faces (step and ramp edges) are ignored.
    Eigen::Vector2d terrainGradient(double x, double y) const;
    /// Angle of the local terrain surface from horizontal [deg], from the analytic gradient.
    double terrainSlopeDeg(double x, double y) const;

    /// Water level of puddle k (world z).
    double waterLevel(std::size_t k) const;

    /// Scene-wide upper bound of h (every positive contribution at its maximum), covers included.
    double terrainUpperBound() const;
    /// Upper bound of h over the axis-aligned rectangle [lo, hi] (conservative, not tight),
    /// the covers' canopies included.
    double terrainUpperBound(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const;

    /// Vertical extent of an object once placed on the terrain. Unless floating (clearance > 0),
    /// the bottom reaches 5 cm below the lowest terrain sampled under the footprint, so no gap
    /// shows on sloped ground.
    ZRange placement(const Box& box) const;
    ZRange placement(const Pole& pole) const;
    ZRange placement(const Wall& wall) const;

    /// Throws std::invalid_argument on a zero instance id, a zero direction, a non-positive size.
    void validate() const;
};

/// Robot base pose on the scene's terrain: x, y, yaw given; z, roll, pitch from the
/// least-squares terrain plane under the footprint (robot-frame corners) and its centre.
/// Returns the rotation (robot -> world) and fills z.
Eigen::Matrix3d robotAttitudeOnTerrain(const Scene& scene,
                                       const std::vector<Eigen::Vector2d>& footprint, double x,
                                       double y, double yaw, double& z);

}  // namespace travel::sim
