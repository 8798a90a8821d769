// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TravelFilter.hpp"

#include <mrpt/containers/yaml.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "travel/Preprocessing.hpp"
#include "travel/tracking/FrameTracker.hpp"
#include "travel_mrpt/Attitude.hpp"
#include "travel_mrpt/LabelledOutputs.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"

namespace travel_mrpt {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double seconds(mrpt::Clock::time_point t) {
    return mrpt::Clock::toDouble(t);
}

Eigen::Matrix3d rotationOf(const mrpt::poses::CPose3D& pose) {
    return pose.getRotationMatrix().asEigen();
}

Eigen::Isometry3d isometryOf(const mrpt::poses::CPose3D& pose) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = rotationOf(pose);
    T.translation() = Eigen::Vector3d(pose.x(), pose.y(), pose.z());
    return T;
}

/// Heading of a rotation: the angle of its x axis in the xy plane.
double yawOf(const Eigen::Matrix3d& R) {
    return std::atan2(R(1, 0), R(0, 0));
}

Eigen::Matrix3d yawRotation(double yaw) {
    return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

bool sameRotation(const mrpt::poses::CPose3D& a, const mrpt::poses::CPose3D& b) {
    return (rotationOf(a) - rotationOf(b)).cwiseAbs().maxCoeff() < 1e-12;
}

}  // namespace

TravelFilter::TravelFilter() : TravelFilter(TravelFilterOptions{}) {}

TravelFilter::TravelFilter(const TravelFilterOptions& options)
    : mrpt::system::COutputLogger("TravelFilter") {
    setOptions(options);
}

TravelFilter::~TravelFilter() {
    // CTimeLogger prints its table on destruction; callers who want it call dumpAllStats().
    time_logger_.clear(true);
}

void TravelFilter::setOptions(const TravelFilterOptions& options) {
    options.params.validate();
    options.validate();
    options_ = options;
    label_regex_ = std::regex(options_.sensor_label, std::regex::ECMAScript);
    pipelines_.clear();
    noted_no_attitude_ = noted_no_velocity_ = noted_imu_time_ = noted_odometry_time_ = false;
    noted_track_registration_ = noted_track_time_ = false;
    motion_.setVelocitySource(options_.velocity_source);
    motion_.setMaxAge(options_.max_motion_age);
    reset();
}

void TravelFilter::initialize(const mrpt::containers::yaml& cfg) {
    TravelFilterOptions options;
    options.loadFromYaml(cfg);
    setOptions(options);
}

void TravelFilter::loadConfigFile(const std::string& path) {
    TravelFilterOptions options;
    options.loadFromFile(path);
    setOptions(options);
}

void TravelFilter::reset() {
    motion_.reset();
    robot_pose_ = odometry_pose_ = PoseSample{};
    trackers_.clear();
}

void TravelFilter::noteOnce(bool& flag, const std::string& message,
                            mrpt::system::VerbosityLevel level) {
    if (flag) return;
    flag = true;
    logStr(level, message);
}

TravelFilter::SensorPipeline& TravelFilter::pipelineFor(const std::string& label,
                                                        const mrpt::poses::CPose3D& pose) {
    SensorPipeline& entry = pipelines_[label];
    if (entry.pipeline && (!options_.use_sensor_pose || sameRotation(entry.mount, pose)))
        return entry;
    travel::Params params = options_.params;
    if (options_.use_sensor_pose) setMountFromSensorPose(pose, params);
    if (entry.pipeline)
        logStr(mrpt::system::LVL_INFO,
               "sensor '" + label + "' changed its mount: rebuilding its TRAVEL pipeline");
    entry.pipeline = std::make_unique<travel::Pipeline>(params);
    ++entry.generation;
    // Fixed angles come from the sensorPose here: the configuration keys would change nothing.
    if (options_.use_sensor_pose)
        entry.pipeline->setMountAnglesSource(
            {"the sensorPose of '" + label + "'",
             "ignore the sensorPose's angles (filter option use_sensor_pose: false, "
             "travel-rawlog --ignore-sensor-pose) and set mount_roll_deg / mount_pitch_deg "
             "(or auto)"});
    entry.mount = pose;
    return entry;
}

bool TravelFilter::filter(const mrpt::obs::CObservation& obs, TravelFrame& out,
                          std::string* why_not) {
    FrameJob job;
    if (!prepare(obs, out, job, why_not)) return false;
    segmentPrepared(out, job);
    return true;
}

bool TravelFilter::prepare(const mrpt::obs::CObservation& obs, TravelFrame& out, FrameJob& job,
                           std::string* why_not) {
    const auto fail = [&](const std::string& reason) {
        if (why_not) *why_not = reason;
        return false;
    };
    if (isTravelOutput(obs))
        return fail("'" + obs.sensorLabel +
                    "' is a TRAVEL output (labels or a per-class cloud of travel-rawlog), not a "
                    "LiDAR frame");
    if (!isLidarObservation(obs))
        return fail("'" + obs.sensorLabel + "' (" + obs.GetRuntimeClass()->className +
                    ") is not a 3-D LiDAR observation");
    if (!std::regex_match(obs.sensorLabel, label_regex_))
        return fail("sensor label '" + obs.sensorLabel + "' does not match sensor_label '" +
                    options_.sensor_label + "'");

    out.aligned = nullptr;
    const Clock::time_point convert_start = Clock::now();
    {
        mrpt::system::CTimeLoggerEntry entry(time_logger_, "convert");
        if (!toTravelCloud(obs, out.cloud, out.sensorPose, &why_scratch_))
            return fail("'" + obs.sensorLabel + "': " + why_scratch_);
    }
    out.convert_ms = msSince(convert_start);
    out.sensorLabel = obs.sensorLabel;
    out.timestamp = obs.timestamp;
    prepareSegmentation(out, job);
    return true;
}

void TravelFilter::filter(const travel::PointCloud& cloud, const mrpt::poses::CPose3D& sensorPose,
                          mrpt::Clock::time_point timestamp, const std::string& sensorLabel,
                          TravelFrame& out) {
    out.aligned = nullptr;
    out.cloud = cloud;
    out.sensorPose = sensorPose;
    out.convert_ms = 0;
    out.sensorLabel = sensorLabel;
    out.timestamp = timestamp;
    segment(out);
}

void TravelFilter::segment(TravelFrame& out) {
    FrameJob job;
    prepareSegmentation(out, job);
    segmentPrepared(out, job);
}

void TravelFilter::segmentPrepared(TravelFrame& out, const FrameJob& job) {
    const Clock::time_point start = Clock::now();
    {
        mrpt::system::CTimeLoggerEntry entry(time_logger_, "travel");
        job.pipeline->process(out.cloud, job.input, out.result);
    }
    complete(out, job, job.pipeline->aligned(), msSince(start));
}

void TravelFilter::prepareSegmentation(TravelFrame& out, FrameJob& job) {
    const Clock::time_point start = Clock::now();
    SensorPipeline& sensor = pipelineFor(out.sensorLabel, out.sensorPose);
    job.pipeline = sensor.pipeline.get();
    job.generation = sensor.generation;
    const travel::Params& params = sensor.pipeline->params();

    // Motion at the frame's time zero (see the header): robot frame -> sensor frame.
    job.robot_pose.reset();
    if (options_.track_objects && out.timestamp != INVALID_TIMESTAMP)
        job.robot_pose = egoPoseAt(out.timestamp);
    travel::FrameInput& input = job.input;
    input = travel::FrameInput{};
    input.reference_time = 0.0;
    out.levelled = out.deskewed = false;
    out.sensorLinearVelocity.setZero();
    out.sensorAngularVelocity.setZero();
    const bool timed = out.timestamp != INVALID_TIMESTAMP;
    const travel::MotionEstimate motion =
        timed ? motion_.estimateAt(seconds(out.timestamp)) : travel::MotionEstimate{};
    if (options_.use_robot_attitude && params.align_attitude) {
        if (motion.attitude) {
            setVehicleAttitude(
                mrpt::poses::CPose3D::FromRotationAndTranslation(
                    mrpt::math::CMatrixDouble33(*motion.attitude), mrpt::math::TVector3D(0, 0, 0)),
                input);
            out.levelled = true;
        } else {
            if (!noted_no_attitude_)
                noteOnce(noted_no_attitude_,
                         "no recent robot attitude (IMU or 3-D robot pose): "
                         "frames are not levelled",
                         mrpt::system::LVL_INFO);
        }
    }
    if (params.deskew && options_.velocity_source != VelocitySource::None) {
        if (!out.cloud.hasTime()) {
            if (!sensor.noted_no_times)
                noteOnce(sensor.noted_no_times,
                         "'" + out.sensorLabel + "' has no per-point times: no deskew",
                         mrpt::system::LVL_INFO);
        } else if (motion.linear_velocity && motion.angular_velocity) {
            // v_s = R^T (v + w x t), w_s = R^T w for the sensor at (R, t) on the robot.
            const Eigen::Matrix3d R = travel::mountRotation(params);  // as the pipeline
            const Eigen::Vector3d t(out.sensorPose.x(), out.sensorPose.y(), out.sensorPose.z());
            const Eigen::Vector3d& v = *motion.linear_velocity;
            const Eigen::Vector3d& w = *motion.angular_velocity;
            out.sensorLinearVelocity = R.transpose() * (v + w.cross(t));
            out.sensorAngularVelocity = R.transpose() * w;
            input.linear_velocity = out.sensorLinearVelocity;
            input.angular_velocity = out.sensorAngularVelocity;
            out.deskewed = true;
        } else {
            if (!noted_no_velocity_)
                noteOnce(noted_no_velocity_,
                         std::string("no recent robot velocity (velocity_source=") +
                             toString(options_.velocity_source) + "): frames are not deskewed",
                         mrpt::system::LVL_INFO);
        }
    }
    job.prepare_ms = msSince(start);
}

void TravelFilter::complete(TravelFrame& out, const FrameJob& job,
                            const travel::AlignedCloud& aligned, double segment_ms) {
    const Clock::time_point start = Clock::now();
    out.alignedRotation = aligned.rotation;
    out.aligned = &aligned;
    out.tracked = out.egoFromPoses = false;
    if (options_.track_objects) track(out, job.robot_pose);
    out.process_ms = job.prepare_ms + segment_ms + msSince(start);
}

void TravelFilter::track(TravelFrame& out, const std::optional<Eigen::Isometry3d>& robot) {
    if (out.timestamp == INVALID_TIMESTAMP) {
        noteOnce(noted_track_time_,
                 "'" + out.sensorLabel + "' without timestamp: its clusters are not tracked",
                 mrpt::system::LVL_WARN);
        return;
    }
    auto& tracker = trackers_[out.sensorLabel];
    if (!tracker) tracker = std::make_unique<travel::FrameTracker>(options_.tracking);
    if (robot) {
        // The aligned frame is levelled (z up), so only the robot's yaw turns it in the world:
        // composing a planar pose (odometry: no roll, pitch) with the levelling rotation would
        // tilt it by the robot's attitude. The pose the tracker gets is the sensor's position
        // and that yaw, in the sensor's axes.
        const Eigen::Isometry3d world_T_sensor = *robot * isometryOf(out.sensorPose);
        const Eigen::Matrix3d aligned_R_sensor = out.alignedRotation.cast<double>();
        const Eigen::Matrix3d world_R_aligned =
            world_T_sensor.linear() * aligned_R_sensor.transpose();
        out.worldTSensor.linear() = yawRotation(yawOf(world_R_aligned)) * aligned_R_sensor;
        out.worldTSensor.translation() = world_T_sensor.translation();
        out.egoFromPoses = true;
    } else if (!noted_track_registration_) {
        noteOnce(noted_track_registration_,
                 "no robot poses or odometry: tracking takes the ego-motion from registering "
                 "consecutive scans",
                 mrpt::system::LVL_INFO);
    }
    out.worldTSensor = tracker->update(seconds(out.timestamp), out.cloud, out.result.labels,
                                       out.alignedRotation, out.result.clusters,
                                       robot ? &out.worldTSensor : nullptr, &out.result.cluster_id);
    out.tracked = true;
}

const travel::AlignedCloud& TravelFilter::aligned(const std::string& sensor_label) const {
    const auto it = pipelines_.find(sensor_label);
    if (it == pipelines_.end() || !it->second.pipeline)
        throw std::out_of_range("TravelFilter::aligned: no frame processed yet for sensor '" +
                                sensor_label + "'");
    return it->second.pipeline->aligned();
}

void TravelFilter::processImu(const mrpt::obs::CObservationIMU& imu) {
    using namespace mrpt::obs;
    if (imu.timestamp == INVALID_TIMESTAMP) {
        noteOnce(noted_imu_time_, "IMU '" + imu.sensorLabel + "' without timestamp: ignored",
                 mrpt::system::LVL_WARN);
        return;
    }
    mrpt::poses::CPose3D imu_pose;
    imu.getSensorPose(imu_pose);
    const auto has = [&](TIMUDataIndex i) { return imu.has(i); };
    travel::ImuReading reading;
    if (has(IMU_ORI_QUAT_X) && has(IMU_ORI_QUAT_Y) && has(IMU_ORI_QUAT_Z) && has(IMU_ORI_QUAT_W))
        reading.orientation = Eigen::Quaterniond(imu.get(IMU_ORI_QUAT_W), imu.get(IMU_ORI_QUAT_X),
                                                 imu.get(IMU_ORI_QUAT_Y), imu.get(IMU_ORI_QUAT_Z));
    if (has(IMU_ROLL)) reading.roll = imu.get(IMU_ROLL);
    if (has(IMU_PITCH)) reading.pitch = imu.get(IMU_PITCH);
    if (has(IMU_YAW)) reading.yaw = imu.get(IMU_YAW);
    if (has(IMU_WX) && has(IMU_WY) && has(IMU_WZ))
        reading.angular_velocity =
            Eigen::Vector3d(imu.get(IMU_WX), imu.get(IMU_WY), imu.get(IMU_WZ));
    motion_.addImu(seconds(imu.timestamp), rotationOf(imu_pose), reading);
}

void TravelFilter::processOdometry(const mrpt::obs::CObservationOdometry& odometry) {
    if (odometry.timestamp == INVALID_TIMESTAMP) {
        noteOnce(noted_odometry_time_,
                 "odometry '" + odometry.sensorLabel + "' without timestamp: ignored",
                 mrpt::system::LVL_WARN);
        return;
    }
    addOdometry(odometry.odometry, odometry.timestamp,
                odometry.hasVelocities ? &odometry.velocityLocal : nullptr);
}

void TravelFilter::processAction(const mrpt::obs::CActionRobotMovement2D& action,
                                 const mrpt::poses::CPose2D& odometry_pose) {
    if (action.timestamp == INVALID_TIMESTAMP) {
        setOdometryPose(mrpt::poses::CPose3D(odometry_pose), INVALID_TIMESTAMP);
        return;
    }
    addOdometry(odometry_pose, action.timestamp,
                action.hasVelocities ? &action.velocityLocal : nullptr);
}

void TravelFilter::addOdometry(const mrpt::poses::CPose2D& pose, mrpt::Clock::time_point t,
                               const mrpt::math::TTwist2D* velocity) {
    setOdometryPose(mrpt::poses::CPose3D(pose), t);
    motion_.addPlanarOdometry(seconds(t), pose.x(), pose.y(), pose.phi(),
                              velocity ? std::optional<Eigen::Vector3d>(Eigen::Vector3d(
                                             velocity->vx, velocity->vy, velocity->omega))
                                       : std::nullopt);
}

void TravelFilter::setRobotPose(const mrpt::poses::CPose3D& pose, mrpt::Clock::time_point t) {
    if (t == INVALID_TIMESTAMP) return;
    motion_.addRobotPose(seconds(t), isometryOf(pose));
    robot_pose_ = {true, true, t, isometryOf(pose)};
}

void TravelFilter::setOdometryPose(const mrpt::poses::CPose3D& pose, mrpt::Clock::time_point t) {
    odometry_pose_ = {true, t != INVALID_TIMESTAMP, t, isometryOf(pose)};
}

std::optional<Eigen::Isometry3d> TravelFilter::egoPoseAt(mrpt::Clock::time_point t) const {
    // Untimed samples (odometry actions without a timestamp) count as current.
    const auto fresh = [&](const PoseSample& s) {
        return s.valid && (!s.timed || t == INVALID_TIMESTAMP ||
                           std::abs(seconds(t) - seconds(s.t)) <= options_.max_motion_age);
    };
    const PoseSample* sample = fresh(robot_pose_)      ? &robot_pose_
                               : fresh(odometry_pose_) ? &odometry_pose_
                                                       : nullptr;
    if (!sample) return std::nullopt;
    Eigen::Isometry3d pose = sample->pose;
    if (t == INVALID_TIMESTAMP) return pose;
    const travel::MotionEstimate motion = motion_.estimateAt(seconds(t));
    // A measured attitude gives the roll and pitch that planar poses (odometry) lack: the sensor,
    // high on a pitching robot, moves back and forth by tenths of a metre with them.
    if (motion.attitude) {
        const Eigen::Matrix3d roll_pitch = yawRotation(-yawOf(*motion.attitude)) * *motion.attitude;
        pose.linear() = yawRotation(yawOf(pose.linear())) * roll_pitch;
    }
    if (!sample->timed) return pose;
    // Carried from the sample's time to t at the robot's velocity (robot frame), to first order.
    const double dt = seconds(t) - seconds(sample->t);
    if (dt != 0 && motion.linear_velocity && motion.angular_velocity) {
        const Eigen::Vector3d rotation = *motion.angular_velocity * dt;
        Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
        if (rotation.norm() > 0)
            step.linear() =
                Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).toRotationMatrix();
        step.translation() = *motion.linear_velocity * dt;
        pose = pose * step;
    }
    return pose;
}

travel::MotionEstimate TravelFilter::motionAt(mrpt::Clock::time_point t) const {
    return motion_.estimateAt(seconds(t));
}

AlignedInWorld alignedInWorld(const TravelFrame& frame, const mrpt::poses::CPose3D& robotPose) {
    const mrpt::poses::CPose3D sensor_in_world = robotPose + frame.sensorPose;
    AlignedInWorld out;
    out.rotation = sensor_in_world.getRotationMatrix().asEigen().cast<float>() *
                   frame.alignedRotation.transpose();
    out.origin = Eigen::Vector3f(float(sensor_in_world.x()), float(sensor_in_world.y()),
                                 float(sensor_in_world.z()));
    return out;
}

}  // namespace travel_mrpt
