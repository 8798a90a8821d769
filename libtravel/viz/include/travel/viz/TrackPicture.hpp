// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A bird's-eye picture of a tracked sequence in the world frame: the ego path in black, each
// confirmed track as a polyline of its positions in its cluster colour (clusterColour(track id),
// the colour RawLogViewer keeps per track), a dot on its last position, and a velocity arrow
// (1 s of motion) on moving tracks. Image up = +x, left = +y, like the frame pictures.
#pragma once

#include <cstdint>
#include <vector>

#include "travel/viz/Raster.hpp"

namespace travel::viz {

/// One tracked cluster in one frame, world frame.
struct TrackSample {
    uint32_t track_id = 0;
    float x = 0, y = 0;    ///< [m]
    float vx = 0, vy = 0;  ///< [m/s]
    bool moving = false;
};

struct TrackFrame {
    float ego_x = 0, ego_y = 0;  ///< sensor position [m]
    std::vector<TrackSample> tracks;
};

struct TrackPictureOptions {
    int size_px = 800;
    /// [m] what is shown around the ego path's bounding box.
    double margin = 25.0;
};

Raster renderTracks(const std::vector<TrackFrame>& frames, const TrackPictureOptions& options);

}  // namespace travel::viz
