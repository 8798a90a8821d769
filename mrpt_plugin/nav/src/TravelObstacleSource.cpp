// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TravelObstacleSource.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace travel_mrpt {
namespace {

using travel::NodeClass;
using travel::PointClass;
using travel::TerrainModel;
using travel::TriNode;

/// The plane TRAVEL labels with: the TTMF refit when there is one, else the node's own fit.
float groundHeight(const TriNode& n, float x, float y) {
    if (n.refitted && n.refit_normal.z() > 0.1f)
        return travel::planeHeightAt(n.refit_normal, n.refit_d, x, y);
    return travel::planeHeightAt(n.normal, n.d, x, y);
}

/// Node of (x, y) (same rule as TriGridField::nodeOf), -1 outside the grid.
int nodeAt(const TerrainModel& t, float x, float y) {
    const float gx = (x - t.origin_xy) / t.resolution, gy = (y - t.origin_xy) / t.resolution;
    const float limit = static_cast<float>(t.cells_per_side);
    if (!(gx >= 0.f && gy >= 0.f && gx < limit && gy < limit)) return -1;
    const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
    const float u = gx - (static_cast<float>(ix) + 0.5f), v = gy - (static_cast<float>(iy) + 0.5f);
    const int tri = std::fabs(u) >= std::fabs(v) ? (u < 0.f ? 2 : 0) : (v < 0.f ? 3 : 1);
    return 4 * (iy * t.cells_per_side + ix) + tri;
}

/// A node whose plane is a ground reference: traversable and not too steep (TTMF also marks
/// steep nodes such as kerb faces traversable; their planes are not the ground).
bool isGround(const TriNode& n) {
    return n.traversable && n.node_class == NodeClass::Terrain;
}

bool usableTerrain(const TerrainModel& t) {
    return t.cells_per_side > 0 && t.resolution > 0.f &&
           t.nodes.size() == 4u * static_cast<std::size_t>(t.cells_per_side) *
                                 static_cast<std::size_t>(t.cells_per_side);
}

}  // namespace

TravelObstacleSource::TravelObstacleSource(const TravelObstacleOptions& options) {
    setOptions(options);
}

void TravelObstacleSource::setOptions(const TravelObstacleOptions& o) {
    if (!(o.max_step_height >= 0) || !(o.max_height > 0) || !(o.report_floor >= 0.01) ||
        !(o.ground_search_radius >= 0) || !(o.step_min_spread >= 0))
        throw std::invalid_argument(
            "TravelObstacleSource: need max_step_height >= 0, max_height > 0, report_floor >= "
            "0.01 m (the navigator drops lower points), ground_search_radius >= 0, step_min_spread "
            ">= 0");
    options_ = o;
}

void TravelObstacleSource::findGroundNodes(const TerrainModel& t) {
    const int n = static_cast<int>(t.nodes.size()), side = t.cells_per_side;
    ground_node_.assign(t.nodes.size(), -1);
    const int reach = static_cast<int>(std::ceil(options_.ground_search_radius / t.resolution));
    const float max_d2 =
        static_cast<float>(options_.ground_search_radius * options_.ground_search_radius);
    for (int k = 0; k < n; ++k) {
        const TriNode& node = t.nodes[k];
        if (isGround(node)) {
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
                    if (isGround(t.nodes[4 * other + tri])) {
                        best = d2;
                        ground_node_[k] = 4 * other + tri;
                        break;
                    }
            }
    }
}

void TravelObstacleSource::findSteps(const TerrainModel& t) {
    step_height_.assign(t.nodes.size(), 0.f);
    const int side = t.cells_per_side;
    const float h = 0.5f * t.resolution, limit = static_cast<float>(options_.max_step_height);
    // A plane through one ring's arc (a line) or a small patch is only known there: its tilt
    // across is an assumption (TRAVEL levels line nodes) or noise.
    const float min_l2 = static_cast<float>(options_.step_min_spread * options_.step_min_spread);
    const auto spread = [&](const TriNode& n) { return n.eigenvalues.y() >= min_l2; };
    // Each node's OWN plane (TTMF smooths steps away). A step of a over b must show three
    // times: a's plane above b's at the midpoint of their shared edge (where both planes meet
    // on a bend, such as the foot of a ramp), a's seen ground (its mean) above b's plane, and
    // b's seen ground below a's plane. A plane is only known where its points are: a node
    // that the LiDAR sees in a small patch (next to the blind zone around the robot, or beside
    // a kerb's shadow) gets a tilt from noise, and that plane extrapolated to the edge can
    // stand 0.15 m off the true slope; the seen-ground measures, which use the other node's
    // plane at this node's own points, veto such steps.
    const auto compare = [&](int a, int b, float x, float y) {
        const TriNode &na = t.nodes[a], &nb = t.nodes[b];
        if (!isGround(na) || !isGround(nb) || !spread(na) || !spread(nb)) return;
        const float edge = travel::planeHeightAt(na.normal, na.d, x, y) -
                           travel::planeHeightAt(nb.normal, nb.d, x, y);
        if (!(std::fabs(edge) > limit)) return;
        const float a_over_b =
            na.mean.z() - travel::planeHeightAt(nb.normal, nb.d, na.mean.x(), na.mean.y());
        const float b_under_a =
            travel::planeHeightAt(na.normal, na.d, nb.mean.x(), nb.mean.y()) - nb.mean.z();
        if (edge > 0.f) {
            const float dz = std::min({edge, a_over_b, b_under_a});
            if (dz > limit) step_height_[a] = std::max(step_height_[a], dz);
        } else {
            const float dz = std::min({-edge, -a_over_b, -b_under_a});
            if (dz > limit) step_height_[b] = std::max(step_height_[b], dz);
        }
    };
    // Corners between triangle k and k + 1 (east/north, north/west, west/south, south/east).
    static constexpr float kCorner[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (int cy = 0; cy < side; ++cy)
        for (int cx = 0; cx < side; ++cx) {
            const int cell = cy * side + cx;
            const Eigen::Vector2f c = t.cellCenter(cell);
            for (int k = 0; k < 4; ++k)
                compare(4 * cell + k, 4 * cell + (k + 1) % 4, c.x() + 0.5f * h * kCorner[k][0],
                        c.y() + 0.5f * h * kCorner[k][1]);
            if (cx + 1 < side) compare(4 * cell + 0, 4 * (cell + 1) + 2, c.x() + h, c.y());
            if (cy + 1 < side) compare(4 * cell + 1, 4 * (cell + side) + 3, c.x(), c.y() + h);
        }
}

void TravelObstacleSource::compute(const ObstacleFrame& frame, ObstaclePoints& out) {
    const travel::PointCloud& cloud = *frame.cloud;
    if (frame.result == nullptr)
        throw std::invalid_argument("travel obstacle source: the frame has no TRAVEL result");
    const travel::Result& result = *frame.result;
    if (result.labels.size() != cloud.size())
        throw std::invalid_argument(
            "travel obstacle source: " + std::to_string(result.labels.size()) + " labels for " +
            std::to_string(cloud.size()) + " points");
    const TerrainModel& terrain = result.terrain;
    const bool have_terrain = usableTerrain(terrain);
    if (have_terrain) {
        findGroundNodes(terrain);
        findSteps(terrain);
    }

    // Robot -> aligned rotation, and the robot origin and base-plane normal in the aligned
    // (sensor-centred) frame: the fallback ground and the origin of the output xy.
    const Eigen::Matrix3f R_level =
        frame.alignedRotation * frame.sensorOnRobot.linear().transpose();
    const Eigen::Vector3f origin = -(R_level * frame.sensorOnRobot.translation());
    const Eigen::Vector3f base_normal = R_level.col(2);
    const auto baseHeight = [&](float x, float y) {
        return origin.z() -
               (base_normal.x() * (x - origin.x()) + base_normal.y() * (y - origin.y())) /
                   base_normal.z();
    };

    const float max_step = static_cast<float>(options_.max_step_height);
    const float max_h = static_cast<float>(options_.max_height);
    const float floor_z = static_cast<float>(options_.report_floor);
    const Eigen::Matrix3f& A = frame.alignedRotation;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const PointClass label = result.labels[i];
        if (label != PointClass::Ground && label != PointClass::NonGround) continue;
        const Eigen::Vector3f a = A * Eigen::Vector3f(cloud.x[i], cloud.y[i], cloud.z[i]);
        const int node = have_terrain ? nodeAt(terrain, a.x(), a.y()) : -1;
        float h = std::numeric_limits<float>::infinity();
        if (node >= 0 && label == PointClass::NonGround) {
            // The lowest height over the ground planes of this cell and its 4 neighbours: where
            // the terrain bends (the foot of a ramp), one node's plane extrapolated across the
            // bend would lift the ground ahead above max_step_height.
            const int side = terrain.cells_per_side, cell = node / 4;
            const int cx = cell % side, cy = cell / side;
            static constexpr int kAround[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            for (const auto& d : kAround) {
                const int ix = cx + d[0], iy = cy + d[1];
                if (ix < 0 || iy < 0 || ix >= side || iy >= side) continue;
                for (int tri = 0; tri < 4; ++tri) {
                    const TriNode& n = terrain.nodes[4 * (iy * side + ix) + tri];
                    if (isGround(n)) h = std::min(h, a.z() - groundHeight(n, a.x(), a.y()));
                }
            }
        }
        if (!std::isfinite(h)) {
            const int ground = node >= 0 ? ground_node_[node] : -1;
            h = a.z() - (ground >= 0 ? groundHeight(terrain.nodes[ground], a.x(), a.y())
                                     : baseHeight(a.x(), a.y()));
        }
        if (!(h <= max_h)) continue;  // also drops NaN
        const float rx = a.x() - origin.x(), ry = a.y() - origin.y();
        if (label == PointClass::Ground) {
            if (node >= 0 && step_height_[node] > 0.f)
                out.push_back(rx, ry, std::max(step_height_[node], floor_z));
            continue;
        }
        const bool steep = node >= 0 && terrain.nodes[node].node_class == NodeClass::Obstacle;
        // In a too-steep node everything above the ground reference is an obstacle; elsewhere
        // only what the robot cannot climb.
        if (h > (steep ? floor_z : max_step)) out.push_back(rx, ry, h);
    }
}

}  // namespace travel_mrpt
