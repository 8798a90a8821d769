// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TraversabilityGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "travel/Errors.hpp"

namespace travel_mrpt {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kDegToRad = 3.14159265358979f / 180.f;
constexpr uint32_t kStepReferencePoints = 2;  ///< ground points a step reference cell needs
constexpr int kStepRadius = 2;                ///< [cells] neighbourhood of the step rule
constexpr float kMaxPairDistance = 4.f;       ///< [cells] farthest pair of the step rule

void require(bool ok, const std::string& what) {
    if (!ok) throw travel::ConfigError(what);
}

}  // namespace

int GridGeometry::sizeX() const {
    return static_cast<int>(std::ceil((max_x - min_x) / resolution - 1e-9));
}
int GridGeometry::sizeY() const {
    return static_cast<int>(std::ceil((max_y - min_y) / resolution - 1e-9));
}

void GridGeometry::validate() const {
    require(std::isfinite(min_x) && std::isfinite(max_x) && min_x < max_x,
            "min_x/max_x: need finite min_x < max_x [m]");
    require(std::isfinite(min_y) && std::isfinite(max_y) && min_y < max_y,
            "min_y/max_y: need finite min_y < max_y [m]");
    require(std::isfinite(resolution) && resolution > 0, "resolution: must be > 0 [m]");
    require((max_x - min_x) / resolution <= 16384 && (max_y - min_y) / resolution <= 16384,
            "resolution: the grid would exceed 16384 x 16384 cells (enlarge the resolution or "
            "shrink the extent)");
}

void GridFusionParams::validate() const {
    require(std::isfinite(logodds_obstacle) && logodds_obstacle > 0,
            "logodds_obstacle: must be > 0");
    require(std::isfinite(logodds_ground) && logodds_ground < 0, "logodds_ground: must be < 0");
    require(std::isfinite(logodds_min) && logodds_min < 0, "logodds_min: must be < 0");
    require(std::isfinite(logodds_max) && logodds_max > 0, "logodds_max: must be > 0");
    require(obstacle_threshold >= 0 && obstacle_threshold < logodds_max,
            "obstacle_threshold: must be in [0, logodds_max)");
    require(free_threshold <= 0 && free_threshold > logodds_min,
            "free_threshold: must be in (logodds_min, 0]");
    require(min_obstacle_points >= 1, "min_obstacle_points: must be >= 1");
    require(min_step_points >= 2, "min_step_points: must be >= 2");
    require(std::isfinite(max_step_height) && max_step_height > 0,
            "max_step_height: must be > 0 [m]");
    require(std::isfinite(max_neighbour_step) && max_neighbour_step >= 0,
            "max_neighbour_step: must be >= 0 [m] (0 = off)");
    require(max_slope_deg > 0 && max_slope_deg < 90, "max_slope_deg: must be in (0, 90) [deg]");
}

const char* toString(CellState state) {
    switch (state) {
        case CellState::Unknown:
            return "unknown";
        case CellState::Traversable:
            return "traversable";
        case CellState::Obstacle:
            return "obstacle";
    }
    return "?";
}

void TraversabilityGrid::reset(const GridGeometry& geometry) {
    geometry.validate();
    geometry_ = geometry;
    size_x_ = geometry.sizeX();
    size_y_ = geometry.sizeY();
    const std::size_t n = std::size_t(size_x_) * std::size_t(size_y_);
    logodds_.assign(n, 0.f);
    ground_count_.assign(n, 0);
    ground_mean_.assign(n, 0.f);
    ground_m2_.assign(n, 0.f);
    slope_sum_.assign(n, 0.f);
    step_height_.assign(n, 0.f);
    obstacle_frames_.assign(n, 0.f);
    frames_seen_.assign(n, 0);
    last_seen_.assign(n, 0.0);
    frame_slot_.assign(n, -1);
    frame_touched_.clear();
    frame_cells_.clear();
    observed_cells_ = 0;
}

void TraversabilityGrid::clear() {
    reset(geometry_);
}

long TraversabilityGrid::cellIndex(double x, double y) const {
    const double fx = (x - geometry_.min_x) / geometry_.resolution;
    const double fy = (y - geometry_.min_y) / geometry_.resolution;
    if (!(fx >= 0 && fy >= 0 && fx < size_x_ && fy < size_y_)) return -1;  // also NaN
    return long(fy) * size_x_ + long(fx);
}

void TraversabilityGrid::beginFrame() {
    for (long cell : frame_touched_) frame_slot_[cell] = -1;
    frame_touched_.clear();
    frame_cells_.clear();  // keeps capacity
}

TraversabilityGrid::FrameCell& TraversabilityGrid::frameCell(long cell) {
    int32_t& slot = frame_slot_[cell];
    if (slot < 0) {
        slot = static_cast<int32_t>(frame_cells_.size());
        FrameCell fresh;
        fresh.z_low[0] = fresh.z_low[1] = std::numeric_limits<float>::infinity();
        fresh.z_high[0] = fresh.z_high[1] = -std::numeric_limits<float>::infinity();
        frame_cells_.push_back(fresh);
        frame_touched_.push_back(cell);
    }
    return frame_cells_[slot];
}

void TraversabilityGrid::addGround(double x, double y, float z, float slope_deg) {
    const long cell = cellIndex(x, y);
    if (cell < 0 || !std::isfinite(z)) return;
    FrameCell& f = frameCell(cell);
    ++f.ground;
    if (z < f.z_low[1]) f.z_low[1] = z;
    if (f.z_low[1] < f.z_low[0]) std::swap(f.z_low[0], f.z_low[1]);
    if (z > f.z_high[1]) f.z_high[1] = z;
    if (f.z_high[1] > f.z_high[0]) std::swap(f.z_high[0], f.z_high[1]);
    // Welford: running mean and sum of squared deviations over all frames.
    const uint32_t n = ++ground_count_[cell];
    const float delta = z - ground_mean_[cell];
    ground_mean_[cell] += delta / float(n);
    ground_m2_[cell] += delta * (z - ground_mean_[cell]);
    slope_sum_[cell] += std::isfinite(slope_deg) ? slope_deg : 0.f;
}

void TraversabilityGrid::addObstacle(double x, double y) {
    const long cell = cellIndex(x, y);
    if (cell >= 0) ++frameCell(cell).obstacle;
}

std::size_t TraversabilityGrid::endFrame(double time_s, const GridFusionParams& fusion) {
    std::size_t updated = 0;
    const float diagonal = float(geometry_.resolution) * 1.41421356f;
    for (std::size_t k = 0; k < frame_touched_.size(); ++k) {
        const long cell = frame_touched_[k];
        const FrameCell& f = frame_cells_[k];
        const bool obstacle = f.obstacle >= uint32_t(fusion.min_obstacle_points);
        if (!obstacle && f.ground == 0) continue;  // too few obstacle points: no evidence
        float& l = logodds_[cell];
        l += obstacle ? fusion.logodds_obstacle : fusion.logodds_ground;
        l = std::clamp(l, fusion.logodds_min, fusion.logodds_max);
        if (obstacle) obstacle_frames_[cell] += 1.f;
        if (f.ground >= uint32_t(fusion.min_step_points)) {
            // Second-lowest to second-highest: one stray point cannot make a step. The rise a
            // sloped plane has across the cell is not a step.
            const float slope = slopeDeg(cell);
            const float rise = diagonal * std::tan(std::min(slope, 80.f) * kDegToRad);
            const float step = (f.z_high[1] - f.z_low[1]) - (std::isfinite(rise) ? rise : 0.f);
            step_height_[cell] = std::max(step_height_[cell], step);
        }
        if (frames_seen_[cell]++ == 0) ++observed_cells_;
        last_seen_[cell] = time_s;
        ++updated;
    }
    return updated;
}

bool TraversabilityGrid::stepReference(long cell, const GridFusionParams& fusion) const {
    return ground_count_[cell] >= kStepReferencePoints && logodds_[cell] < fusion.free_threshold;
}

float TraversabilityGrid::neighbourStep(long cell, const GridFusionParams& fusion) const {
    if (cell < 0 || std::size_t(cell) >= logodds_.size()) return 0.f;
    const int ix = int(cell % size_x_), iy = int(cell / size_x_);
    const float r = float(geometry_.resolution);
    const float max_slope = std::min(fusion.max_slope_deg, 80.f);
    // The rise a slope explains over `distance` cells: the mean terrain-model slope of the two
    // cells (capped at max_slope_deg: a steeper slope is not traversable anyway), so that a
    // ramp's foot and top (a flat and a sloped cell) are not steps.
    const auto rise = [&](long a, long b, float distance) {
        float slope = 0.5f * (slopeDeg(a) + slopeDeg(b));
        if (!std::isfinite(slope)) slope = 0.f;
        return distance * r * std::tan(std::clamp(slope, 0.f, max_slope) * kDegToRad);
    };
    // Reference cells within kStepRadius cells (Chebyshev), with their offsets.
    struct Ref {
        long cell;
        int dx, dy;
    };
    Ref refs[(2 * kStepRadius + 1) * (2 * kStepRadius + 1)];
    int count = 0;
    for (int dy = -kStepRadius; dy <= kStepRadius; ++dy)
        for (int dx = -kStepRadius; dx <= kStepRadius; ++dx) {
            const int x = ix + dx, y = iy + dy;
            if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= size_x_ || y >= size_y_) continue;
            const long n = cellIndex(x, y);
            if (stepReference(n, fusion)) refs[count++] = {n, dx, dy};
        }
    const bool own = stepReference(cell, fusion);
    const float h = ground_mean_[cell];
    float step = 0.f;
    for (int i = 0; i < count; ++i) {
        const Ref& a = refs[i];
        // This cell and a reference: the edge lies between them.
        if (own && std::abs(a.dx) + std::abs(a.dy) == 1)
            step = std::max(step, std::abs(h - ground_mean_[a.cell]) -
                                      rise(cell, a.cell, std::hypot(float(a.dx), float(a.dy))));
        // Two references on opposite sides of this cell: the edge lies inside this cell when
        // its own height is between theirs (a cell holding both levels) or it has no ground.
        for (int j = i + 1; j < count; ++j) {
            const Ref& b = refs[j];
            const float dot = float(a.dx * b.dx + a.dy * b.dy);
            const float la = std::hypot(float(a.dx), float(a.dy));
            const float lb = std::hypot(float(b.dx), float(b.dy));
            if (dot > -0.9f * la * lb) continue;  // not on opposite sides (within ~25 deg)
            const float lo = std::min(ground_mean_[a.cell], ground_mean_[b.cell]);
            const float hi = std::max(ground_mean_[a.cell], ground_mean_[b.cell]);
            constexpr float kTolerance = 0.02f;  // [m]
            if (ground_count_[cell] > 0 && (h < lo - kTolerance || h > hi + kTolerance)) continue;
            const float dist = std::hypot(float(a.dx - b.dx), float(a.dy - b.dy));
            if (dist > kMaxPairDistance) continue;
            step = std::max(step, (hi - lo) - rise(a.cell, b.cell, dist));
        }
    }
    return step;
}

CellState TraversabilityGrid::state(long cell, const GridFusionParams& fusion) const {
    if (cell < 0 || std::size_t(cell) >= logodds_.size() || frames_seen_[cell] == 0)
        return CellState::Unknown;
    const float l = logodds_[cell];
    if (l > fusion.obstacle_threshold) return CellState::Obstacle;
    // A step between the fused ground of the neighbours (across frames) on this cell's edges.
    if (fusion.max_neighbour_step > 0 && neighbourStep(cell, fusion) > fusion.max_neighbour_step)
        return CellState::Obstacle;
    if (l >= fusion.free_threshold) return CellState::Unknown;
    if (step_height_[cell] > fusion.max_step_height) return CellState::Obstacle;
    const float slope = slopeDeg(cell);
    if (std::isfinite(slope) && slope > fusion.max_slope_deg) return CellState::Obstacle;
    return CellState::Traversable;
}

float TraversabilityGrid::groundHeight(long cell) const {
    return ground_count_[cell] > 0 ? ground_mean_[cell] : kNaN;
}

float TraversabilityGrid::groundSpread(long cell) const {
    const uint32_t n = ground_count_[cell];
    return n > 1 ? std::sqrt(std::max(0.f, ground_m2_[cell]) / float(n - 1)) : 0.f;
}

float TraversabilityGrid::slopeDeg(long cell) const {
    const uint32_t n = ground_count_[cell];
    return n > 0 ? slope_sum_[cell] / float(n) : kNaN;
}

TraversabilityGrid::Arrays TraversabilityGrid::arrays() {
    return Arrays{
        {&logodds_, &ground_mean_, &ground_m2_, &slope_sum_, &step_height_, &obstacle_frames_},
        {&ground_count_, &frames_seen_},
        {&last_seen_}};
}

void TraversabilityGrid::arraysLoaded() {
    const std::size_t n = std::size_t(size_x_) * std::size_t(size_y_);
    Arrays a = arrays();
    for (auto* v : a.floats)
        if (v->size() != n) throw std::runtime_error("traversability grid: array size mismatch");
    for (auto* v : a.counts)
        if (v->size() != n) throw std::runtime_error("traversability grid: array size mismatch");
    for (auto* v : a.doubles)
        if (v->size() != n) throw std::runtime_error("traversability grid: array size mismatch");
    observed_cells_ = std::size_t(
        std::count_if(frames_seen_.begin(), frames_seen_.end(), [](uint32_t f) { return f > 0; }));
    frame_slot_.assign(n, -1);
    frame_touched_.clear();
    frame_cells_.clear();
}

}  // namespace travel_mrpt
