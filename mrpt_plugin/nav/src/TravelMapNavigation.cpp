// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TravelMapNavigation.hpp"

#include <mrpt/nav/reactive/CWaypointsNavigator.h>
#include <mrpt/poses/CPose3D.h>

#include <chrono>

#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace travel_mrpt {

namespace {
/// Frames between two attempts when no path was found (the map grows meanwhile).
constexpr std::size_t kRetryFrames = 10;

/// The planner's distances are to obstacle cell centres; the source reports each cell grown by
/// half a cell plus its margin: the path keeps robot_radius (and comfort_radius) from what the
/// navigator is given.
travel::GridPlannerOptions plannerFor(const TravelMapNavigationOptions& o) {
    travel::GridPlannerOptions p = o.planner;
    const double growth = 0.5 * o.map.resolution + o.source.margin;
    p.robot_radius += growth, p.comfort_radius += growth;
    return p;
}
}  // namespace

TravelMapNavigation::TravelMapNavigation(const TravelMapNavigationOptions& options)
    : options_(options),
      filter_(std::make_unique<TravelFilter>(options.filter)),
      frame_(std::make_unique<TravelFrame>()),
      source_(std::make_unique<MapObstacleSource>(options.map, options.nav, options.source)),
      planner_(plannerFor(options)) {}

TravelMapNavigation::~TravelMapNavigation() = default;

bool TravelMapNavigation::processObservation(const mrpt::obs::CObservation& obs,
                                             const mrpt::poses::CPose3D& robotPose,
                                             std::string* why_not) {
    filter_->setRobotPose(robotPose, obs.timestamp);
    if (!filter_->filter(obs, *frame_, why_not)) return false;
    publish(robotPose);
    return true;
}

void TravelMapNavigation::processScan(const travel::PointCloud& cloud,
                                      const mrpt::poses::CPose3D& sensorOnRobot,
                                      const mrpt::poses::CPose3D& robotPose,
                                      mrpt::Clock::time_point t) {
    filter_->setRobotPose(robotPose, t);
    filter_->filter(cloud, sensorOnRobot, t, "LIDAR", *frame_);
    publish(robotPose);
}

void TravelMapNavigation::publish(const mrpt::poses::CPose3D& robotPose) {
    ObstacleFrame f;
    f.cloud = &frame_->cloud;
    f.result = &frame_->result;
    f.aligned = frame_->aligned;
    f.travel = frame_.get();
    f.sensorOnRobot.matrix() =
        frame_->sensorPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>()
            .asEigen()
            .cast<float>();
    f.robotPose.matrix() =
        robotPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
    f.robotOdometry = {robotPose.x(), robotPose.y(), robotPose.yaw()};
    f.timestamp = frame_->timestamp;
    source_->update(f);
    ++frames_since_plan_;
}

void TravelMapNavigation::setGoal(const Eigen::Vector2d& goal, double tolerance) {
    goal_ = goal, goal_tolerance_ = tolerance, has_goal_ = true;
    path_.clear(), progress_ = 0;
}

bool TravelMapNavigation::replan(const Eigen::Vector2d& robot) {
    if (!has_goal_) return false;
    const auto start = std::chrono::steady_clock::now();
    source_->plannerGrid(states_, slopes_);
    planner_.setGrid(source_->map().options(), states_, slopes_);
    // Progress along the path: the nearest point a little ahead of the last one.
    for (std::size_t i = progress_, end = std::min(path_.size(), progress_ + 40); i < end; ++i)
        if ((path_[i] - robot).squaredNorm() < (path_[progress_] - robot).squaredNorm())
            progress_ = i;
    const bool first = history_.empty();
    const bool retry = path_.empty() && frames_since_plan_ >= kRetryFrames;
    bool changed = false;
    if (first || retry || (!path_.empty() && planner_.blocked(path_, progress_, robot))) {
        frames_since_plan_ = 0;
        std::vector<Eigen::Vector2d> path;
        if (planner_.plan(robot, goal_, path)) {
            path_ = std::move(path);
            history_.push_back(path_);
        } else {
            path_.clear();
            if (first) history_.push_back({});
        }
        progress_ = 0;
        changed = !path_.empty() || first;
    }
    plan_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return changed;
}

std::vector<Eigen::Vector2d> TravelMapNavigation::waypoints() const {
    return path_.empty() ? std::vector<Eigen::Vector2d>{goal_} : planner_.waypoints(path_);
}

bool TravelMapNavigation::updatePlan(mrpt::nav::CWaypointsNavigator& navigator,
                                     const Eigen::Vector2d& robot) {
    if (!replan(robot)) return false;
    mrpt::nav::TWaypointSequence seq;
    const std::vector<Eigen::Vector2d> points = waypoints();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const bool last = i + 1 == points.size();
        seq.waypoints.emplace_back(points[i].x(), points[i].y(),
                                   last ? goal_tolerance_ : options_.waypoint_tolerance,
                                   /*allow_skip=*/!last);
    }
    navigator.navigateWaypoints(seq);
    return true;
}

void TravelMapNavigation::saveMap(const std::string& prefix) const {
    source_->map().saveTo(prefix);
    source_->map().saveMetricMapRepresentationToFile(prefix);
}

void TravelMapNavigation::loadMap(const std::string& prefix) {
    source_->map().loadFrom(prefix);
}

}  // namespace travel_mrpt
