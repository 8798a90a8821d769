// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/viz/TrackPicture.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "travel/viz/BirdsEye.hpp"

namespace travel::viz {
namespace {

Rgb rgbOf(uint32_t colour) {
    return {uint8_t(colour >> 16), uint8_t(colour >> 8), uint8_t(colour)};
}

}  // namespace

Raster renderTracks(const std::vector<TrackFrame>& frames, const TrackPictureOptions& options) {
    Raster raster;
    raster.reset(options.size_px, options.size_px, {255, 255, 255});
    if (frames.empty()) return raster;
    float lo_x = frames[0].ego_x, hi_x = lo_x, lo_y = frames[0].ego_y, hi_y = lo_y;
    for (const TrackFrame& f : frames) {
        lo_x = std::min(lo_x, f.ego_x), hi_x = std::max(hi_x, f.ego_x);
        lo_y = std::min(lo_y, f.ego_y), hi_y = std::max(hi_y, f.ego_y);
    }
    const double cx = 0.5 * (lo_x + hi_x), cy = 0.5 * (lo_y + hi_y);
    const double half = 0.5 * std::max(hi_x - lo_x, hi_y - lo_y) + options.margin;
    const double px_per_m = 0.5 * options.size_px / half;
    // Image up = +x, image left = +y.
    const auto u = [&](double y) {
        return int(std::lround(0.5 * options.size_px - (y - cy) * px_per_m));
    };
    const auto v = [&](double x) {
        return int(std::lround(0.5 * options.size_px - (x - cx) * px_per_m));
    };

    // Each track's samples in frame order (std::map: drawn in id order, deterministic).
    std::map<uint32_t, std::vector<const TrackSample*>> tracks;
    for (const TrackFrame& f : frames)
        for (const TrackSample& s : f.tracks)
            if (s.track_id) tracks[s.track_id].push_back(&s);
    for (const auto& [id, samples] : tracks) {
        const Rgb c = rgbOf(clusterColour(id));
        for (std::size_t k = 1; k < samples.size(); ++k)
            raster.line(u(samples[k - 1]->y), v(samples[k - 1]->x), u(samples[k]->y),
                        v(samples[k]->x), c);
        const TrackSample& last = *samples.back();
        raster.fillRect(u(last.y) - 2, v(last.x) - 2, u(last.y) + 2, v(last.x) + 2, c);
        if (last.moving) {
            const int tip_u = u(last.y + last.vy), tip_v = v(last.x + last.vx);
            raster.line(u(last.y), v(last.x), tip_u, tip_v, {200, 0, 0});
            raster.circle(tip_u, tip_v, 2, {200, 0, 0});
        }
    }
    for (std::size_t k = 1; k < frames.size(); ++k)
        for (int d = -1; d <= 1; ++d)
            raster.line(u(frames[k - 1].ego_y) + d, v(frames[k - 1].ego_x), u(frames[k].ego_y) + d,
                        v(frames[k].ego_x), {0, 0, 0});
    return raster;
}

}  // namespace travel::viz
