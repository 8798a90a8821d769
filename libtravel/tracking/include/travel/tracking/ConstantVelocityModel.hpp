// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The motion model of one track: a linear Kalman filter on the horizontal state
// [x, y, vx, vy] (world frame, metres and m/s) with a constant velocity and white-noise
// acceleration (the discrete Wiener process acceleration model of Bar-Shalom, "Estimation with
// Applications to Tracking and Navigation", Sec. 6.3.2). Objects move over the ground, so z is
// not filtered: the tracker keeps the last measured height.
#pragma once

#include <Eigen/Core>

namespace travel {

class ConstantVelocityModel {
  public:
    using State = Eigen::Vector4d;
    using Covariance = Eigen::Matrix4d;

    /// At rest at `position`, with the given 1-sigma of position [m] and velocity [m/s].
    void start(const Eigen::Vector2d& position, double position_sigma, double velocity_sigma);
    /// Like start(), but moving with the velocity (and its covariance) of `other`: an object
    /// found again after an occlusion keeps the velocity its old track had.
    void startWithVelocityOf(const Eigen::Vector2d& position, double position_sigma,
                             const ConstantVelocityModel& other);
    /// Moves the state `dt` seconds ahead (dt <= 0: nothing); `acceleration_sigma` [m/s^2].
    void predict(double dt, double acceleration_sigma);
    /// Moves the position estimate by `delta` [m] (a new reference point), velocity unchanged.
    void shift(const Eigen::Vector2d& delta) { x_.head<2>() += delta; }
    /// Fuses a measured position with 1-sigma `position_sigma` [m] per axis.
    void correct(const Eigen::Vector2d& position, double position_sigma);
    /// Fuses a measured position with the 2x2 covariance `noise` [m^2] (an anisotropic
    /// measurement: a face fixes the position across itself, not along it).
    void correct(const Eigen::Vector2d& position, const Eigen::Matrix2d& noise);

    Eigen::Vector2d position() const { return x_.head<2>(); }
    Eigen::Vector2d velocity() const { return x_.tail<2>(); }
    /// The 2x2 covariance of the velocity [(m/s)^2].
    Eigen::Matrix2d velocityCovariance() const { return P_.bottomRightCorner<2, 2>(); }
    const State& state() const { return x_; }
    const Covariance& covariance() const { return P_; }

  private:
    State x_ = State::Zero();
    Covariance P_ = Covariance::Identity();
};

}  // namespace travel
