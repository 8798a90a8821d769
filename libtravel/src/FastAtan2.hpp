// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A vectorisable float atan2 (libm's is a call per point). RangeImage's azimuths and elevations
// and MountEstimator's polar bins use it.
#pragma once

#include <algorithm>
#include <cmath>

namespace travel::detail {

// atan2 with a degree-11 minimax polynomial on [0, 1]: max error 2e-6 rad (0.0001 deg, far
// below half a column). One division (no min/max selects feeding it, which made GCC compute
// both), Estrin evaluation and the octant applied in one step keep it short. Same results as
// std::atan2 for signed zeros and infinities, except atan2(0, 0), which is NaN here.
constexpr float kFastAtan2Pi = 3.14159265358979f;

inline float fastAtan2(float y, float x) {
    const float ax = std::fabs(x), ay = std::fabs(y);
    const float lo = std::min(ax, ay);
    const float t = lo / (ax + ay - lo);  // min / max, in [0, 1]
    const float t2 = t * t, t4 = t2 * t2;
    const float p01 = 0.99997726f - 0.33262347f * t2;
    const float p23 = 0.19354346f - 0.11643287f * t2;
    const float p45 = 0.05265332f - 0.01172120f * t2;
    const float atan_t = t * (p01 + t4 * (p23 + t4 * p45));
    // |y| > |x| gives pi/2 - a, x < 0 gives pi - a, both give pi/2 + a.
    const bool swapped = ay > ax, negative_x = x < 0.0f;
    const float offset = swapped ? 0.5f * kFastAtan2Pi : (negative_x ? kFastAtan2Pi : 0.0f);
    const float sign = swapped != negative_x ? -1.0f : 1.0f;
    return std::copysign(offset + sign * atan_t, y);
}

/// Largest error of fastAtan2 [rad] (2e-6 from the polynomial, float rounding of the result
/// near pi), with margin.
constexpr double kFastAtan2MaxError = 1e-5;

}  // namespace travel::detail
