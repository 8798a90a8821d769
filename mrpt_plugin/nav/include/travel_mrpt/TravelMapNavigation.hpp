// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The whole chain for a user's robot: LiDAR observation -> TravelFilter -> CTraversabilityMap
// and the map obstacle source -> global path on the map (travel::GridPathPlanner) -> waypoints
// for MRPT's CWaypointsNavigator (CReactiveNavigationSystem / 3D are waypoint navigators),
// re-planned when the map blocks the path. travel-nav-sim's `-s map` is one user of it.
//
//   TravelMapNavigation chain(options);                        // filter, map, planner keys
//   // sensor thread, per LiDAR observation (robot pose in the map frame, e.g. localization):
//   chain.processObservation(obs, robotPose);
//   // in CRobot2NavInterface::senseObstacles(points, stamp):
//   return chain.source().latest(points, stamp);
//   // navigation: once, then after each processed frame
//   chain.setGoal({x, y}, 0.4);
//   chain.updatePlan(navigator, {robot_x, robot_y});          // sends waypoints when (re)planned
//   // on exit
//   chain.saveMap("run");   // run.bt, run_grid.gridmap.gz, run_height.gridmap.gz, pictures
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "travel/traversability/GridPathPlanner.hpp"
#include "travel_mrpt/MapObstacleSource.hpp"
#include "travel_mrpt/TravelFilterOptions.hpp"

namespace mrpt::nav {
class CWaypointsNavigator;
}
namespace mrpt::obs {
class CObservation;
}
namespace mrpt::poses {
class CPose3D;
}

namespace travel_mrpt {

class TravelFilter;
struct TravelFrame;

struct TravelMapNavigationOptions {
    TravelFilterOptions filter;    ///< TRAVEL and the filter (levelling, deskew)
    TraversabilityMapOptions map;  ///< grid extent and fusion (its `travel` part is not used)
    travel::NavSection nav;        ///< TRAVEL's obstacle rule (memory keys not used)
    MapSourceOptions source;       ///< horizon, margin
    /// robot_radius and comfort_radius from the robot's outline; the planner adds the growth
    /// of the reported cells (half a cell + source.margin) to both.
    travel::GridPlannerOptions planner;
    double waypoint_tolerance = 0.5;  ///< [m] allowed distance of the intermediate waypoints
};

class TravelMapNavigation {
  public:
    /// Throws travel::ConfigError naming the key.
    explicit TravelMapNavigation(const TravelMapNavigationOptions& options);
    ~TravelMapNavigation();

    TravelFilter& filter() { return *filter_; }
    MapObstacleSource& source() { return *source_; }
    const MapObstacleSource& source() const { return *source_; }

    // ---- Sensor side: segment, fuse, publish the obstacles ----
    /// A LiDAR observation at robotPose (map frame; also the filter's attitude source). False
    /// (and nothing fused) when the filter does not take the observation (*why_not says why).
    bool processObservation(const mrpt::obs::CObservation& obs,
                            const mrpt::poses::CPose3D& robotPose, std::string* why_not = nullptr);
    /// A cloud already in travel's form (simulators, own drivers), sensor frame.
    void processScan(const travel::PointCloud& cloud, const mrpt::poses::CPose3D& sensorOnRobot,
                     const mrpt::poses::CPose3D& robotPose, mrpt::Clock::time_point t);
    const TravelFrame& lastFrame() const { return *frame_; }

    // ---- Planning (same thread as the sensor side) ----
    void setGoal(const Eigen::Vector2d& goal, double tolerance);
    /// Plans when there is no plan yet, re-plans when a cell of the remaining path became
    /// forbidden (an obstacle, or within robot_radius of one); then sends the path as waypoints
    /// (CWaypointsNavigator::navigateWaypoints). True when waypoints were sent. When no path
    /// exists, the goal alone is sent (the reactive navigator gets as close as it can).
    bool updatePlan(mrpt::nav::CWaypointsNavigator& navigator, const Eigen::Vector2d& robot);
    /// The decision of updatePlan() without a navigator: plans when needed; true when the
    /// waypoints (waypoints()) changed and should be sent.
    bool replan(const Eigen::Vector2d& robot);
    /// The current waypoints: the path every waypoint_spacing metres, or the goal alone when
    /// there is no path.
    std::vector<Eigen::Vector2d> waypoints() const;
    /// The current path (cell centres, start to goal) and every path planned so far.
    const std::vector<Eigen::Vector2d>& path() const { return path_; }
    const std::vector<std::vector<Eigen::Vector2d>>& plannedPaths() const { return history_; }
    std::size_t plans() const { return history_.size(); }
    double lastPlanMs() const { return plan_ms_; }

    /// Saves the map on exit: CTraversabilityMap::saveTo (prefix.travelgrid and prefix.ot, what
    /// loadMap() reads back) and saveMetricMapRepresentationToFile (prefix.bt,
    /// prefix_grid.gridmap.gz, prefix_height.gridmap.gz and pictures, for OctoMap's and MRPT's
    /// tools). Throws std::runtime_error naming the file it could not write.
    void saveMap(const std::string& prefix) const;
    /// Starts from the map a previous run saved with saveMap(prefix) (CTraversabilityMap::
    /// loadFrom): the planner knows its cells before the first frame. Throws std::runtime_error
    /// naming the missing, truncated or corrupt file; the map is then left as it was.
    void loadMap(const std::string& prefix);

  private:
    void publish(const mrpt::poses::CPose3D& robotPose);

    TravelMapNavigationOptions options_;
    std::unique_ptr<TravelFilter> filter_;
    std::unique_ptr<TravelFrame> frame_;
    std::unique_ptr<MapObstacleSource> source_;
    travel::GridPathPlanner planner_;
    std::vector<travel::CellState> states_;
    std::vector<float> slopes_;
    Eigen::Vector2d goal_ = Eigen::Vector2d::Zero();
    double goal_tolerance_ = 0.4;
    bool has_goal_ = false;
    std::vector<Eigen::Vector2d> path_;
    std::size_t progress_ = 0;  // path index nearest the robot
    std::vector<std::vector<Eigen::Vector2d>> history_;
    double plan_ms_ = 0;
    std::size_t frames_since_plan_ = 0;
};

}  // namespace travel_mrpt
