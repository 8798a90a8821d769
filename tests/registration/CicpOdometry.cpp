// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "CicpOdometry.hpp"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/slam/CICP.h>

#include <cmath>

namespace travel::test {

struct CicpOdometry::State {
    mrpt::slam::CICP icp;
    mrpt::maps::CSimplePointsMap previous;
    bool first = true;
    mrpt::poses::CPose2D pose, step;  ///< world pose, last frame-to-frame motion
};

CicpOdometry::CicpOdometry() : state_(std::make_unique<State>()) {
    auto& o = state_->icp.options;
    o.ICP_algorithm = mrpt::slam::icpClassic;
    o.maxIterations = 100;
    // A car moves ~1 m between two 10 Hz scans; the guess (the last motion) is within ~0.3 m.
    o.thresholdDist = 1.5;
    o.thresholdAng = 0;
    o.ALFA = 0.5;
    o.smallestThresholdDist = 0.05;
    o.skip_cov_calculation = true;
}

CicpOdometry::~CicpOdometry() = default;

Eigen::Isometry3d CicpOdometry::add(const PointCloud& cloud) {
    mrpt::maps::CSimplePointsMap current;
    int k = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double r = std::hypot(cloud.x[i], cloud.y[i]);
        if (r < kMinRange || r > kMaxRange || cloud.z[i] < kMinZ || cloud.z[i] > kMaxZ) continue;
        if (k++ % kStride == 0) current.insertPoint(cloud.x[i], cloud.y[i], cloud.z[i]);
    }
    State& s = *state_;
    if (!s.first) {
        // The new scan's pose in the previous one's frame (m1 = previous, m2 = current).
        const auto pdf = s.icp.Align(&s.previous, &current, s.step);
        s.step = pdf->getMeanVal();
        s.pose = s.pose + s.step;
    }
    s.first = false;
    s.previous = std::move(current);
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.linear() = Eigen::AngleAxisd(s.pose.phi(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    out.translation() = Eigen::Vector3d(s.pose.x(), s.pose.y(), 0);
    return out;
}

}  // namespace travel::test
