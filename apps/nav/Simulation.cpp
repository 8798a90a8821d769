// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "nav/Simulation.hpp"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleSimul_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem3D.h>
#include <mrpt/nav/reactive/CRobot2NavInterfaceForSimulator.h>
#include <mrpt/system/filesystem.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <unistd.h>

#include "Interrupt.hpp"
#include "OutputFolder.hpp"
#include "nav/Collision.hpp"
#include "travel/EnumNames.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel_mrpt/ObstacleSources.hpp"
#include "travel_mrpt/TravelFilter.hpp"
#include "travel_mrpt/TravelMapNavigation.hpp"

namespace travel::navsim {
namespace fs = std::filesystem;

namespace {

constexpr EnumName<SourceKind> kSourceKindNames[] = {{SourceKind::Travel, "travel"},
                                                     {SourceKind::Raw, "raw"},
                                                     {SourceKind::Threshold, "threshold"},
                                                     {SourceKind::Map, "map"}};
constexpr EnumName<Outcome> kOutcomeNames[] = {{Outcome::Goal, "goal"},
                                               {Outcome::Collision, "collision"},
                                               {Outcome::NavigatorGaveUp, "navigator-gave-up"},
                                               {Outcome::Timeout, "timeout"}};

}  // namespace

const char* toString(SourceKind kind) {
    return nameOf(kSourceKindNames, kind);
}

std::vector<SourceKind> parseSources(const std::string& name) {
    if (name == "all") return {SourceKind::Travel, SourceKind::Raw, SourceKind::Threshold};
    if (const std::optional<SourceKind> kind = findByName(kSourceKindNames, name)) return {*kind};
    throw std::invalid_argument("unknown obstacle source '" + name + "' (expected " +
                                namesOf(kSourceKindNames, ", ", ", ") + " or all)");
}

const char* toString(Outcome outcome) {
    return nameOf(kOutcomeNames, outcome);
}

sim::LidarModel SimOptions::defaultLidar() {
    sim::LidarModel m = sim::LidarModel::uniform(32, -45.0, 15.0, 720);
    m.min_range = 0.3;
    m.max_range = 20.0;
    m.range_noise_sigma = 0.01;
    m.sweep_period = 0.1;
    m.seed = 7;
    return m;
}

travel::Params SimOptions::defaultTravelParams(const sim::LidarModel& lidar, double sensor_height) {
    travel::Params p;
    p.sensor_height = sensor_height;
    p.min_range = 0.4;
    p.max_range = lidar.max_range;
    p.tgf_resolution = 1.0;
    p.node_min_points = 5;
    p.seed_search_radius = 3.0;
    p.seed_height_tolerance = 0.5;
    p.cluster_objects = false;
    p.ring_source = "field";
    p.num_rings = static_cast<int>(lidar.numBeams());
    p.num_columns = lidar.columns;
    p.elevation_table = "uniform";
    const auto e = lidar.elevationsByRing();
    p.min_elevation_deg = e.front();
    p.max_elevation_deg = e.back();
    return p;
}

std::vector<Eigen::Vector2d> footprintFromConfig(const std::string& file) {
    if (!fs::is_regular_file(file)) throw std::runtime_error(file + ": navigator config not found");
    mrpt::config::CConfigFile cfg(file);
    std::vector<double> xs, ys;
    cfg.read_vector("CReactiveNavigationSystem3D", "LEVEL1_VECTORX", std::vector<double>{}, xs);
    cfg.read_vector("CReactiveNavigationSystem3D", "LEVEL1_VECTORY", std::vector<double>{}, ys);
    if (xs.size() < 3 || xs.size() != ys.size())
        throw std::runtime_error(file +
                                 ": [CReactiveNavigationSystem3D] needs LEVEL1_VECTORX and "
                                 "LEVEL1_VECTORY with the same number (>= 3) of values");
    std::vector<Eigen::Vector2d> out;
    for (std::size_t i = 0; i < xs.size(); ++i) out.emplace_back(xs[i], ys[i]);
    return out;
}

namespace {

/// "60 s", "2.5 s": no trailing zeros.
std::string formatSeconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g s", s);
    return buf;
}

/// Simulated clock: every timestamp the navigator sees is start + simulated seconds.
mrpt::Clock::time_point simStamp(double t) {
    return mrpt::Clock::fromDouble(1.7e9 + t);
}

/// MRPT's clock on the simulated time while a run lasts. The navigator reads mrpt::Clock::now()
/// itself (its "not approaching the target" alarm, its model of sensing and command delays): on
/// the wall clock it compared the simulated stamps with a time years later and counted the
/// alarm in wall seconds of a simulation running 1-20 x faster than real time, so how far it
/// drove before giving up depended on the machine's load, and two runs of one world and seed
/// could end differently. One run at a time (the clock is process-wide); the previous source
/// comes back at the end, also on exceptions.
class SimulatedMrptClock {
  public:
    explicit SimulatedMrptClock(double t) : previous_(mrpt::Clock::getActiveClock()) {
        set(t);  // before the switch, so that now() is never undefined
        mrpt::Clock::setActiveClock(mrpt::Clock::Simulated);
    }
    ~SimulatedMrptClock() { mrpt::Clock::setActiveClock(previous_); }
    SimulatedMrptClock(const SimulatedMrptClock&) = delete;
    SimulatedMrptClock& operator=(const SimulatedMrptClock&) = delete;
    void set(double t) { mrpt::Clock::setSimulatedTime(simStamp(t)); }

  private:
    mrpt::Clock::Source previous_;
};

/// MRPT's simulator interface, with obstacles from an ObstacleSource and simulated time stamps.
class SimRobot : public mrpt::nav::CRobot2NavInterfaceForSimulator_DiffDriven {
  public:
    SimRobot(mrpt::kinematics::CVehicleSimul_DiffDriven& sim,
             const travel_mrpt::ObstacleSource& source)
        : CRobot2NavInterfaceForSimulator_DiffDriven(sim), sim_(sim), source_(source) {}

    bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& vel,
                                 mrpt::system::TTimeStamp& stamp, mrpt::math::TPose2D& odometry,
                                 std::string& frame_id) override {
        const bool ok = CRobot2NavInterfaceForSimulator_DiffDriven::getCurrentPoseAndSpeeds(
            pose, vel, stamp, odometry, frame_id);
        stamp = simStamp(sim_.getTime());
        return ok;
    }
    bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
                        mrpt::system::TTimeStamp& stamp) override {
        ++sensed;
        return source_.latest(obstacles, stamp);
    }
    // The navigator's events: remembered for the report instead of printed.
    void sendNavigationEndDueToErrorEvent() override { gave_up = "navigation error"; }
    void sendWaySeemsBlockedEvent() override { gave_up = "way seems blocked"; }
    void sendCannotGetCloserToBlockedTargetEvent() override {
        gave_up = "cannot get closer to the blocked target";
    }

    std::string gave_up;
    std::size_t sensed = 0;

  private:
    mrpt::kinematics::CVehicleSimul_DiffDriven& sim_;
    const travel_mrpt::ObstacleSource& source_;
};

std::unique_ptr<travel_mrpt::ObstacleSource> makeSource(const SimOptions& o) {
    std::unique_ptr<travel_mrpt::ObstacleSource> s;
    switch (o.source) {
        case SourceKind::Travel:
            s = std::make_unique<travel_mrpt::TravelObstacleSource>(o.nav);
            break;
        case SourceKind::Raw:
            s = travel_mrpt::RobotFrameBandSource::raw(o.raw_min_z);
            break;
        case SourceKind::Threshold:
            s = travel_mrpt::RobotFrameBandSource::heightThreshold(o.threshold_min_z);
            break;
        case SourceKind::Map:
            return nullptr;  // TravelMapNavigation's
    }
    s->setMemory(o.nav);
    return s;
}

/// The navigator, with its loggers reachable: MRPT's CAbstractNavigator dumps its delay
/// CTimeLogger's table at INFO level when it is destroyed.
class Navigator : public mrpt::nav::CReactiveNavigationSystem3D {
  public:
    using CReactiveNavigationSystem3D::CReactiveNavigationSystem3D;
    /// The apps' -q/-v rule for the navigator, its time loggers and the robot interface.
    void setVerbosity(travel::apps::Verbosity verbosity, mrpt::system::COutputLogger& robot) {
        for (mrpt::system::COutputLogger* logger :
             {static_cast<mrpt::system::COutputLogger*>(this),
              static_cast<mrpt::system::COutputLogger*>(&m_timlog_delays),
              static_cast<mrpt::system::COutputLogger*>(&m_navProfiler),
              static_cast<mrpt::system::COutputLogger*>(&m_timelogger), &robot})
            travel::apps::configureMrptLogging(*logger, verbosity);
    }
};

mrpt::poses::CPose3D toPose3D(const Eigen::Isometry3d& T) {
    return mrpt::poses::CPose3D::FromRotationAndTranslation(
        mrpt::math::CMatrixDouble33(T.linear()),
        mrpt::math::TVector3D(T.translation().x(), T.translation().y(), T.translation().z()));
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

/// The final map for the picture: the planner's view of each cell.
void snapshotMap(const travel_mrpt::MapObstacleSource& source, RunReport& r) {
    std::vector<travel::CellState> states;
    std::vector<float> slopes;
    source.plannerGrid(states, slopes);
    const travel::TraversabilityGrid& g = source.obstacleGrid();
    r.map_min_x = g.geometry().min_x, r.map_min_y = g.geometry().min_y;
    r.map_resolution = g.geometry().resolution;
    r.map_size_x = g.sizeX(), r.map_size_y = g.sizeY();
    r.map_cells.resize(states.size());
    for (std::size_t i = 0; i < states.size(); ++i) r.map_cells[i] = uint8_t(states[i]);
}

}  // namespace

travel_mrpt::TravelMapNavigationOptions mapChainOptions(const World& world, const SimOptions& o) {
    travel_mrpt::TravelMapNavigationOptions c;
    c.filter.params = o.travel;
    c.filter.velocity_source = travel_mrpt::VelocitySource::None;
    if (o.track) {
        c.filter.track_objects = true;
        c.filter.tracking = o.tracking;
        c.filter.params.cluster_objects = true;
    }
    const Eigen::Vector4d ext = worldExtent(world);
    c.map.min_x = ext[0] - 1.0, c.map.min_y = ext[1] - 1.0;
    c.map.max_x = ext[2] + 1.0, c.map.max_y = ext[3] + 1.0;
    c.map.resolution = o.map_resolution;
    c.map.max_ray_length = o.lidar.max_range;
    c.nav = o.nav;
    c.nav.memory_seconds = 0.0;
    return c;
}

SimTravel::SimTravel(const travel::Params& params, bool track,
                     const travel::TrackingParams& tracking)
    : filter_(std::make_unique<travel_mrpt::TravelFilter>()),
      frame_(std::make_unique<travel_mrpt::TravelFrame>()) {
    travel_mrpt::TravelFilterOptions options;
    options.params = params;
    options.velocity_source = travel_mrpt::VelocitySource::None;
    if (track) {
        options.track_objects = true;
        options.tracking = tracking;
        options.params.cluster_objects = true;  // the tracker follows clusters
    }
    filter_->setOptions(options);
}

SimTravel::~SimTravel() = default;

void SimTravel::process(const travel::PointCloud& cloud, const Eigen::Isometry3d& robot,
                        const Eigen::Isometry3d& mount, double t,
                        travel_mrpt::ObstacleFrame& frame) {
    filter_->setRobotPose(toPose3D(robot), simStamp(t));
    filter_->filter(cloud, toPose3D(mount), simStamp(t), "SIM_LIDAR", *frame_);
    frame.cloud = &cloud;
    frame.result = &frame_->result;
    frame.aligned = frame_->aligned;
}

RunReport runSimulation(const World& world, const SimOptions& o) {
    if (!(o.dt > 0) || !(o.timeout > 0) || !(o.goal_tolerance > 0) || !(o.sensor_height > 0))
        throw std::runtime_error("dt, timeout, goal_tolerance and sensor_height must be > 0");
    const std::vector<Eigen::Vector2d> footprint = footprintFromConfig(o.nav_config_file);
    o.lidar.validate();
    SimTravel segmenter(o.travel, o.track, o.tracking);  // validates (throws ConfigError)
    World live = world;                                  // movers placed at each scan's time
    auto source = makeSource(o);
    // The map source: the library's chain (filter -> map -> planner -> waypoints).
    std::unique_ptr<travel_mrpt::TravelMapNavigation> chain;
    if (o.source == SourceKind::Map)
        chain = std::make_unique<travel_mrpt::TravelMapNavigation>(mapChainOptions(world, o));

    // The navigator writes PTG caches and its log into a directory of its own, under TMPDIR
    // (else /tmp), removed at the end, on errors and on Ctrl-C (travel::apps::TempDir).
    static int run_counter = 0;
    const travel::apps::TempDir scratch(
        fs::temp_directory_path() /
        (".travel-nav-sim-" + std::to_string(::getpid()) + "-" + std::to_string(run_counter++)));

    mrpt::kinematics::CVehicleSimul_DiffDriven sim;
    SimulatedMrptClock clock(sim.getTime());
    sim.setCurrentGTPose(mrpt::math::TPose2D(world.start.x(), world.start.y(), world.start.z()));
    SimRobot robot(sim, chain ? chain->source() : *source);
    RunReport report;
    {
        // The log file is enabled after the loggers are set: enabling it logs DEBUG lines.
        Navigator nav(robot, o.verbosity == travel::apps::Verbosity::Verbose, false,
                      (scratch.path() / "log").string());
        nav.setVerbosity(o.verbosity, robot);
        if (!o.navlog_file.empty()) nav.enableLogFile(true);
        {
            mrpt::config::CConfigFile cfg(o.nav_config_file);
            nav.loadConfigFile(cfg);
        }
        nav.params_abstract_ptg_navigator.ptg_cache_files_directory = scratch.path().string();
        nav.initialize();

        mrpt::nav::CAbstractNavigator::TNavigationParams request;
        request.target.target_coords = mrpt::math::TPose2D(world.goal.x(), world.goal.y(), 0.0);
        request.target.targetAllowedDistance = o.goal_tolerance;
        request.target.targetIsRelative = false;
        if (chain && o.plan)
            chain->setGoal(world.goal, o.goal_tolerance);  // waypoints from the first frame on
        else
            nav.navigate(&request);

        // Mount: sensor straight above the robot origin.
        const Eigen::Isometry3d mount(Eigen::Translation3d(0.0, 0.0, o.sensor_height));
        sim::Scan scan;
        travel_mrpt::ObstacleFrame frame;
        frame.sensorOnRobot = mount.cast<float>();

        double start_z = 0.0, max_z = -1e9;
        double wall_ms = 0.0, plan_ms = 0.0;
        std::vector<double> map_ms, map_cpu_ms, fusion_ms;
        int steps = 0;
        const int max_steps = static_cast<int>(std::ceil(o.timeout / o.dt));
        Eigen::Vector2d last_xy = world.start.head<2>();
        travel::apps::ProgressLine progress(std::string("travel-nav-sim: ") + toString(o.source), 0,
                                            o.verbosity, "steps");
        for (;; ++steps) {
            const double t = sim.getTime();
            clock.set(t);
            progress.updateSimTime(std::size_t(steps), t, o.timeout);
            travel::apps::throwIfInterrupted();  // unwinds: the scratch directory goes
            const mrpt::math::TPose2D p = sim.getCurrentGTPose();
            placeMovers(live, t);
            double z = 0.0;
            const Eigen::Matrix3d R =
                robotAttitudeOnTerrain(world.scene, footprint, p.x, p.y, p.phi, z);
            if (steps == 0) start_z = z;
            max_z = std::max(max_z, z);

            // Collision check and trajectory sample at this pose.
            const auto placed = placeFootprint(footprint, {p.x, p.y, p.phi});
            const Clearance c = clearance(placed, live);
            TrajectorySample s;
            s.t = t, s.x = p.x, s.y = p.y, s.z = z, s.yaw = p.phi;
            s.pitch = -std::asin(std::clamp(R(2, 0), -1.0, 1.0));
            s.roll = std::atan2(R(2, 1), R(2, 2));
            const auto vel = sim.getCurrentGTVelLocal();
            s.v = vel.vx, s.w = vel.omega, s.clearance = c.distance;
            if (!live.movers.empty()) {
                s.mover_clearance = clearance(placed, live, true).distance;
                report.min_mover_clearance =
                    std::min(report.min_mover_clearance, s.mover_clearance);
            }
            report.path_length += (Eigen::Vector2d(p.x, p.y) - last_xy).norm();
            last_xy = {p.x, p.y};
            if (c.distance < report.min_clearance) {
                report.min_clearance = c.distance;
                report.min_clearance_to = c.nearest;
            }
            report.final_goal_distance = (Eigen::Vector2d(p.x, p.y) - world.goal).norm();

            if (c.distance <= 0.0) {
                report.outcome = Outcome::Collision;
                report.detail = "footprint overlaps " + c.nearest;
            } else if (report.final_goal_distance <= o.goal_tolerance + 0.05) {
                report.outcome = Outcome::Goal;
            } else if (nav.getCurrentState() == mrpt::nav::CAbstractNavigator::NAV_ERROR ||
                       (steps > 0 &&
                        nav.getCurrentState() == mrpt::nav::CAbstractNavigator::IDLE)) {
                report.outcome = Outcome::NavigatorGaveUp;
                report.detail = robot.gave_up.empty() ? "navigator stopped" : robot.gave_up;
            } else if (steps >= max_steps) {
                report.outcome = Outcome::Timeout;
            } else {
                report.outcome = Outcome::Timeout;  // provisional: still running
                report.detail.clear();
            }
            const bool finished = c.distance <= 0.0 || report.outcome == Outcome::Goal ||
                                  report.outcome == Outcome::NavigatorGaveUp || steps >= max_steps;

            const auto tic = std::chrono::steady_clock::now();
            if (!finished) {
                // The LiDAR's true pose, its scan, TRAVEL levelled with the robot attitude.
                Eigen::Isometry3d robot_pose = Eigen::Isometry3d::Identity();
                robot_pose.linear() = R;
                robot_pose.translation() = Eigen::Vector3d(p.x, p.y, z);
                sim::LidarModel lidar = o.lidar;
                sim::scan(live.scene, lidar, robot_pose * mount, scan);
                travel_mrpt::ObstaclePoints handed;
                if (chain) {
                    chain->processScan(scan.cloud, toPose3D(mount), toPose3D(robot_pose),
                                       simStamp(t));
                    const auto& src = chain->source();
                    map_ms.push_back(src.lastMapMs() + src.lastSensingMs());
                    map_cpu_ms.push_back(src.lastCpuMs());
                    fusion_ms.push_back(src.lastMapMs());
                    if (o.plan) {
                        chain->updatePlan(nav, {p.x, p.y});
                        plan_ms += chain->lastPlanMs();
                    }
                    src.latest(handed);
                } else {
                    frame.cloud = &scan.cloud;
                    if (o.source == SourceKind::Travel)
                        segmenter.process(scan.cloud, robot_pose, mount, t, frame);
                    frame.robotOdometry = {p.x, p.y, p.phi};
                    frame.timestamp = simStamp(t);
                    source->update(frame);
                    source->latest(handed);
                }
                s.obstacles = handed.size();

                nav.navigationStep();
            }
            wall_ms +=
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - tic)
                    .count();
            report.trajectory.push_back(s);
            if (finished) break;
            sim.simulateOneTimeStep(o.dt);
        }
        report.time = sim.getTime();
        report.max_height_gain = max_z - start_z;
        report.mean_step_ms = steps > 0 ? wall_ms / steps : 0.0;
        if (chain) {
            report.median_map_ms = median(map_ms);
            report.median_map_cpu_ms = median(map_cpu_ms);
            report.median_fusion_ms = median(fusion_ms);
            report.max_map_ms =
                map_ms.empty() ? 0.0 : *std::max_element(map_ms.begin(), map_ms.end());
            report.mean_plan_ms = steps > 0 ? plan_ms / steps : 0.0;
            report.planned_paths = chain->plannedPaths();
            snapshotMap(chain->source(), report);
            if (!o.map_prefix.empty()) chain->saveMap(o.map_prefix);
        }
        if (report.outcome == Outcome::Timeout)
            report.detail = "no goal after " + formatSeconds(o.timeout);
    }  // the navigator closes its log here

    if (!o.navlog_file.empty()) {
        const fs::path produced = scratch.path() / "log" / "log_000.reactivenavlog";
        if (!fs::is_regular_file(produced))
            throw std::runtime_error("the navigator wrote no log (expected " + produced.string() +
                                     ")");
        // Copied beside the name and moved in place: a failed copy leaves no cut log there.
        travel::PartFile file(o.navlog_file);
        std::error_code ec;
        fs::copy_file(produced, file.part(), fs::copy_options::overwrite_existing, ec);
        if (ec) throw std::runtime_error(travel::cannotWriteMessage(o.navlog_file, ec.message()));
        file.commit();
    }
    return report;
}

void writeTrajectoryCsv(const RunReport& r, const std::string& path) {
    travel::writeThroughPartFile(path, [&](std::ostream& f) {
        const bool movers = r.min_mover_clearance < 1e9;
        f << "t,x,y,z,yaw_deg,roll_deg,pitch_deg,v,w,clearance,obstacles"
          << (movers ? ",mover_clearance\n" : "\n");
        char line[256];
        for (const auto& s : r.trajectory) {
            std::snprintf(line, sizeof line,
                          "%.2f,%.3f,%.3f,%.3f,%.2f,%.2f,%.2f,%.3f,%.3f,%.3f,%zu", s.t, s.x, s.y,
                          s.z, s.yaw * 180 / M_PI, s.roll * 180 / M_PI, s.pitch * 180 / M_PI, s.v,
                          s.w, s.clearance, s.obstacles);
            f << line;
            if (movers) {
                std::snprintf(line, sizeof line, ",%.3f", s.mover_clearance);
                f << line;
            }
            f << "\n";
        }
    });
}

}  // namespace travel::navsim
