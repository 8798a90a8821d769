// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/RotatingScan.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace travel::io {
namespace {

/// As MRPT (and the Velodyne drivers) convert: x * pi / 180, in this order.
double radians(double deg) {
    return deg * 3.14159265358979323846 / 180.0;
}

}  // namespace

void ringOfLaser(const LaserCorrection* lasers, std::size_t n, uint16_t* ring) {
    std::array<uint16_t, kMaxLasers> by_elevation{};
    for (std::size_t i = 0; i < n; ++i) by_elevation[i] = static_cast<uint16_t>(i);
    std::stable_sort(by_elevation.begin(), by_elevation.begin() + n, [&](uint16_t a, uint16_t b) {
        return lasers[a].vertical_deg < lasers[b].vertical_deg;
    });
    for (std::size_t rank = 0; rank < n; ++rank)
        ring[by_elevation[rank]] = static_cast<uint16_t>(rank);
}

void rangeImageToCloud(const RangeImageScan& scan, const LaserCorrection* lasers, PointCloud& out) {
    out.clear();
    const std::size_t rows = scan.rows;
    std::array<uint16_t, kMaxLasers> ring{};
    ringOfLaser(lasers, rows, ring.data());
    std::array<float, kMaxLasers> cos_vert{}, sin_vert{}, vert_offset{}, horiz_offset{},
        azimuth_corr{}, firing_delay{};  // firing_delay in columns
    for (std::size_t r = 0; r < rows; ++r) {
        const LaserCorrection& lc = lasers[r];
        cos_vert[r] = static_cast<float>(std::cos(radians(lc.vertical_deg)));
        sin_vert[r] = static_cast<float>(std::sin(radians(lc.vertical_deg)));
        vert_offset[r] = static_cast<float>(lc.vertical_offset);
        horiz_offset[r] = static_cast<float>(lc.horizontal_offset);
        azimuth_corr[r] = static_cast<float>(radians(lc.azimuth_deg));
        firing_delay[r] = static_cast<float>(scan.laser_delay_in_columns * static_cast<double>(r));
    }

    const bool has_time = scan.sweep_duration > 0;
    const float range_scale = static_cast<float>(scan.range_resolution);
    const double azimuth_step = scan.azimuth_span / static_cast<double>(scan.sweep_columns);
    const double time_step = scan.sweep_duration / static_cast<double>(scan.sweep_columns);
    const auto at = [&](std::size_t r, std::size_t c) { return r * scan.columns + c; };

    std::size_t num_returns = 0;
    for (std::size_t c = 0; c < scan.columns_used; ++c)
        for (std::size_t r = 0; r < rows; ++r) num_returns += scan.ranges[at(r, c)] != 0;
    out.reserve(num_returns);
    out.ring.reserve(num_returns);
    if (has_time) out.time.reserve(num_returns);

    for (std::size_t c = 0; c < scan.columns_used; ++c) {
        for (std::size_t r = 0; r < rows; ++r) {
            const uint16_t raw = scan.ranges[at(r, c)];
            if (raw == 0) continue;  // no return
            const double column = static_cast<double>(c) + firing_delay[r];
            const float d = range_scale * static_cast<float>(raw);
            // Velodyne azimuth grows clockwise seen from above: +y is Velodyne -x.
            const float az =
                static_cast<float>(scan.start_azimuth + azimuth_step * column) + azimuth_corr[r];
            const float cos_az = std::cos(az), sin_az = std::sin(az);
            const float xy = d * cos_vert[r];
            out.push_back(xy * cos_az + horiz_offset[r] * sin_az,
                          -(xy * sin_az - horiz_offset[r] * cos_az),
                          d * sin_vert[r] + vert_offset[r],
                          scan.intensity ? static_cast<float>(scan.intensity[at(r, c)]) : 0.f);
            out.ring.push_back(ring[r]);
            if (has_time) out.time.push_back(static_cast<float>(time_step * column));
        }
    }
}

}  // namespace travel::io
