// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Structure-of-arrays point buffer: one std::vector per field, so that every stage streams
// only the fields it reads. Optional fields (ring, time) are empty when the sensor lacks them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "travel/EnumNames.hpp"

namespace travel {

struct PointCloud {
    /// Coordinates [m] in the sensor frame: origin at the LiDAR's optical centre, z up before
    /// the mount_* rotation (docs/input-contract.md, "Coordinate frame"). Same length each.
    std::vector<float> x, y, z;
    /// Any unit; carried to the outputs, not read by the segmentation (may stay empty).
    std::vector<float> intensity;
    /// Laser ring (0 = lowest elevation), empty when unknown.
    std::vector<uint16_t> ring;
    /// Per-point time [s] relative to the frame reference time, empty when unknown.
    std::vector<float> time;

    std::size_t size() const { return x.size(); }
    bool empty() const { return x.empty(); }
    bool hasRing() const { return !ring.empty() && ring.size() == x.size(); }
    bool hasTime() const { return !time.empty() && time.size() == x.size(); }

    void clear() { x.clear(), y.clear(), z.clear(), intensity.clear(), ring.clear(), time.clear(); }
    void reserve(std::size_t n) { x.reserve(n), y.reserve(n), z.reserve(n), intensity.reserve(n); }
    void push_back(float px, float py, float pz, float pi = 0.f) {
        x.push_back(px), y.push_back(py), z.push_back(pz), intensity.push_back(pi);
    }
    /// Resize the mandatory fields (x, y, z, intensity) and any optional field in use.
    void resize(std::size_t n) {
        x.resize(n), y.resize(n), z.resize(n), intensity.resize(n);
        if (!ring.empty()) ring.resize(n);
        if (!time.empty()) time.resize(n);
    }
};

/// One class per input point. The numeric values are the lower 16 bits of travel-kitti's
/// .label output, so they are part of the file format: never renumber.
enum class PointClass : uint8_t {
    Invalid = 0,    ///< NaN / inf / all-zero no-return / outside [min_range, max_range]
    Ground = 1,     ///< on a traversable terrain model (paper eq. 5)
    NonGround = 2,  ///< above the ground surface, or on a non-traversable node
    Outlier = 3,    ///< far below the ground surface (reflections, multipath)
};

inline constexpr EnumName<PointClass> kPointClassNames[] = {{PointClass::Invalid, "invalid"},
                                                            {PointClass::Ground, "ground"},
                                                            {PointClass::NonGround, "nonground"},
                                                            {PointClass::Outlier, "outlier"}};

inline const char* toString(PointClass c) {
    return nameOf(kPointClassNames, c);
}

}  // namespace travel
