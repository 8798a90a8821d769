// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/TravelObstacles.hpp"

#include <algorithm>
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

void TravelObstacles::compute(const Result& result, const AlignedCloud& aligned,
                              const Eigen::Isometry3f& sensor_on_robot, ObstaclePointCloud& out) {
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
    const Eigen::Matrix3f R_level = aligned.rotation * sensor_on_robot.linear().transpose();
    const Eigen::Vector3f origin = -(R_level * sensor_on_robot.translation());
    const Eigen::Vector3f base_normal = R_level.col(2);
    const auto baseHeight = [&](float x, float y) {
        return origin.z() -
               (base_normal.x() * (x - origin.x()) + base_normal.y() * (y - origin.y())) /
                   base_normal.z();
    };

    const float max_step = static_cast<float>(options_.max_step_height);
    const float max_h = static_cast<float>(options_.max_height);
    const float floor_z = static_cast<float>(options_.report_floor);
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
                out.push_back(rx, ry, std::max(step_height_[node], floor_z));
            continue;
        }
        const bool steep = node >= 0 && terrain.nodes[node].node_class == NodeClass::Obstacle;
        // In a too-steep node everything above the ground reference is an obstacle; elsewhere
        // only what the robot cannot climb.
        if (h > (steep ? floor_z : max_step)) out.push_back(rx, ry, h);
    }
}

}  // namespace travel
