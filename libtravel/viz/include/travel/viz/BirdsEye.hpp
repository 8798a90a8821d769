// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Bird's-eye pictures of a labelled frame, shared by travel-rawlog and travel-view (through
// travel_mrpt::renderBirdsEye, which saves them as PNG). Headless: everything but the text is
// drawn into a plain Raster; the text is returned as labels for the caller to write with its
// font (the MRPT layer uses CImage's bitmap fonts).
//
// The picture is centred on the sensor, image up = +x (forward), image left = +y. Ground is
// green, non-ground red (grey when cluster ids are given: each cluster then gets its own colour,
// a hash of its id into a palette of well-separated hues), outliers blue; invalid points are not
// drawn. Optionally the traversable tri-grid nodes of the terrain model are outlined underneath.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "travel/LabelledFrame.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/viz/Raster.hpp"

namespace travel::viz {

struct BirdsEyeOptions {
    int size_px = 800;                ///< image side [px]
    double metres_per_pixel = 0.075;  ///< scale (0.075: +/-30 m in 800 px)
    std::string title;                ///< first line, top left (empty: none)
    bool legend = true;
    bool scale_bar = true;
    bool range_rings = true;  ///< one ring per scale-bar length
    bool sensor_marker = true;
    /// Outline the traversable nodes of the terrain model (when one is given).
    bool draw_nodes = true;
    /// Also fill them faintly (makes the traversable area readable at a glance).
    bool fill_nodes = true;
    int point_px = 2;  ///< side of the square drawn per point [px]
};

/// A line of black text whose top-left corner is (x, y). The layout assumes the 9x15 bitmap
/// font (9 px per character).
struct TextLabel {
    int x = 0, y = 0;
    std::string text;
};

struct Picture {
    Raster raster;
    std::vector<TextLabel> text;  ///< to be written over the raster, in order
};

/// Colour of cluster `id` (> 0): deterministic, the same id always gets the same colour.
/// Returned as 0xRRGGBB.
uint32_t clusterColour(uint32_t id);

/// Colour of a cluster in the 3-D views: its track's, clusterColour(track_id), when the
/// tracker continued a track with it (so an object keeps its colour from frame to frame), else
/// clusterColour(id).
uint32_t clusterColour(const ClusterSummary& cluster);

/// Colour (0xRRGGBB) of a point of class `c` in every picture and 3-D view: ground green,
/// outliers blue, non-ground in its cluster's colour, grey when in no cluster while others are
/// clustered (`any_cluster`), red when nothing is clustered. 0 for invalid points (not drawn).
uint32_t pointColour(PointClass c, uint32_t cluster_id, bool any_cluster);

/// Renders n points (x[i], y[i] in the frame of `terrain`, normally the aligned frame) with
/// their labels. `cluster_id` is either empty (no cluster colouring) or n long. `terrain` may be
/// null. Throws std::invalid_argument on size mismatches.
Picture renderBirdsEye(const float* x, const float* y, std::size_t n,
                       const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id, const TerrainModel* terrain,
                       const BirdsEyeOptions& opt);

/// Same, for a cloud (points in the same frame as `terrain`).
Picture renderBirdsEye(const PointCloud& points, const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id, const TerrainModel* terrain,
                       const BirdsEyeOptions& opt);

/// Same, for the aligned coordinates of a pipeline (Pipeline::aligned()).
Picture renderBirdsEye(const AlignedCloud& points, const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id, const TerrainModel* terrain,
                       const BirdsEyeOptions& opt);

/// The differences between two labellings of the same n points: the golden classes as
/// renderBirdsEye draws them without clusters and terrain (ground green, non-ground red,
/// outliers blue), then every point with changed[i] != 0 (its class changed) in black, larger,
/// on top, with a legend entry. Throws std::invalid_argument on size mismatches.
Picture renderClassChanges(const float* x, const float* y, std::size_t n,
                           const std::vector<PointClass>& golden_labels,
                           const std::vector<uint8_t>& changed, const BirdsEyeOptions& opt);

/// Same, for a stored frame (its points, labels and clusters are the golden ones), drawn in its
/// levelled frame (alignedRotation).
Picture renderClassChanges(const LabelledFrame& golden, const std::vector<uint8_t>& changed,
                           const BirdsEyeOptions& opt);

}  // namespace travel::viz
