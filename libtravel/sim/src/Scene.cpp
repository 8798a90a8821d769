// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/sim/Scene.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace travel::sim {
namespace {

// Objects reach this far below the lowest sampled terrain under them, so that terrain between
// the samples cannot open a gap under the object.
constexpr double kObjectSink = 0.05;
// Bumps are cut off beyond 6 sigma, where they are below 2e-8 of their amplitude: saves the exp
// in the ray-marching loop.
constexpr double kBumpCutoffSq = 36.0;

// Coordinates of p in the frame of a feature: u along its direction, v to its left.
struct FeatureFrame {
    Eigen::Vector2d origin;
    Eigen::Vector2d along;
    Eigen::Vector2d left;

    FeatureFrame(const Eigen::Vector2d& start, const Eigen::Vector2d& direction)
        : origin(start), along(direction.normalized()), left(-along.y(), along.x()) {}

    double u(double x, double y) const {
        return (x - origin.x()) * along.x() + (y - origin.y()) * along.y();
    }
    double v(double x, double y) const {
        return (x - origin.x()) * left.x() + (y - origin.y()) * left.y();
    }

    // Ranges of u and v over an axis-aligned rectangle: both are linear, so the corners bound
    // them.
    void ranges(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double& u_min, double& u_max,
                double& v_min, double& v_max) const {
        u_min = v_min = kInfinity;
        u_max = v_max = -kInfinity;
        for (int corner = 0; corner < 4; ++corner) {
            const double x = (corner & 1) ? hi.x() : lo.x();
            const double y = (corner & 2) ? hi.y() : lo.y();
            u_min = std::min(u_min, u(x, y)), u_max = std::max(u_max, u(x, y));
            v_min = std::min(v_min, v(x, y)), v_max = std::max(v_max, v(x, y));
        }
    }
};

double rampHeightAt(const Ramp& ramp, double u) {
    return std::tan(ramp.slope_deg * kDegToRad) * std::min(u, ramp.length);
}

bool insideRamp(const Ramp& ramp, double u, double v) {
    return u >= 0.0 && u <= ramp.length + ramp.plateau_length && std::abs(v) <= 0.5 * ramp.width;
}

bool insideStep(const Step& step, double u, double v) {
    return u >= 0.0 && u <= step.length && std::abs(v) <= 0.5 * step.width;
}

double roughnessWavenumber(const Roughness& roughness) {
    return 2.0 * kPi / roughness.wavelength;
}

// The depth a puddle's bowl presses the terrain at (x, y): depth * (1 - d^2 / radius^2) inside.
double bowlDepth(const Puddle& puddle, double x, double y) {
    const double dx = x - puddle.centre.x(), dy = y - puddle.centre.y();
    const double d2 = (dx * dx + dy * dy) / (puddle.radius * puddle.radius);
    return d2 < 1.0 ? puddle.depth * (1.0 - d2) : 0.0;
}

// Whether two axis-aligned rectangles meet.
bool rectanglesMeet(const Eigen::Vector2d& lo_a, const Eigen::Vector2d& hi_a,
                    const Eigen::Vector2d& lo_b, const Eigen::Vector2d& hi_b) {
    return (lo_a.array() <= hi_b.array()).all() && (lo_b.array() <= hi_a.array()).all();
}

void require(bool condition, const std::string& what) {
    if (!condition) throw std::invalid_argument("travel::sim::Scene: " + what);
}

void requireDirection(const Eigen::Vector2d& direction, const std::string& what) {
    require(direction.allFinite() && direction.norm() > 1e-9, what + " direction is zero");
}

}  // namespace

double Ramp::topHeight() const {
    return std::tan(slope_deg * kDegToRad) * length;
}

double Scene::terrainHeight(double x, double y) const {
    double height = base_height;
    for (const Ramp& ramp : ramps) {
        const FeatureFrame frame(ramp.start, ramp.direction);
        const double u = frame.u(x, y), v = frame.v(x, y);
        if (insideRamp(ramp, u, v)) height += rampHeightAt(ramp, u);
    }
    for (const Step& step : steps) {
        const FeatureFrame frame(step.start, step.direction);
        if (insideStep(step, frame.u(x, y), frame.v(x, y))) height += step.height;
    }
    for (const Bump& bump : bumps) {
        const double dx = x - bump.centre.x(), dy = y - bump.centre.y();
        const double distance_sq = dx * dx + dy * dy, var = bump.sigma * bump.sigma;
        if (distance_sq < kBumpCutoffSq * var) {
            height += bump.amplitude * std::exp(-0.5 * distance_sq / var);
        }
    }
    if (roughness.amplitude != 0.0) {
        const double k = roughnessWavenumber(roughness);
        height += roughness.amplitude * std::sin(k * x) * std::cos(k * y);
    }
    for (const Puddle& puddle : puddles) height -= bowlDepth(puddle, x, y);
    return height;
}

double Scene::waterLevel(std::size_t k) const {
    const Puddle& puddle = puddles.at(k);
    // The bowl presses `depth` at the centre (puddles do not overlap).
    return terrainHeight(puddle.centre.x(), puddle.centre.y()) + puddle.depth - puddle.rim_height;
}

Eigen::Vector2d Scene::terrainGradient(double x, double y) const {
    Eigen::Vector2d gradient(0.0, 0.0);
    for (const Ramp& ramp : ramps) {
        const FeatureFrame frame(ramp.start, ramp.direction);
        const double u = frame.u(x, y), v = frame.v(x, y);
        // The plateau is flat; only the inclined part has a gradient.
        if (insideRamp(ramp, u, v) && u <= ramp.length) {
            gradient += std::tan(ramp.slope_deg * kDegToRad) * frame.along;
        }
    }
    for (const Bump& bump : bumps) {
        const double dx = x - bump.centre.x(), dy = y - bump.centre.y();
        const double inv_var = 1.0 / (bump.sigma * bump.sigma);
        if ((dx * dx + dy * dy) * inv_var >= kBumpCutoffSq) continue;
        const double value = bump.amplitude * std::exp(-0.5 * (dx * dx + dy * dy) * inv_var);
        gradient += -value * inv_var * Eigen::Vector2d(dx, dy);
    }
    if (roughness.amplitude != 0.0) {
        const double k = roughnessWavenumber(roughness);
        const double a = roughness.amplitude * k;
        gradient += Eigen::Vector2d(a * std::cos(k * x) * std::cos(k * y),
                                    -a * std::sin(k * x) * std::sin(k * y));
    }
    for (const Puddle& puddle : puddles) {
        const Eigen::Vector2d d(x - puddle.centre.x(), y - puddle.centre.y());
        const double r2 = puddle.radius * puddle.radius;
        if (d.squaredNorm() < r2) gradient += 2.0 * puddle.depth / r2 * d;
    }
    return gradient;
}

double Scene::terrainSlopeDeg(double x, double y) const {
    return std::atan(terrainGradient(x, y).norm()) / kDegToRad;
}

double Scene::terrainUpperBound() const {
    double bound = base_height + std::abs(roughness.amplitude);
    for (const Ramp& ramp : ramps) bound += std::max(0.0, ramp.topHeight());
    for (const Step& step : steps) bound += std::max(0.0, step.height);
    for (const Bump& bump : bumps) bound += std::max(0.0, bump.amplitude);
    double canopy = 0.0;
    for (const GroundCover& cover : covers) canopy = std::max(canopy, cover.height);
    return bound + canopy;
}

double Scene::terrainUpperBound(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const {
    double bound = base_height + std::abs(roughness.amplitude);
    double u_min, u_max, v_min, v_max;
    for (const Ramp& ramp : ramps) {
        const FeatureFrame frame(ramp.start, ramp.direction);
        frame.ranges(lo, hi, u_min, u_max, v_min, v_max);
        const bool overlaps = u_max >= 0.0 && u_min <= ramp.length + ramp.plateau_length &&
                              v_max >= -0.5 * ramp.width && v_min <= 0.5 * ramp.width;
        // h grows with u along a rising ramp, so the largest reachable u bounds it.
        if (overlaps) bound += std::max(0.0, rampHeightAt(ramp, std::max(u_max, 0.0)));
    }
    for (const Step& step : steps) {
        const FeatureFrame frame(step.start, step.direction);
        frame.ranges(lo, hi, u_min, u_max, v_min, v_max);
        const bool overlaps = u_max >= 0.0 && u_min <= step.length && v_max >= -0.5 * step.width &&
                              v_min <= 0.5 * step.width;
        if (overlaps) bound += std::max(0.0, step.height);
    }
    for (const Bump& bump : bumps) {
        if (bump.amplitude <= 0.0) continue;
        // Distance from the centre to the nearest point of the rectangle.
        const double dx = std::max({lo.x() - bump.centre.x(), 0.0, bump.centre.x() - hi.x()});
        const double dy = std::max({lo.y() - bump.centre.y(), 0.0, bump.centre.y() - hi.y()});
        bound += bump.amplitude * std::exp(-(dx * dx + dy * dy) / (2.0 * bump.sigma * bump.sigma));
    }
    double canopy = 0.0;
    for (const GroundCover& cover : covers)
        if (rectanglesMeet(cover.lo, cover.hi, lo, hi)) canopy = std::max(canopy, cover.height);
    return bound + canopy;
}

ZRange Scene::placement(const Box& box) const {
    const double c = std::cos(box.yaw_deg * kDegToRad), s = std::sin(box.yaw_deg * kDegToRad);
    const double ground = terrainHeight(box.centre.x(), box.centre.y());
    double lowest = ground;
    for (int corner = 0; corner < 4; ++corner) {
        const double along = ((corner & 1) ? 0.5 : -0.5) * box.length;
        const double across = ((corner & 2) ? 0.5 : -0.5) * box.width;
        lowest = std::min(lowest, terrainHeight(box.centre.x() + c * along - s * across,
                                                box.centre.y() + s * along + c * across));
    }
    const double top = ground + box.clearance + box.height;
    if (box.clearance > 0.0) return {ground + box.clearance, top};
    return {lowest - kObjectSink, top};
}

ZRange Scene::placement(const Pole& pole) const {
    const double ground = terrainHeight(pole.centre.x(), pole.centre.y());
    double lowest = ground;
    constexpr int kRimSamples = 8;
    for (int i = 0; i < kRimSamples; ++i) {
        const double angle = 2.0 * kPi * i / kRimSamples;
        lowest = std::min(lowest, terrainHeight(pole.centre.x() + pole.radius * std::cos(angle),
                                                pole.centre.y() + pole.radius * std::sin(angle)));
    }
    return {lowest - kObjectSink, ground + pole.height};
}

ZRange Scene::placement(const Wall& wall) const {
    const Eigen::Vector2d midpoint = 0.5 * (wall.a + wall.b);
    const Eigen::Vector2d along = wall.b - wall.a;
    const Eigen::Vector2d left = Eigen::Vector2d(-along.y(), along.x()).normalized();
    // Sample both long faces about every half metre: walls can be long and cross bumps.
    const int samples = 1 + static_cast<int>(std::ceil(along.norm() / 0.5));
    double lowest = terrainHeight(midpoint.x(), midpoint.y());
    for (int i = 0; i <= samples; ++i) {
        const Eigen::Vector2d p = wall.a + along * (static_cast<double>(i) / samples);
        for (double side : {-0.5, 0.5}) {
            const Eigen::Vector2d q = p + side * wall.thickness * left;
            lowest = std::min(lowest, terrainHeight(q.x(), q.y()));
        }
    }
    return {lowest - kObjectSink, terrainHeight(midpoint.x(), midpoint.y()) + wall.height};
}

void Scene::validate() const {
    require(std::isfinite(base_height), "base_height is not finite");
    require(max_ground_slope_deg >= 0.0 && max_ground_slope_deg <= 90.0,
            "max_ground_slope_deg must be in [0, 90]");
    for (const Ramp& ramp : ramps) {
        requireDirection(ramp.direction, "ramp");
        require(ramp.length > 0.0 && ramp.width > 0.0, "ramp length and width must be > 0");
        require(ramp.plateau_length >= 0.0, "ramp plateau_length must be >= 0");
        require(std::abs(ramp.slope_deg) < 90.0, "ramp slope_deg must be in (-90, 90)");
    }
    for (const Step& step : steps) {
        requireDirection(step.direction, "step");
        require(step.length > 0.0 && step.width > 0.0, "step length and width must be > 0");
        require(std::isfinite(step.height), "step height is not finite");
    }
    for (const Bump& bump : bumps) {
        require(bump.sigma > 0.0, "bump sigma must be > 0");
        require(std::isfinite(bump.amplitude), "bump amplitude is not finite");
    }
    require(roughness.amplitude == 0.0 || roughness.wavelength > 0.0,
            "roughness wavelength must be > 0");
    for (const Puddle& puddle : puddles) {
        require(puddle.radius > 0.0 && puddle.depth >= 0.0,
                "puddle radius must be > 0, depth >= 0");
        require(puddle.mirror_fraction >= 0.0 && puddle.mirror_fraction <= 1.0,
                "puddle mirror_fraction must be in [0, 1]");
    }
    for (const GroundCover& cover : covers) {
        require((cover.lo.array() < cover.hi.array()).all() && cover.height >= 0.0,
                "cover needs lo < hi and height >= 0");
        require(cover.return_fraction >= 0.0 && cover.return_fraction <= 1.0,
                "cover return_fraction must be in [0, 1]");
    }
    for (const Box& box : boxes) {
        require(box.id > 0, "box instance id must be > 0");
        require(box.length > 0.0 && box.width > 0.0 && box.height > 0.0,
                "box dimensions must be > 0");
        require(box.clearance >= 0.0, "box clearance must be >= 0");
        require(box.return_fraction >= 0.0 && box.return_fraction <= 1.0,
                "box return_fraction must be in [0, 1]");
        require(box.velocity.allFinite(), "box velocity must be finite");
    }
    for (const Pole& pole : poles) {
        require(pole.id > 0, "pole instance id must be > 0");
        require(pole.radius > 0.0 && pole.height > 0.0, "pole radius and height must be > 0");
    }
    for (const Wall& wall : walls) {
        require(wall.id > 0, "wall instance id must be > 0");
        requireDirection(wall.b - wall.a, "wall");
        require(wall.thickness > 0.0 && wall.height > 0.0, "wall thickness and height must be > 0");
    }
}

Eigen::Matrix3d robotAttitudeOnTerrain(const Scene& scene,
                                       const std::vector<Eigen::Vector2d>& footprint, double x,
                                       double y, double yaw, double& z) {
    // Least-squares plane z = a + b dx + c dy through the footprint corners and the centre.
    Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
    Eigen::Vector3d Atb = Eigen::Vector3d::Zero();
    const double cy = std::cos(yaw), sy = std::sin(yaw);
    const auto add = [&](double dx, double dy) {
        const Eigen::Vector3d row(1.0, dx, dy);
        AtA += row * row.transpose();
        Atb += row * scene.terrainHeight(x + dx, y + dy);
    };
    add(0.0, 0.0);
    for (const auto& p : footprint) add(cy * p.x() - sy * p.y(), sy * p.x() + cy * p.y());
    const Eigen::Vector3d abc = AtA.ldlt().solve(Atb);
    z = abc[0];
    const Eigen::Vector3d n = Eigen::Vector3d(-abc[1], -abc[2], 1.0).normalized();
    Eigen::Vector3d f(cy, sy, abc[1] * cy + abc[2] * sy);  // heading, on the plane
    f.normalize();
    Eigen::Matrix3d R;
    R.col(0) = f;
    R.col(1) = n.cross(f);
    R.col(2) = n;
    return R;
}

}  // namespace travel::sim
