// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/ConstantVelocityModel.hpp"

#include <Eigen/Dense>

namespace travel {

void ConstantVelocityModel::start(const Eigen::Vector2d& position, double position_sigma,
                                  double velocity_sigma) {
    x_ << position, 0.0, 0.0;
    P_.setZero();
    P_.diagonal() << position_sigma * position_sigma, position_sigma * position_sigma,
        velocity_sigma * velocity_sigma, velocity_sigma * velocity_sigma;
}

void ConstantVelocityModel::startWithVelocityOf(const Eigen::Vector2d& position,
                                                double position_sigma,
                                                const ConstantVelocityModel& other) {
    x_ << position, other.velocity();
    P_.setZero();
    P_.topLeftCorner<2, 2>().diagonal().setConstant(position_sigma * position_sigma);
    P_.bottomRightCorner<2, 2>() = other.velocityCovariance();
}

void ConstantVelocityModel::predict(double dt, double acceleration_sigma) {
    if (!(dt > 0)) return;
    Covariance F = Covariance::Identity();
    F(0, 2) = F(1, 3) = dt;
    // Q = G G^T sigma_a^2 with G = [dt^2/2, dt] per axis.
    const double q = acceleration_sigma * acceleration_sigma;
    const double a = 0.25 * dt * dt * dt * dt * q, b = 0.5 * dt * dt * dt * q, c = dt * dt * q;
    Covariance Q = Covariance::Zero();
    Q(0, 0) = Q(1, 1) = a;
    Q(0, 2) = Q(2, 0) = Q(1, 3) = Q(3, 1) = b;
    Q(2, 2) = Q(3, 3) = c;
    x_ = F * x_;
    P_ = F * P_ * F.transpose() + Q;
}

void ConstantVelocityModel::correct(const Eigen::Vector2d& position, double position_sigma) {
    correct(position, Eigen::Matrix2d::Identity() * (position_sigma * position_sigma));
}

void ConstantVelocityModel::correct(const Eigen::Vector2d& position, const Eigen::Matrix2d& noise) {
    // H = [I 0]: the innovation covariance is the top-left block plus R.
    const Eigen::Matrix2d S = P_.topLeftCorner<2, 2>() + noise;
    const Eigen::Matrix<double, 4, 2> K = P_.leftCols<2>() * S.inverse();
    x_ += K * (position - x_.head<2>());
    // Joseph form keeps P symmetric and positive definite.
    Eigen::Matrix4d IKH = Eigen::Matrix4d::Identity();
    IKH.leftCols<2>() -= K;
    P_ = IKH * P_ * IKH.transpose() + K * noise * K.transpose();
}

}  // namespace travel
