// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/MapObstacleSource.hpp"

#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <stdexcept>

#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace travel_mrpt {

namespace {
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
/// [m] longest stretch of a ground ray carved free before its hit (see compute()).
constexpr double kMaxCarve = 1.0;
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}
double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}
bool sameGeometry(const GridGeometry& a, const GridGeometry& b) {
    return a.min_x == b.min_x && a.max_x == b.max_x && a.min_y == b.min_y && a.max_y == b.max_y &&
           a.resolution == b.resolution;
}
}  // namespace

MapObstacleSource::MapObstacleSource(const TraversabilityMapOptions& map,
                                     const travel::NavSection& nav, const MapSourceOptions& options)
    : options_(options), map_(std::make_unique<CTraversabilityMap>(map)), rule_(nav) {
    if (!(options.horizon > 0) || !(options.margin >= 0) || !(options.column_step > 0))
        throw std::invalid_argument(
            "map obstacle source: horizon and column_step must be > 0, margin >= 0");
    resetObstacles();
}

void MapObstacleSource::resetObstacles() {
    obstacles_grid_.reset(map_->options());
    low_.assign(obstacles_grid_.cellCount(), 0.f);
    high_.assign(obstacles_grid_.cellCount(), 0.f);
    frame_low_.assign(obstacles_grid_.cellCount(), kNaN);
    frame_high_.assign(obstacles_grid_.cellCount(), kNaN);
}

MapObstacleSource::~MapObstacleSource() = default;

bool MapObstacleSource::obstacleCell(long cell) const {
    return obstacles_grid_.observed(cell) &&
           obstacles_grid_.logodds(cell) > map_->options().obstacle_threshold;
}

void MapObstacleSource::plannerGrid(std::vector<travel::CellState>& states,
                                    std::vector<float>& slopes) const {
    const std::size_t n = obstacles_grid_.cellCount();
    states.resize(n), slopes.resize(n);
    const travel::TraversabilityGrid& grid = map_->grid();
    // A map assigned since the last update() may have another geometry: look it up by place.
    const bool same = sameGeometry(map_->options(), obstacles_grid_.geometry());
    for (std::size_t c = 0; c < n; ++c) {
        const long m =
            same ? long(c)
                 : grid.cellIndex(obstacles_grid_.cellCenterX(int(c % obstacles_grid_.sizeX())),
                                  obstacles_grid_.cellCenterY(int(c / obstacles_grid_.sizeX())));
        const bool known = m >= 0 && grid.observed(m);
        states[c] = obstacleCell(long(c)) ? travel::CellState::Obstacle
                    : known               ? map_->state(m)
                                          : travel::CellState::Unknown;
        slopes[c] = known ? grid.slopeDeg(m) : kNaN;
    }
}

void MapObstacleSource::compute(const ObstacleFrame& frame, ObstaclePoints& out,
                                travel::ObstaclePointCloud& transient) {
    if (frame.travel == nullptr || frame.result == nullptr || frame.aligned == nullptr)
        throw std::invalid_argument(
            "map obstacle source: the frame has no TravelFrame, TRAVEL result or aligned cloud");
    // The map may have been replaced (a previous run's): the obstacle grid follows its geometry.
    if (!sameGeometry(map_->options(), obstacles_grid_.geometry())) resetObstacles();
    const Eigen::Isometry3d& robot = frame.robotPose;
    const double cpu_start = threadCpuMs();
    auto start = Clock::now();
    map_->fuseFrame(*frame.travel,
                    mrpt::poses::CPose3D::FromRotationAndTranslation(
                        mrpt::math::CMatrixDouble33(robot.linear()),
                        mrpt::math::TVector3D(robot.translation().x(), robot.translation().y(),
                                              robot.translation().z())));
    map_ms_ = msSince(start);
    start = Clock::now();

    // TRAVEL's obstacles, levelled robot frame (xy from the robot origin, yaw only).
    frame_points_.clear();
    // Moving objects (tracking on) skip the obstacle grid: they and their predicted paths are
    // handed for this frame only, or they would leave a trail of static obstacle cells.
    rule_.compute(*frame.result, *frame.aligned, frame.sensorOnRobot, frame_points_, &transient);
    rule_.predictMoving(*frame.result, *frame.aligned, frame.sensorOnRobot, transient,
                        float(options_.column_step));
    const double yaw = std::atan2(robot.linear()(1, 0), robot.linear()(0, 0));
    const double c = std::cos(yaw), s = std::sin(yaw);
    const double rx = robot.translation().x(), ry = robot.translation().y();

    // Ground of this frame (free evidence) and the obstacles, into the obstacle grid.
    const CTraversabilityMap& m = *map_;
    const AlignedInWorld placed =
        alignedInWorld(*frame.travel, mrpt::poses::CPose3D::FromRotationAndTranslation(
                                          mrpt::math::CMatrixDouble33(robot.linear()),
                                          mrpt::math::TVector3D(rx, ry, robot.translation().z())));
    const Eigen::Matrix3f& to_world = placed.rotation;
    const Eigen::Vector3f& origin = placed.origin;
    const travel::AlignedCloud& a = *frame.aligned;
    const auto& labels = frame.result->labels;
    // Free evidence: a ground hit, and the cells its ray crossed lower than max_step_height
    // above the hit (flat ground assumed between; at most kMaxCarve back): anything the robot
    // cannot climb standing there would have stopped the ray. The rings of a LiDAR hit the
    // ground metres apart far out: without this, cells between rings never get evidence.
    const double res = m.options().resolution;
    const double climb = rule_.options().max_step_height;
    const double near2 = (options_.horizon + kMaxCarve) * (options_.horizon + kMaxCarve);
    obstacles_grid_.beginFrame();
    for (std::size_t i = 0, n = std::min(a.x.size(), labels.size()); i < n; ++i) {
        if (!a.valid[i] || labels[i] != travel::PointClass::Ground) continue;
        const Eigen::Vector3f pw = to_world * Eigen::Vector3f(a.x[i], a.y[i], a.z[i]) + origin;
        obstacles_grid_.addGround(pw.x(), pw.y(), pw.z(), kNaN);
        const double ux = double(origin.x()) - pw.x(), uy = double(origin.y()) - pw.y();
        const double reach2 = ux * ux + uy * uy, drop = double(origin.z()) - pw.z();
        if (drop <= 0 || reach2 < 1e-6 ||
            (pw.x() - rx) * (pw.x() - rx) + (pw.y() - ry) * (pw.y() - ry) > near2)
            continue;
        const double reach = std::sqrt(reach2);
        const double back = std::min({climb * reach / drop, kMaxCarve, reach});
        for (double d = res; d <= back; d += res)
            obstacles_grid_.addGround(pw.x() + ux * d / reach, pw.y() + uy * d / reach, pw.z(),
                                      kNaN);
    }
    frame_cells_.clear();
    for (std::size_t i = 0; i < frame_points_.size(); ++i) {
        const double wx = rx + c * frame_points_.x[i] - s * frame_points_.y[i];
        const double wy = ry + s * frame_points_.x[i] + c * frame_points_.y[i];
        const long cell = obstacles_grid_.cellIndex(wx, wy);
        if (cell < 0) continue;
        obstacles_grid_.addObstacle(wx, wy);
        const float z = frame_points_.z[i];
        float &lo = frame_low_[cell], &hi = frame_high_[cell];
        if (std::isnan(lo)) frame_cells_.push_back(cell), lo = hi = z;
        lo = std::min(lo, z), hi = std::max(hi, z);
    }
    obstacles_grid_.endFrame(mrpt::Clock::toDouble(frame.timestamp), m.options());
    for (long cell : frame_cells_) {
        low_[cell] = frame_low_[cell], high_[cell] = frame_high_[cell];
        frame_low_[cell] = frame_high_[cell] = kNaN;
    }

    // The obstacle cells within the horizon, grown by the margin, into the robot frame.
    const GridGeometry& g = m.options();
    const double half = 0.5 * res + options_.margin;
    const double r2 = options_.horizon * options_.horizon;
    const int reach = int(std::ceil(options_.horizon / res));
    const int cx = int(std::floor((rx - g.min_x) / res)),
              cy = int(std::floor((ry - g.min_y) / res));
    static constexpr double kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    const float step = float(options_.column_step);
    for (int iy = std::max(0, cy - reach); iy <= std::min(obstacles_grid_.sizeY() - 1, cy + reach);
         ++iy)
        for (int ix = std::max(0, cx - reach);
             ix <= std::min(obstacles_grid_.sizeX() - 1, cx + reach); ++ix) {
            const long cell = obstacles_grid_.cellIndex(ix, iy);
            if (!obstacleCell(cell)) continue;
            const double dx = obstacles_grid_.cellCenterX(ix) - rx,
                         dy = obstacles_grid_.cellCenterY(iy) - ry;
            if (dx * dx + dy * dy > r2) continue;
            const float lo = low_[cell], hi = high_[cell];
            for (const auto& k : kCorner) {
                const double px = dx + k[0] * half, py = dy + k[1] * half;
                const float qx = float(c * px + s * py), qy = float(-s * px + c * py);
                for (float z = lo; z < hi; z += step) out.push_back(qx, qy, z);
                out.push_back(qx, qy, hi);
            }
        }
    sensing_ms_ = msSince(start);
    cpu_ms_ = threadCpuMs() - cpu_start;
}

}  // namespace travel_mrpt
