// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/TravelObstacles.hpp"

#include "travel/traversability/StaticScene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace travel {

TravelObstacles::TravelObstacles(const NavSection& options) {
    setOptions(options);
}

void TravelObstacles::setOptions(const NavSection& options) {
    options.validate();
    options_ = options;
}

void TravelObstacles::findGroundNodes(const TerrainModel& t) {
    const int n = static_cast<int>(t.nodes.size()), side = t.cells_per_side;
    ground_node_.assign(t.nodes.size(), -1);
    const int reach = static_cast<int>(std::ceil(options_.ground_search_radius / t.resolution));
    const float max_d2 =
        static_cast<float>(options_.ground_search_radius * options_.ground_search_radius);
    for (int k = 0; k < n; ++k) {
        const TriNode& node = t.nodes[k];
        if (t.groundPlane(k)) {
            ground_node_[k] = k;
            continue;
        }
        if (node.count == 0) continue;  // no point will ask
        const int cell = k / 4, cx = cell % side, cy = cell / side;
        const Eigen::Vector2f c = t.cellCenter(cell);
        float best = std::numeric_limits<float>::infinity();
        for (int iy = std::max(0, cy - reach); iy <= std::min(side - 1, cy + reach); ++iy)
            for (int ix = std::max(0, cx - reach); ix <= std::min(side - 1, cx + reach); ++ix) {
                const int other = iy * side + ix;
                const float d2 = (t.cellCenter(other) - c).squaredNorm();
                if (d2 > max_d2 || d2 >= best) continue;
                for (int tri = 0; tri < 4; ++tri)
                    if (t.groundPlane(4 * other + tri)) {
                        best = d2;
                        ground_node_[k] = 4 * other + tri;
                        break;
                    }
            }
    }
}

void TravelObstacles::findSteps(const TerrainModel& t) {
    step_height_.assign(t.nodes.size(), 0.f);
    const int side = t.cells_per_side;
    const float limit = static_cast<float>(options_.max_step_height);
    const float min_spread = static_cast<float>(options_.step_min_spread);
    const auto compare = [&](int a, int b) {
        const float dz = t.stepBetween(a, b, min_spread);
        if (dz > limit) step_height_[a] = std::max(step_height_[a], dz);
        if (-dz > limit) step_height_[b] = std::max(step_height_[b], -dz);
    };
    // Every pair of nodes sharing an edge once: triangles k and k + 1 of a cell, the east
    // triangle and the west one of the next cell, the north triangle and the south one above.
    for (int cy = 0; cy < side; ++cy)
        for (int cx = 0; cx < side; ++cx) {
            const int cell = cy * side + cx;
            for (int k = 0; k < 4; ++k) compare(4 * cell + k, 4 * cell + (k + 1) % 4);
            if (cx + 1 < side) compare(4 * cell + 0, 4 * (cell + 1) + 2);
            if (cy + 1 < side) compare(4 * cell + 1, 4 * (cell + side) + 3);
        }
}

namespace {

/// Robot -> aligned rotation, and the robot origin in the aligned (sensor-centred) frame.
struct RobotInAligned {
    Eigen::Matrix3f R_level;
    Eigen::Vector3f origin;
};

RobotInAligned robotInAligned(const AlignedCloud& aligned,
                              const Eigen::Isometry3f& sensor_on_robot) {
    RobotInAligned r;
    r.R_level = aligned.rotation * sensor_on_robot.linear().transpose();
    r.origin = -(r.R_level * sensor_on_robot.translation());
    return r;
}

/// Cross product of (a - o) and (b - o): > 0 when o, a, b turn counter-clockwise.
float turn(const Eigen::Vector2f& o, const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

/// Convex hull of 8 points (Andrew's monotone chain), counter-clockwise, in `hull`; returns
/// its vertex count. Fixed-size arrays: no allocation.
int convexHull8(std::array<Eigen::Vector2f, 8> p, std::array<Eigen::Vector2f, 16>& hull) {
    std::sort(p.begin(), p.end(), [](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    int k = 0;
    for (int i = 0; i < 8; ++i) {  // lower chain
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], p[i]) <= 0.f) --k;
        hull[k++] = p[i];
    }
    for (int i = 6, lower = k + 1; i >= 0; --i) {  // upper chain
        while (k >= lower && turn(hull[k - 2], hull[k - 1], p[i]) <= 0.f) --k;
        hull[k++] = p[i];
    }
    return k - 1;  // the last point repeats the first
}

}  // namespace

void TravelObstacles::predictMoving(const Result& result, const AlignedCloud& aligned,
                                    const Eigen::Isometry3f& sensor_on_robot,
                                    ObstaclePointCloud& out, float column_step) const {
    const Eigen::Vector3f origin = robotInAligned(aligned, sensor_on_robot).origin;
    const float horizon = static_cast<float>(options_.predict_seconds);
    const float floor_z = static_cast<float>(options_.report_floor);
    const float max_h = static_cast<float>(options_.max_height);
    const float step = std::max(column_step, 0.01f);
    for (const ClusterSummary& c : result.clusters) {
        if (!c.moving || !c.velocity.allFinite() || !c.obb_center.allFinite()) continue;
        // The box now (obb in the aligned frame) and where the velocity takes it.
        const Eigen::Vector2f centre = c.obb_center.head<2>() - origin.head<2>();
        const Eigen::Vector2f u =
            Eigen::Vector2f(std::cos(c.obb_yaw), std::sin(c.obb_yaw)) * (0.5f * c.obb_extent.x());
        const Eigen::Vector2f v =
            Eigen::Vector2f(-u.y(), u.x()).normalized() * (0.5f * c.obb_extent.y());
        const Eigen::Vector2f travel = c.velocity.head<2>() * horizon;
        std::array<Eigen::Vector2f, 8> corners;
        for (int k = 0; k < 4; ++k) {
            const Eigen::Vector2f corner =
                centre + ((k & 1) ? u : Eigen::Vector2f(-u)) + ((k & 2) ? v : Eigen::Vector2f(-v));
            corners[k] = corner, corners[k + 4] = corner + travel;
        }
        std::array<Eigen::Vector2f, 16> hull;
        const int n = convexHull8(corners, hull);  // >= 1 (coincident points: 1 or 2)
        const float top =
            std::isfinite(c.height_above_ground) ? std::min(c.height_above_ground, max_h) : floor_z;
        for (int e = 0; e < n; ++e) {
            const Eigen::Vector2f a = hull[e], d = hull[(e + 1) % n] - a;
            const int pieces = std::max(1, static_cast<int>(std::ceil(d.norm() / kOutlineSpacing)));
            for (int i = 0; i < pieces; ++i) {  // the next edge adds the end vertex
                const Eigen::Vector2f p = a + d * (float(i) / float(pieces));
                for (float z = floor_z; z < top; z += step) out.push_back(p.x(), p.y(), z);
                out.push_back(p.x(), p.y(), std::max(top, floor_z));
            }
        }
    }
}

void TravelObstacles::compute(const Result& result, const AlignedCloud& aligned,
                              const Eigen::Isometry3f& sensor_on_robot, ObstaclePointCloud& out,
                              ObstaclePointCloud* moving) {
    const std::size_t n = aligned.x.size();
    if (result.labels.size() != n || aligned.y.size() != n || aligned.z.size() != n)
        throw std::invalid_argument("travel obstacles: " + std::to_string(result.labels.size()) +
                                    " labels for " + std::to_string(n) + " aligned points");
    const TerrainModel& terrain = result.terrain;
    const bool have_terrain = terrain.usable();
    if (have_terrain) {
        findGroundNodes(terrain);
        findSteps(terrain);
    }

    // Robot -> aligned rotation, and the robot origin and base-plane normal in the aligned
    // (sensor-centred) frame: the fallback ground and the origin of the output xy.
    const RobotInAligned robot = robotInAligned(aligned, sensor_on_robot);
    const Eigen::Vector3f& origin = robot.origin;
    const Eigen::Vector3f base_normal = robot.R_level.col(2);
    const auto baseHeight = [&](float x, float y) {
        return origin.z() -
               (base_normal.x() * (x - origin.x()) + base_normal.y() * (y - origin.y())) /
                   base_normal.z();
    };

    const float max_step = static_cast<float>(options_.max_step_height);
    const float max_h = static_cast<float>(options_.max_height);
    const float floor_z = static_cast<float>(options_.report_floor);
    // Points in a moving cluster's grown footprint are the mover's (StaticScene.hpp).
    if (moving != nullptr)
        movers_.build(result.clusters);
    else
        movers_.build({});
    const auto inMover = [&](const Eigen::Vector3f& a) { return movers_.contains(a.x(), a.y()); };
    for (std::size_t i = 0; i < n; ++i) {
        const PointClass label = result.labels[i];
        if (label != PointClass::Ground && label != PointClass::NonGround) continue;
        const Eigen::Vector3f a(aligned.x[i], aligned.y[i], aligned.z[i]);
        const int node = have_terrain ? terrain.nodeAt(a.x(), a.y()) : -1;
        float h = node >= 0 && label == PointClass::NonGround
                      ? terrain.heightAboveGround(a.x(), a.y(), a.z())
                      : std::numeric_limits<float>::quiet_NaN();
        if (!std::isfinite(h)) {
            const int ground = node >= 0 ? ground_node_[node] : -1;
            h = a.z() - (ground >= 0 ? terrain.groundPlane(ground)->heightAt(a.x(), a.y())
                                     : baseHeight(a.x(), a.y()));
        }
        if (!(h <= max_h)) continue;  // also drops NaN
        const float rx = a.x() - origin.x(), ry = a.y() - origin.y();
        if (label == PointClass::Ground) {
            if (node >= 0 && step_height_[node] > 0.f)
                (!movers_.empty() && inMover(a) ? *moving : out)
                    .push_back(rx, ry, std::max(step_height_[node], floor_z));
            continue;
        }
        const bool steep = node >= 0 && terrain.nodes[node].node_class == NodeClass::Obstacle;
        // In a too-steep node everything above the ground reference is an obstacle; elsewhere
        // only what the robot cannot climb.
        if (!(h > (steep ? floor_z : max_step))) continue;
        const uint32_t id = i < result.cluster_id.size() ? result.cluster_id[i] : 0;
        const bool mover =
            !movers_.empty() &&
            ((id > 0 && id <= result.clusters.size() && result.clusters[id - 1].moving) ||
             inMover(a));
        (mover ? *moving : out).push_back(rx, ry, h);
    }
}

}  // namespace travel
