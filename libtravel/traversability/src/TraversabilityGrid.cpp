// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/TraversabilityGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "travel/EnumNames.hpp"

namespace travel {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kDegToRad = 3.14159265358979f / 180.f;
constexpr uint32_t kStepReferencePoints = 2;     ///< ground points a step reference cell needs
constexpr uint32_t kCorrectionPoints = 2;        ///< ground points per cell, frame and map
constexpr std::size_t kCorrectionMinCells = 50;  ///< cells a frame height correction needs
constexpr double kCorrectionGate0 = 2.0;         ///< [m] residuals beyond: not ground both times
/// [m] inlier gates of the successive refits (the first fit takes every residual).
constexpr double kCorrectionGates[] = {kCorrectionGate0, 0.3, 0.1, 0.05};
constexpr int kStepRadius = 2;           ///< [cells] neighbourhood of the step rule
constexpr float kMaxPairDistance = 4.f;  ///< [cells] farthest pair of the step rule

constexpr EnumName<CellState> kCellStateNames[] = {{CellState::Unknown, "unknown"},
                                                   {CellState::Traversable, "traversable"},
                                                   {CellState::Obstacle, "obstacle"}};

}  // namespace

const char* toString(CellState state) {
    return nameOf(kCellStateNames, state);
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
    // Welford within the frame (merged into the cell in endFrame, after the frame's height
    // correction).
    const float delta = z - f.z_mean;
    f.z_mean += delta / float(f.ground);
    f.z_m2 += delta * (z - f.z_mean);
    f.slope_sum += std::isfinite(slope_deg) ? slope_deg : 0.f;
}

float TraversabilityGrid::groundHeightThisFrame(long cell) const {
    if (ground_count_[cell] > 0) return ground_mean_[cell];
    const int32_t slot = frame_slot_[cell];
    return slot >= 0 && frame_cells_[slot].ground > 0 ? frame_cells_[slot].z_mean : kNaN;
}

bool TraversabilityGrid::frameHeightCorrection(float c[3], double& xm, double& ym) const {
    // Residuals (frame mean - fused mean) of the ground cells seen before and in this frame.
    struct Sample {
        double x, y, r;
    };
    std::vector<Sample> samples;
    double sx = 0, sy = 0;
    for (std::size_t k = 0; k < frame_touched_.size(); ++k) {
        const long cell = frame_touched_[k];
        const FrameCell& f = frame_cells_[k];
        if (f.ground < kCorrectionPoints || ground_count_[cell] < kCorrectionPoints) continue;
        const double r = double(f.z_mean) - double(ground_mean_[cell]);
        if (std::abs(r) > kCorrectionGate0) continue;
        const double x = cellCenterX(int(cell % size_x_)), y = cellCenterY(int(cell / size_x_));
        samples.push_back({x, y, r});
        sx += x, sy += y;
    }
    if (samples.size() < kCorrectionMinCells) return false;
    xm = sx / double(samples.size());
    ym = sy / double(samples.size());
    // Least squares r = c0 + c1 (x - xm) + c2 (y - ym), refitted on the inliers of the previous
    // fit with shrinking gates (a kerb, a box or a mislabelled cell is not an attitude error).
    double fit[3] = {0, 0, 0};
    for (double gate : kCorrectionGates) {
        Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        std::size_t used = 0;
        for (const Sample& q : samples) {
            const Eigen::Vector3d v(1.0, q.x - xm, q.y - ym);
            const double predicted = fit[0] + fit[1] * v[1] + fit[2] * v[2];
            if (std::abs(q.r - predicted) > gate) continue;
            A += v * v.transpose();
            b += v * q.r;
            ++used;
        }
        if (used < kCorrectionMinCells) return false;
        const Eigen::Vector3d sol = A.ldlt().solve(b);
        if (!sol.allFinite()) return false;
        fit[0] = sol[0], fit[1] = sol[1], fit[2] = sol[2];
    }
    c[0] = float(fit[0]), c[1] = float(fit[1]), c[2] = float(fit[2]);
    return true;
}

void TraversabilityGrid::addObstacle(double x, double y) {
    const long cell = cellIndex(x, y);
    if (cell >= 0) ++frameCell(cell).obstacle;
}

std::size_t TraversabilityGrid::endFrame(double time_s, const GridFusionParams& fusion) {
    std::size_t updated = 0;
    const float diagonal = float(geometry_.resolution) * 1.41421356f;
    // The frame's ground against the ground fused so far: an attitude (or height) error of the
    // frame tilts (shifts) all its ground heights by a plane in x, y; remove it before fusing, so
    // that heights of neighbouring cells seen from different frames can be compared.
    float corr[3] = {0.f, 0.f, 0.f};
    double xm = 0, ym = 0;
    if (fusion.max_neighbour_step > 0) frameHeightCorrection(corr, xm, ym);
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
            const float slope = f.slope_sum / float(f.ground);
            const float rise = diagonal * std::tan(std::min(slope, 80.f) * kDegToRad);
            const float step = (f.z_high[1] - f.z_low[1]) - (std::isfinite(rise) ? rise : 0.f);
            step_height_[cell] = std::max(step_height_[cell], step);
        }
        if (f.ground > 0) {  // merge the frame's ground statistics (Chan et al.)
            const float cx = float(cellCenterX(int(cell % size_x_)) - xm);
            const float cy = float(cellCenterY(int(cell / size_x_)) - ym);
            const float mean_b = f.z_mean - (corr[0] + corr[1] * cx + corr[2] * cy);
            const uint32_t na = ground_count_[cell], nb = f.ground, nab = na + nb;
            const float delta = mean_b - ground_mean_[cell];
            ground_mean_[cell] += delta * float(nb) / float(nab);
            ground_m2_[cell] += f.z_m2 + delta * delta * float(na) * float(nb) / float(nab);
            ground_count_[cell] = nab;
            slope_sum_[cell] += f.slope_sum;
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
    const float max_slope = std::min(fusion.max_traversable_slope_deg, 80.f);
    const float max_grade = std::tan(max_slope * kDegToRad);
    // The rise a slope explains between cells a and b (offsets (dxa, dya), (dxb, dyb) from this
    // cell): the steeper of the height gradients just OUTSIDE the pair (a against the reference
    // one step further from b, and likewise for b), capped at max_traversable_slope_deg, times
    // their distance. On a ramp, its foot or its top the outer cells continue the gradient; beside
    // a kerb they are flat. Without an outer reference, the pair's mean terrain-model slope (that
    // one is biased near a kerb: TRAVEL nodes straddling it fit planes tilted ~10 degrees).
    const auto rise = [&](long a, int dxa, int dya, long b, int dxb, int dyb) {
        const int ux = (dxb > dxa) - (dxb < dxa), uy = (dyb > dya) - (dyb < dya);  // a -> b
        const float distance = std::hypot(float(dxb - dxa), float(dyb - dya));
        const float unit = std::hypot(float(ux), float(uy));
        float grade = -1.f;
        const auto outer = [&](long inner, int x, int y, int steps) {
            if (x < 0 || y < 0 || x >= size_x_ || y >= size_y_) return;
            const long o = cellIndex(x, y);
            if (!stepReference(o, fusion)) return;
            grade = std::max(
                grade, std::abs(ground_mean_[o] - ground_mean_[inner]) / (float(steps) * unit * r));
        };
        for (int k = 1; k <= 2; ++k) {  // 1 and 2 cells out: one noisy cell does not decide
            outer(a, ix + dxa - k * ux, iy + dya - k * uy, k);
            outer(b, ix + dxb + k * ux, iy + dyb + k * uy, k);
        }
        if (grade < 0) {
            float slope = 0.5f * (slopeDeg(a) + slopeDeg(b));
            if (!std::isfinite(slope)) slope = 0.f;
            grade = std::tan(std::clamp(slope, 0.f, max_slope) * kDegToRad);
        }
        return distance * r * std::min(grade, max_grade);
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
            step = std::max(
                step, std::abs(h - ground_mean_[a.cell]) - rise(cell, 0, 0, a.cell, a.dx, a.dy));
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
            // Own height in the middle half: the cell holds both levels (a cell at one of
            // them is on one side of the edge, marked by the 4-neighbour test if adjacent).
            const float quarter = 0.25f * (hi - lo);
            if (ground_count_[cell] > 0 && (h <= lo + quarter || h >= hi - quarter)) continue;
            const int ddx = b.dx - a.dx, ddy = b.dy - a.dy;
            // Along an axis or a diagonal only, so that the outer gradients of rise() are
            // measured along the pair.
            if (ddx != 0 && ddy != 0 && std::abs(ddx) != std::abs(ddy)) continue;
            const float dist = std::hypot(float(ddx), float(ddy));
            if (dist > kMaxPairDistance) continue;
            step = std::max(step, (hi - lo) - rise(a.cell, a.dx, a.dy, b.cell, b.dx, b.dy));
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
    if (std::isfinite(slope) && slope > fusion.max_traversable_slope_deg)
        return CellState::Obstacle;
    return CellState::Traversable;
}

float TraversabilityGrid::groundHeight(long cell) const {
    return ground_count_[cell] > 0 ? ground_mean_[cell] : kNaN;
}

double TraversabilityGrid::meanGroundHeight() const {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t c = 0; c < cellCount(); ++c)
        if (ground_count_[c] > 0) sum += ground_mean_[c], ++count;
    return count ? sum / double(count) : std::numeric_limits<double>::quiet_NaN();
}

std::array<std::size_t, 3> TraversabilityGrid::stateCounts(const GridFusionParams& fusion) const {
    std::array<std::size_t, 3> counts{};
    for (std::size_t c = 0; c < cellCount(); ++c) ++counts[int(state(long(c), fusion))];
    return counts;
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

}  // namespace travel
