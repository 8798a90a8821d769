// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Velodyne-style rotating scans: lasers indexed in FIRING order, each with its calibration
// (db.xml); TRAVEL wants rings in ELEVATION order and points in the sensor frame. The MRPT
// layer fills these from VelodyneCalibration and CObservationRotatingScan.
#pragma once

#include <cstddef>
#include <cstdint>

#include "travel/PointCloud.hpp"

namespace travel::io {

/// Enough for every Velodyne/Ouster model; fixed-size tables keep decoding allocation-free.
constexpr std::size_t kMaxLasers = 256;

/// One laser's calibration, as in a Velodyne db.xml.
struct LaserCorrection {
    double vertical_deg = 0;       ///< elevation of the beam
    double vertical_offset = 0;    ///< [m] along z
    double horizontal_offset = 0;  ///< [m] perpendicular to the beam, in the xy plane
    double azimuth_deg = 0;        ///< added to the column's azimuth
};

/// ring[k] = rank of laser k's elevation (0 = lowest); ties keep laser order. n <= kMaxLasers.
void ringOfLaser(const LaserCorrection* lasers, std::size_t n, uint16_t* ring);

/// A scan stored as a range image: row r = laser r (firing order), column c = azimuth step c.
struct RangeImageScan {
    const uint16_t* ranges = nullptr;    ///< rows x columns, row-major; 0 = no return
    const uint8_t* intensity = nullptr;  ///< same layout, or null
    std::size_t rows = 0, columns = 0;   ///< as stored; rows <= kMaxLasers
    std::size_t columns_used = 0;        ///< only columns [0, columns_used) are decoded
    /// Columns of a full sweep: sets the azimuth and time step of a column.
    std::size_t sweep_columns = 0;
    /// Firing delay of laser r after its column's azimuth: r * this (in columns).
    double laser_delay_in_columns = 0;
    double range_resolution = 0;                 ///< [m] per range unit
    double start_azimuth = 0, azimuth_span = 0;  ///< [rad]
    double sweep_duration = 0;                   ///< [s]; 0: no per-point times
};

/// Decodes every return of the used columns into `out` (cleared), column by column (firing
/// order, like the Velodyne packet decoder), with ring and, when the sweep duration is known,
/// per-point time since the first column. lasers[r] calibrates row r.
void rangeImageToCloud(const RangeImageScan& scan, const LaserCorrection* lasers, PointCloud& out);

}  // namespace travel::io
