// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The TRAVEL observation filter: MRPT LiDAR observation in, labelled points out.
//
//   travel_mrpt::TravelFilter filter;
//   filter.loadConfigFile("share/configs/mrpt_sample_vlp16.yaml");  // or initialize(yaml)
//   travel_mrpt::TravelFrame frame;                // keep it: its buffers are reused
//   for each record of the rawlog, in order:
//       IMU -> filter.processImu(imu); odometry -> filter.processOdometry(odo);
//       LiDAR -> if (filter.filter(*obs, frame, &why)) use(frame.result.labels ...);
//
// One travel::Pipeline per sensor label (rebuilt only when that sensor's mount changes). Each
// LiDAR frame is levelled with the robot's roll/pitch and deskewed with the sensor's velocity
// when motion data is known (IMU, odometry, robot poses; see MotionEstimator.hpp). Point times
// from the adapters are seconds after obs.timestamp (Velodyne: after the observation
// timestamp; rotating scans: after the first column, which is the observation timestamp), so
// the motion is evaluated at obs.timestamp and the sweep is deskewed to that instant
// (FrameInput::reference_time = 0).
#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/math/TTwist2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/COutputLogger.h>
#include <mrpt/system/CTimeLogger.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <string>

#include "travel/MotionEstimator.hpp"
#include "travel/Pipeline.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Result.hpp"
#include "travel_mrpt/TravelFilterOptions.hpp"

namespace mrpt::obs {
class CObservation;
class CObservationIMU;
class CObservationOdometry;
class CActionRobotMovement2D;
}  // namespace mrpt::obs

namespace travel {
class FrameTracker;
}

namespace travel_mrpt {

/// One processed LiDAR frame. Reuse the same object across calls: no allocation once warm.
struct TravelFrame {
    travel::PointCloud cloud;  ///< sensor frame, as converted (index i <-> result.labels[i])
    travel::Result result;
    mrpt::poses::CPose3D sensorPose;                                ///< sensor on the robot
    Eigen::Matrix3f alignedRotation = Eigen::Matrix3f::Identity();  ///< sensor -> aligned
    /// The pipeline's aligned cloud (sensor-centred, gravity-aligned) of this frame; valid until
    /// the next filter() call for the same sensor label.
    const travel::AlignedCloud* aligned = nullptr;
    std::string sensorLabel;
    mrpt::Clock::time_point timestamp;
    bool levelled = false;  ///< a robot attitude was applied
    bool deskewed = false;  ///< per-point times and a sensor velocity were applied
    /// options().track_objects: result.clusters carry track ids, velocities and moving flags
    /// (travel::Tracker); ego-motion from the robot poses / odometry (egoFromPoses), else from
    /// registering consecutive scans. worldTSensor: the sensor pose the tracker used (world
    /// frame of the poses, or of the first scan when registered).
    bool tracked = false;
    bool egoFromPoses = false;
    Eigen::Isometry3d worldTSensor = Eigen::Isometry3d::Identity();
    /// The sensor velocity used for deskew (sensor frame), when deskewed.
    Eigen::Vector3d sensorLinearVelocity = Eigen::Vector3d::Zero();
    Eigen::Vector3d sensorAngularVelocity = Eigen::Vector3d::Zero();
    double convert_ms = 0, process_ms = 0;
};

/// Where a frame's aligned cloud lies in a world frame, with the robot at `robotPose`:
/// p_world = rotation * p_aligned + origin (aligned -> sensor is alignedRotation^T, then the
/// sensor's pose on the robot, then the robot's). The one home of this placement: the map layer
/// and the map obstacle source both call it.
struct AlignedInWorld {
    Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();
    Eigen::Vector3f origin = Eigen::Vector3f::Zero();
};
AlignedInWorld alignedInWorld(const TravelFrame& frame, const mrpt::poses::CPose3D& robotPose);

class TravelFilter : public mrpt::system::COutputLogger {
  public:
    TravelFilter();
    explicit TravelFilter(const TravelFilterOptions& options);
    ~TravelFilter() override;

    // ---- Configuration (each call forgets pipelines and motion state) ----
    /// FilterBase idiom: construct, initialize(yaml), then filter() each observation.
    void initialize(const mrpt::containers::yaml& cfg);
    /// .yaml/.yml or .ini/.cfg (section [travel]); errors name the file.
    void loadConfigFile(const std::string& path);
    /// Validates (throws travel::ConfigError) then replaces the options.
    void setOptions(const TravelFilterOptions& options);
    const TravelFilterOptions& options() const { return options_; }

    // ---- LiDAR ----
    /// Converts and segments one observation. Returns false (and *why_not) for non-LiDAR
    /// observations, labels not matching options().sensor_label, observations without points.
    bool filter(const mrpt::obs::CObservation& obs, TravelFrame& out,
                std::string* why_not = nullptr);
    /// Segments a cloud already in travel's form (simulators, own drivers) exactly as
    /// filter(obs) segments a converted observation: same pipelines, levelling and deskew.
    /// No label filter (the caller chose the cloud).
    void filter(const travel::PointCloud& cloud, const mrpt::poses::CPose3D& sensorPose,
                mrpt::Clock::time_point timestamp, const std::string& sensorLabel,
                TravelFrame& out);
    /// Aligned cloud of the last frame of `sensor_label`; throws std::out_of_range if none.
    const travel::AlignedCloud& aligned(const std::string& sensor_label) const;

    // ---- filter() in three steps, for replays that segment on several threads ----
    /// What the segmentation of a prepared frame needs: the sensor's pipeline (a settled one
    /// may be copied, travel::Pipeline::settledCopy(), and the copy used on another thread) and
    /// the frame's input (levelling, deskew velocities).
    struct FrameJob {
        travel::Pipeline* pipeline = nullptr;
        /// Changes when the sensor's pipeline is rebuilt (a new mount): copies made from an
        /// older generation are stale.
        unsigned generation = 0;
        travel::FrameInput input;
        /// The robot pose tracking uses (egoPoseAt the frame's time), taken when prepared:
        /// motion data read after the frame must not change it.
        std::optional<Eigen::Isometry3d> robot_pose;
        double prepare_ms = 0;
    };
    /// filter()'s first step, in record order on this thread: the checks, the conversion, the
    /// motion at the frame's time and the sensor's pipeline. false (and *why_not) as filter().
    bool prepare(const mrpt::obs::CObservation& obs, TravelFrame& out, FrameJob& job,
                 std::string* why_not = nullptr);
    /// The last step, in record order on this thread, once job.pipeline (or a settled copy of
    /// it) has segmented out.cloud into out.result: out.aligned = `aligned` (the aligned cloud
    /// of that segmentation, which the caller keeps alive), tracking, out.process_ms
    /// (prepare + `segment_ms` + this step).
    void complete(TravelFrame& out, const FrameJob& job, const travel::AlignedCloud& aligned,
                  double segment_ms);

    // ---- Motion inputs, in rawlog order ----
    /// Attitude from IMU_ORI_QUAT_* (or IMU_ROLL/IMU_PITCH[/IMU_YAW]) and gyro IMU_WX/WY/WZ,
    /// moved from the IMU frame to the robot frame with the IMU's sensorPose rotation.
    void processImu(const mrpt::obs::CObservationIMU& imu);
    /// Planar pose (differenced when velocities are needed) and, if present, its velocities.
    void processOdometry(const mrpt::obs::CObservationOdometry& odometry);
    /// An odometry action (SensoryFrame rawlogs), like processOdometry(): `odometry_pose` is the
    /// robot pose its increments compose to (the caller composes them), differenced when
    /// velocities are needed; the action's velocities when it has them. An untimed action only
    /// sets the odometry pose (setOdometryPose).
    void processAction(const mrpt::obs::CActionRobotMovement2D& action,
                       const mrpt::poses::CPose2D& odometry_pose);
    /// Robot pose in the world (pose files, SensoryFrames): attitude and velocity source, and
    /// the ego-motion of tracking.
    void setRobotPose(const mrpt::poses::CPose3D& pose, mrpt::Clock::time_point t);
    /// Robot pose in the odometry frame (e.g. composed CActionRobotMovement2D increments; what
    /// processOdometry() also records): the ego-motion of tracking when no robot pose is set.
    /// t may be INVALID_TIMESTAMP (then taken as current).
    void setOdometryPose(const mrpt::poses::CPose3D& pose, mrpt::Clock::time_point t);
    /// Forget the motion state and the tracks (not the pipelines).
    void reset();

    /// The robot pose the tracker uses for a frame at time t: the newest robot pose (else
    /// odometry pose) not older than max_motion_age, with the roll and pitch of the measured
    /// attitude when there is one (IMU; planar odometry has none), carried to t with the robot's
    /// velocity when known; nothing when neither pose is fresh.
    std::optional<Eigen::Isometry3d> egoPoseAt(mrpt::Clock::time_point t) const;

    /// The motion the filter would use for a frame at time t (robot frame), for inspection.
    travel::MotionEstimate motionAt(mrpt::Clock::time_point t) const;

    /// Stages "convert" and "travel". The filter clears it on destruction: dump it before.
    mrpt::system::CTimeLogger& timeLogger() { return time_logger_; }

  private:
    struct SensorPipeline {
        std::unique_ptr<travel::Pipeline> pipeline;
        unsigned generation = 0;     ///< FrameJob::generation
        mrpt::poses::CPose3D mount;  ///< sensor pose the pipeline was built for
        bool noted_no_times = false;
    };
    SensorPipeline& pipelineFor(const std::string& label, const mrpt::poses::CPose3D& pose);
    /// The sensor's pipeline and the frame input that levels and deskews out.cloud
    /// (sensorPose, sensorLabel, timestamp set).
    void prepareSegmentation(TravelFrame& out, FrameJob& job);
    /// Levels, deskews and segments out.cloud (sensorPose, sensorLabel, timestamp set).
    void segment(TravelFrame& out);
    /// Segments a prepared frame with the sensor's own pipeline, then complete().
    void segmentPrepared(TravelFrame& out, const FrameJob& job);
    /// Fills the clusters' tracking fields of `out` (options_.track_objects), with the robot
    /// at `robot` (else ego-motion from registration).
    void track(TravelFrame& out, const std::optional<Eigen::Isometry3d>& robot);
    /// The planar odometry pose at t (timed) and its velocities if known: the odometry pose of
    /// tracking and a velocity source of the motion estimate.
    void addOdometry(const mrpt::poses::CPose2D& pose, mrpt::Clock::time_point t,
                     const mrpt::math::TTwist2D* velocity);
    /// Logs `message` the first time `flag` is false, then sets it (no per-frame strings).
    void noteOnce(bool& flag, const std::string& message, mrpt::system::VerbosityLevel level);

    TravelFilterOptions options_;
    std::regex label_regex_;
    std::map<std::string, SensorPipeline> pipelines_;
    travel::MotionEstimator motion_;
    struct PoseSample {
        bool valid = false;
        bool timed = false;  ///< false: t unknown, taken as current
        mrpt::Clock::time_point t{};
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    };
    PoseSample robot_pose_, odometry_pose_;
    /// One tracker per sensor label (its clusters are in that sensor's aligned frame).
    std::map<std::string, std::unique_ptr<travel::FrameTracker>> trackers_;
    mrpt::system::CTimeLogger time_logger_{true, "TravelFilter"};
    // Each cause is logged once (until the options change).
    bool noted_no_attitude_ = false, noted_no_velocity_ = false;
    bool noted_imu_time_ = false, noted_odometry_time_ = false;
    bool noted_track_registration_ = false, noted_track_time_ = false;
    std::string why_scratch_;
};

}  // namespace travel_mrpt
