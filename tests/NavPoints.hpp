// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Counting obstacle points in robot-frame boxes (nav tests).
#pragma once

#include "travel_mrpt/ObstacleSource.hpp"

namespace travel_test {

/// Obstacle points inside the robot-frame box [x0, x1] x [y0, y1].
inline int countIn(const travel_mrpt::ObstaclePoints& p, double x0, double x1, double y0,
                   double y1) {
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        n += p.x[i] >= x0 && p.x[i] <= x1 && p.y[i] >= y0 && p.y[i] <= y1;
    return n;
}

}  // namespace travel_test
