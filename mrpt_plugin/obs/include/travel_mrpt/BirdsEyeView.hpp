// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Bird's-eye pictures of a labelled frame, shared by travel-rawlog and travel-view. Headless:
// drawing goes to an mrpt::img::CImage (save it with saveToFile("x.png")), no X server needed.
//
// The picture is centred on the sensor, image up = +x (forward), image left = +y. Ground is
// green, non-ground red (grey when cluster ids are given: each cluster then gets its own colour,
// a hash of its id into a palette of well-separated hues), outliers blue; invalid points are not
// drawn. Optionally the traversable tri-grid nodes of the terrain model are outlined underneath.
//
// MRPT headers stay out of this header (they are slow to compile): images are passed by
// reference to the forward-declared CImage; include <mrpt/img/CImage.h> where you use them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/TerrainModel.hpp"

namespace mrpt::img {
class CImage;
}

namespace travel_mrpt {

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

/// Colour of cluster `id` (> 0): deterministic, the same id always gets the same colour.
/// Returned as 0xRRGGBB.
uint32_t clusterColour(uint32_t id);

/// Renders n points (x[i], y[i] in the frame of `terrain`, normally the aligned frame) with
/// their labels into `out` (resized to size_px x size_px, RGB). `cluster_id` is either empty (no
/// cluster colouring) or n long. `terrain` may be null. Throws std::invalid_argument on size
/// mismatches.
void renderBirdsEye(const float* x, const float* y, std::size_t n,
                    const std::vector<travel::PointClass>& labels,
                    const std::vector<uint32_t>& cluster_id, const travel::TerrainModel* terrain,
                    const BirdsEyeOptions& opt, mrpt::img::CImage& out);

/// Same, for a cloud (points in the same frame as `terrain`).
void renderBirdsEye(const travel::PointCloud& points, const std::vector<travel::PointClass>& labels,
                    const std::vector<uint32_t>& cluster_id, const travel::TerrainModel* terrain,
                    const BirdsEyeOptions& opt, mrpt::img::CImage& out);

/// Same, for the aligned coordinates of a pipeline (Pipeline::aligned()).
void renderBirdsEye(const travel::AlignedCloud& points,
                    const std::vector<travel::PointClass>& labels,
                    const std::vector<uint32_t>& cluster_id, const travel::TerrainModel* terrain,
                    const BirdsEyeOptions& opt, mrpt::img::CImage& out);

/// Two panels side by side, separated by a thin gap, into `out`. When a title is non-empty it
/// is written in a header band above its panel. Panels of different heights are top-aligned.
void sideBySide(const mrpt::img::CImage& a, const mrpt::img::CImage& b, const std::string& title_a,
                const std::string& title_b, mrpt::img::CImage& out);

/// Writes `image` as PNG (or any format saveToFile knows by extension); throws
/// std::runtime_error naming `path` on failure.
void savePicture(const mrpt::img::CImage& image, const std::string& path);

}  // namespace travel_mrpt
