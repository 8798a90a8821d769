// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/GridPathPlanner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace travel {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
}

void GridPathPlanner::setGrid(const GridGeometry& geometry, const std::vector<CellState>& states,
                              const std::vector<float>& slopes_deg) {
    geometry_ = geometry;
    sx_ = geometry.sizeX(), sy_ = geometry.sizeY();
    states_ = states;
    slopes_ = slopes_deg;
    slopes_.resize(states_.size(), std::numeric_limits<float>::quiet_NaN());
    distance_.assign(states_.size(), kInf);
    const double res = geometry_.resolution;
    const int reach = int(std::ceil(options_.comfort_radius / res));
    for (int iy = 0; iy < sy_; ++iy)
        for (int ix = 0; ix < sx_; ++ix) {
            if (states_[std::size_t(iy) * sx_ + ix] != CellState::Obstacle) continue;
            for (int dy = -reach; dy <= reach; ++dy) {
                const int y = iy + dy;
                if (y < 0 || y >= sy_) continue;
                for (int dx = -reach; dx <= reach; ++dx) {
                    const int x = ix + dx;
                    if (x < 0 || x >= sx_) continue;
                    float& d = distance_[std::size_t(y) * sx_ + x];
                    d = std::min(d, float(res * std::sqrt(double(dx * dx + dy * dy))));
                }
            }
        }
}

long GridPathPlanner::cellOf(const Eigen::Vector2d& p) const {
    const double res = geometry_.resolution;
    const int ix = int(std::floor((p.x() - geometry_.min_x) / res));
    const int iy = int(std::floor((p.y() - geometry_.min_y) / res));
    if (ix < 0 || iy < 0 || ix >= sx_ || iy >= sy_) return -1;
    return long(iy) * sx_ + ix;
}

float GridPathPlanner::cellCost(long cell) const {
    const float d = distance_[cell];
    if (d < float(options_.robot_radius)) return -1.f;
    float cost = 1.f;
    if (states_[cell] == CellState::Unknown) cost += float(options_.unknown_cost);
    const float slope = slopes_[cell];
    if (std::isfinite(slope)) {
        if (slope > float(options_.max_slope_deg)) return -1.f;
        cost += float(options_.slope_cost) * std::max(0.f, slope) / float(options_.max_slope_deg);
    }
    if (d < float(options_.comfort_radius))
        cost += float(options_.proximity_cost) *
                (1.f - (d - float(options_.robot_radius)) /
                           float(options_.comfort_radius - options_.robot_radius));
    return cost;
}

bool GridPathPlanner::plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                           std::vector<Eigen::Vector2d>& path) {
    path.clear();
    expanded_ = 0;
    const long s = cellOf(start), t = cellOf(goal);
    if (s < 0 || t < 0) return false;
    const std::size_t n = states_.size();
    g_.assign(n, kInf);
    parent_.assign(n, -1);
    closed_.assign(n, 0);
    const double res = geometry_.resolution;
    const double near2 = options_.robot_radius * options_.robot_radius;
    const auto centre = [&](long c) {
        return Eigen::Vector2d(geometry_.min_x + (double(c % sx_) + 0.5) * res,
                               geometry_.min_y + (double(c / sx_) + 0.5) * res);
    };
    // Entering a cell: its cost factor; near the start or the goal inflated cells are allowed
    // (the robot may already stand closer to an obstacle than robot_radius).
    const auto factor = [&](long c) -> float {
        const float f = cellCost(c);
        if (f > 0.f) return f;
        if (states_[c] == CellState::Obstacle) return -1.f;
        const Eigen::Vector2d p = centre(c);
        if ((p - start).squaredNorm() <= near2 || (p - goal).squaredNorm() <= near2)
            return 1.f + float(options_.proximity_cost);
        return -1.f;
    };
    // Octile distance: admissible with every cost factor >= 1.
    const auto heuristic = [&](long c) {
        const double dx = std::abs(double(c % sx_ - t % sx_)),
                     dy = std::abs(double(c / sx_ - t / sx_));
        return float(res * (std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy)));
    };
    using Entry = std::pair<float, long>;  // f = g + h, cell
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    g_[s] = 0.f;
    open.push({heuristic(s), s});
    static constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
    static constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    while (!open.empty()) {
        const long c = open.top().second;
        open.pop();
        if (closed_[c]) continue;
        closed_[c] = 1;
        ++expanded_;
        if (c == t) break;
        const int cx = int(c % sx_), cy = int(c / sx_);
        for (int k = 0; k < 8; ++k) {
            const int x = cx + kDx[k], y = cy + kDy[k];
            if (x < 0 || y < 0 || x >= sx_ || y >= sy_) continue;
            const long m = long(y) * sx_ + x;
            if (closed_[m]) continue;
            const float f = factor(m);
            if (f < 0.f) continue;
            const float g = g_[c] + f * float(res * (k < 4 ? 1.0 : std::sqrt(2.0)));
            if (g < g_[m]) {
                g_[m] = g, parent_[m] = int32_t(c);
                open.push({g + heuristic(m), m});
            }
        }
    }
    if (!closed_[t]) return false;
    for (long c = t; c >= 0; c = parent_[c]) path.push_back(centre(c));
    std::reverse(path.begin(), path.end());
    path.back() = goal;
    return true;
}

bool GridPathPlanner::blocked(const std::vector<Eigen::Vector2d>& path, std::size_t from,
                              const Eigen::Vector2d& robot) const {
    const double near2 = options_.robot_radius * options_.robot_radius;
    for (std::size_t i = from; i < path.size(); ++i) {
        if ((path[i] - robot).squaredNorm() <= near2) continue;
        const long c = cellOf(path[i]);
        if (c >= 0 && cellCost(c) < 0.f &&
            (i + 1 < path.size() || states_[c] == CellState::Obstacle))
            return true;
    }
    return false;
}

std::vector<Eigen::Vector2d> GridPathPlanner::waypoints(
    const std::vector<Eigen::Vector2d>& path) const {
    std::vector<Eigen::Vector2d> out;
    double along = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        along += (path[i] - path[i - 1]).norm();
        if (along >= options_.waypoint_spacing && i + 1 < path.size()) {
            out.push_back(path[i]);
            along = 0.0;
        }
    }
    if (!path.empty()) out.push_back(path.back());
    return out;
}

}  // namespace travel
