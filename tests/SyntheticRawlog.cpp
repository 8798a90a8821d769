// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "SyntheticRawlog.hpp"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/VelodyneCalibration.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "travel/sim/SyntheticLidar.hpp"

namespace travel_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kRangeResolution = 0.002;  // [m], as MRPT's Velodyne conversion
constexpr double kNumericStep = 1e-4;       // [s] for numerical derivatives

/// The robot's true motion: a constant-speed turn over the terrain while pitching and rolling.
class Trajectory {
  public:
    Trajectory(const travel::sim::Scene& scene, const SyntheticRawlogOptions& o)
        : scene_(scene), o_(o) {}

    Eigen::Isometry3d robotPose(double t) const {
        const double yaw = o_.yaw_rate * t;
        double x, y;
        if (std::abs(o_.yaw_rate) > 1e-12) {
            const double r = o_.speed / o_.yaw_rate;
            x = kStart.x() + r * std::sin(yaw);
            y = kStart.y() + r * (1.0 - std::cos(yaw));
        } else {
            x = kStart.x() + o_.speed * t, y = kStart.y();
        }
        const double pitch =
            o_.pitch_amplitude_deg * kDeg * std::sin(2 * kPi * o_.pitch_frequency_hz * t);
        const double roll =
            o_.roll_amplitude_deg * kDeg * std::sin(2 * kPi * o_.roll_frequency_hz * t + 0.7);
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                      Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                      Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                         .toRotationMatrix();
        T.translation() = Eigen::Vector3d(x, y, scene_.terrainHeight(x, y));
        return T;
    }

    /// Robot-frame linear and angular velocity (central differences).
    void robotTwist(double t, Eigen::Vector3d& v, Eigen::Vector3d& w) const {
        const Eigen::Isometry3d a = robotPose(t - kNumericStep), b = robotPose(t + kNumericStep);
        const Eigen::Isometry3d c = robotPose(t);
        v = c.linear().transpose() * (b.translation() - a.translation()) / (2 * kNumericStep);
        const Eigen::AngleAxisd delta(a.linear().transpose() * b.linear());
        w = delta.axis() * delta.angle() / (2 * kNumericStep);
    }

  private:
    inline static const Eigen::Vector2d kStart{-20.0, 0.0};
    const travel::sim::Scene& scene_;
    const SyntheticRawlogOptions& o_;
};

mrpt::Clock::time_point clockAt(double seconds) {
    return mrpt::Clock::fromDouble(seconds);
}

}  // namespace

travel::sim::Scene movingRobotScene() {
    using namespace travel::sim;
    Scene s;
    // Road |y| < 6 between 0.15 m kerbs and raised sidewalks.
    s.steps.push_back({{0.0, 6.0}, {0.0, 1.0}, 0.15});
    s.steps.push_back({{0.0, -6.0}, {0.0, -1.0}, 0.15});
    s.bumps.push_back({{-2.0, -2.0}, 0.3, 3.0});
    s.bumps.push_back({{22.0, 3.0}, 0.25, 2.5});
    s.roughness = {0.01, 1.5};
    uint32_t id = 1;
    for (const Eigen::Vector2d& c :
         {Eigen::Vector2d(-6.0, -4.2), Eigen::Vector2d(8.0, 4.3), Eigen::Vector2d(18.0, -4.2),
          Eigen::Vector2d(-32.0, 4.2), Eigen::Vector2d(30.0, 4.3)}) {
        Box car;
        car.id = id++;
        car.centre = c;
        s.boxes.push_back(car);
    }
    for (const Eigen::Vector2d& c :
         {Eigen::Vector2d(-15.0, 7.0), Eigen::Vector2d(0.0, 7.5), Eigen::Vector2d(15.0, -7.5),
          Eigen::Vector2d(28.0, 7.0), Eigen::Vector2d(-28.0, -7.0)}) {
        Pole pole;
        pole.id = id++;
        pole.centre = c;
        pole.radius = 0.15;
        s.poles.push_back(pole);
    }
    Wall north;
    north.id = id++, north.a = {-45.0, 12.0}, north.b = {45.0, 12.0}, north.height = 3.0;
    Wall south;
    south.id = id++, south.a = {-30.0, -11.0}, south.b = {10.0, -11.0}, south.height = 1.2;
    s.walls = {north, south};
    s.validate();
    return s;
}

SyntheticRawlog makeSyntheticRawlog(const SyntheticRawlogOptions& o) {
    using namespace mrpt::obs;
    if (o.frames < 1 || o.columns < 16 || !(o.sweep_period > 0))
        throw std::invalid_argument(
            "makeSyntheticRawlog: need frames >= 1, columns >= 16, "
            "sweep_period > 0");
    const travel::sim::Scene scene = movingRobotScene();
    const Trajectory trajectory(scene, o);
    std::mt19937 rng(o.seed);
    std::normal_distribution<double> normal(0.0, 1.0);

    travel::sim::LidarModel model = travel::sim::LidarModel::vlp16(o.columns);
    model.clockwise = true;
    model.order = travel::sim::PointOrder::ColumnMajor;
    model.sweep_period = o.sweep_period;
    model.range_noise_sigma = o.range_noise;
    model.min_range = 0.5;
    model.max_range = 100.0;

    const VelodyneCalibration& calib = VelodyneCalibration::LoadDefaultCalibration("VLP16");
    const std::size_t rows = calib.laser_corrections.size();
    if (rows != model.numBeams())
        throw std::runtime_error("makeSyntheticRawlog: MRPT's VLP16 calibration is not 16 lasers");
    // Ring (elevation rank) -> laser id (firing order), as rotatingScanToTravelCloud inverts it.
    std::vector<std::size_t> laser_of_ring(rows);
    {
        std::vector<std::size_t> ids(rows);
        for (std::size_t i = 0; i < rows; ++i) ids[i] = i;
        std::stable_sort(ids.begin(), ids.end(), [&](std::size_t a, std::size_t b) {
            return calib.laser_corrections[a].verticalCorrection <
                   calib.laser_corrections[b].verticalCorrection;
        });
        for (std::size_t ring = 0; ring < rows; ++ring) laser_of_ring[ring] = ids[ring];
    }

    const mrpt::poses::CPose3D sensor_on_robot(o.sensor_offset.x(), o.sensor_offset.y(),
                                               o.sensor_offset.z(), 0.0, o.mount_pitch_deg * kDeg,
                                               0.0);
    Eigen::Isometry3d robot_T_sensor = Eigen::Isometry3d::Identity();
    robot_T_sensor.linear() = sensor_on_robot.getRotationMatrix().asEigen();
    robot_T_sensor.translation() = o.sensor_offset;

    struct Timed {
        double t;
        int order;  // motion records before a LiDAR frame of the same time
        std::shared_ptr<mrpt::serialization::CSerializable> record;
    };
    std::vector<Timed> timed;
    SyntheticRawlog out;

    // ---- LiDAR sweeps ----
    std::vector<Eigen::Isometry3d> column_poses(static_cast<std::size_t>(o.columns));
    travel::sim::Scan scan;
    const auto cols = static_cast<std::size_t>(o.columns);
    std::vector<uint8_t> cls_image(rows * cols);
    std::vector<uint32_t> instance_image(rows * cols);
    std::vector<int> point_of_cell(rows * cols);
    for (int k = 0; k < o.frames; ++k) {
        const double t0 = k * o.sweep_period;
        for (int c = 0; c < o.columns; ++c)
            column_poses[static_cast<std::size_t>(c)] =
                trajectory.robotPose(t0 + o.sweep_period * c / o.columns) * robot_T_sensor;
        model.seed = o.seed * 1000u + static_cast<uint32_t>(k);
        travel::sim::scanMoving(scene, model, column_poses, scan);

        auto obs = CObservationRotatingScan::Create();
        obs->sensorLabel = "VLP16";
        obs->timestamp = clockAt(o.start_time + t0);
        obs->lidarModel = "VLP16";
        obs->rowCount = static_cast<uint16_t>(rows);
        obs->columnCount = static_cast<uint16_t>(cols);
        obs->rangeImage.setZero(static_cast<int>(rows), static_cast<int>(cols));
        obs->intensityImage.setZero(static_cast<int>(rows), static_cast<int>(cols));
        obs->rangeResolution = kRangeResolution;
        obs->startAzimuth = 0.0;
        obs->azimuthSpan = 2 * kPi;
        obs->sweepDuration = o.sweep_period;
        obs->minRange = model.min_range;
        obs->maxRange = model.max_range;
        obs->sensorPose = sensor_on_robot;

        std::fill(point_of_cell.begin(), point_of_cell.end(), -1);
        for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
            const double range = std::sqrt(double(scan.cloud.x[i]) * scan.cloud.x[i] +
                                           double(scan.cloud.y[i]) * scan.cloud.y[i] +
                                           double(scan.cloud.z[i]) * scan.cloud.z[i]);
            const long raw = std::lround(range / kRangeResolution);
            if (raw < 1 || raw > 65535) continue;
            const std::size_t row = laser_of_ring[scan.cloud.ring[i]];
            const auto column = static_cast<std::size_t>(
                std::lround(scan.cloud.time[i] / o.sweep_period * o.columns));
            if (column >= cols) continue;
            obs->rangeImage(static_cast<int>(row), static_cast<int>(column)) =
                static_cast<uint16_t>(raw);
            obs->intensityImage(static_cast<int>(row), static_cast<int>(column)) =
                static_cast<uint8_t>(std::clamp(scan.cloud.intensity[i] * 255.f, 0.f, 255.f));
            point_of_cell[row * cols + column] = static_cast<int>(i);
        }
        // Truth in the adapter's order: column-major, rows in firing order, no-returns skipped.
        FrameTruth truth;
        for (std::size_t c = 0; c < cols; ++c)
            for (std::size_t r = 0; r < rows; ++r) {
                const int i = point_of_cell[r * cols + c];
                if (i < 0) continue;
                const auto p = static_cast<std::size_t>(i);
                truth.cls.push_back(scan.gt.cls[p]);
                truth.instance.push_back(scan.gt.instance[p]);
                truth.points.push_back(scan.cloud.x[p], scan.cloud.y[p], scan.cloud.z[p]);
                truth.points.ring.push_back(scan.cloud.ring[p]);
                truth.points.time.push_back(scan.cloud.time[p]);
            }
        out.truth.push_back(std::move(truth));
        out.frame_poses.push_back(trajectory.robotPose(t0));
        timed.push_back({t0, 1, obs});
    }

    // ---- IMU and odometry over the same span (and a little before the first sweep) ----
    const double t_end = o.frames * o.sweep_period;
    const auto imu_count = static_cast<int>(std::floor(t_end * o.imu_rate_hz));
    for (int i = -2; i <= imu_count; ++i) {
        const double t = i / o.imu_rate_hz;
        const Eigen::Isometry3d pose = trajectory.robotPose(t);
        Eigen::Vector3d v, w;
        trajectory.robotTwist(t, v, w);
        const Eigen::Vector3d tilt_noise(normal(rng), normal(rng), normal(rng));
        const Eigen::Matrix3d measured_R =
            pose.linear() * Eigen::AngleAxisd(o.attitude_noise_deg * kDeg * tilt_noise.norm(),
                                              tilt_noise.norm() > 0 ? tilt_noise.normalized()
                                                                    : Eigen::Vector3d::UnitX())
                                .toRotationMatrix();
        const Eigen::Quaterniond q(measured_R);
        auto imu = CObservationIMU::Create();
        imu->sensorLabel = "IMU";
        imu->timestamp = clockAt(o.start_time + t);
        imu->set(IMU_ORI_QUAT_X, q.x());
        imu->set(IMU_ORI_QUAT_Y, q.y());
        imu->set(IMU_ORI_QUAT_Z, q.z());
        imu->set(IMU_ORI_QUAT_W, q.w());
        imu->set(IMU_WX, w.x() + o.gyro_noise * normal(rng));
        imu->set(IMU_WY, w.y() + o.gyro_noise * normal(rng));
        imu->set(IMU_WZ, w.z() + o.gyro_noise * normal(rng));
        timed.push_back({t, 0, imu});
    }
    const auto odometry_count = static_cast<int>(std::floor(t_end * o.odometry_rate_hz));
    for (int i = -1; i <= odometry_count; ++i) {
        const double t = i / o.odometry_rate_hz;
        const Eigen::Isometry3d pose = trajectory.robotPose(t);
        Eigen::Vector3d v, w;
        trajectory.robotTwist(t, v, w);
        auto odometry = CObservationOdometry::Create();
        odometry->sensorLabel = "ODOMETRY";
        odometry->timestamp = clockAt(o.start_time + t);
        const double yaw = std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
        odometry->odometry =
            mrpt::poses::CPose2D(pose.translation().x(), pose.translation().y(), yaw);
        odometry->hasVelocities = true;
        // Wheel odometry: planar speed and yaw rate only.
        odometry->velocityLocal = mrpt::math::TTwist2D(v.x(), v.y(), w.z());
        timed.push_back({t, 0, odometry});
    }

    std::stable_sort(timed.begin(), timed.end(), [](const Timed& a, const Timed& b) {
        return a.t != b.t ? a.t < b.t : a.order < b.order;
    });
    for (Timed& item : timed) out.records.push_back(std::move(item.record));
    return out;
}

void writeRawlog(const SyntheticRawlog& rawlog, const std::string& path) {
    mrpt::io::CFileGZOutputStream file;
    if (!file.open(path)) throw std::runtime_error("cannot write rawlog '" + path + "'");
    auto archive = mrpt::serialization::archiveFrom(file);
    for (const auto& record : rawlog.records) archive << *record;
    file.close();
}

namespace {

/// Planar (x, y, yaw) part of a 3-D robot pose.
mrpt::poses::CPose2D planar(const Eigen::Isometry3d& T) {
    return mrpt::poses::CPose2D(T.translation().x(), T.translation().y(),
                                std::atan2(T.linear()(1, 0), T.linear()(0, 0)));
}

}  // namespace

void writeSensoryFrameRawlog(const SyntheticRawlog& rawlog, const std::string& path,
                             bool odometry_actions) {
    if (odometry_actions && rawlog.frame_poses.size() != rawlog.truth.size())
        throw std::invalid_argument("writeSensoryFrameRawlog: odometry actions need frame_poses");
    mrpt::io::CFileGZOutputStream file;
    if (!file.open(path)) throw std::runtime_error("cannot write rawlog '" + path + "'");
    auto archive = mrpt::serialization::archiveFrom(file);
    mrpt::obs::CSensoryFrame frame;
    const mrpt::obs::CActionCollection no_actions;
    std::size_t lidar_frame = 0;
    mrpt::poses::CPose2D previous;  // the odometer's zero: the world origin
    for (const auto& record : rawlog.records) {
        auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(record);
        if (!obs) continue;
        frame.insert(obs);
        if (dynamic_cast<const mrpt::obs::CObservationRotatingScan*>(obs.get())) {
            if (odometry_actions) {
                const mrpt::poses::CPose2D now = planar(rawlog.frame_poses[lidar_frame]);
                mrpt::obs::CActionRobotMovement2D move;
                move.timestamp = obs->timestamp;
                move.computeFromOdometry(now - previous,
                                         mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
                mrpt::obs::CActionCollection actions;
                actions.insert(move);
                archive << actions << frame;
                previous = now;
            } else {
                archive << no_actions << frame;
            }
            ++lidar_frame;
            frame.clear();
        }
    }
    file.close();
}

}  // namespace travel_test
