// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Bird's-eye pictures of a labelled frame as mrpt::img::CImage (save them with savePicture).
// The drawing itself is travel::viz::renderBirdsEye (libtravel/viz, what is drawn and how);
// this layer copies its raster into a CImage and writes its text with CImage's bitmap font.
//
// MRPT headers stay out of this header (they are slow to compile): images are passed by
// reference to the forward-declared CImage; include <mrpt/img/CImage.h> where you use them.
#pragma once

#include <string>

#include "travel/viz/BirdsEye.hpp"

namespace mrpt::img {
class CImage;
}

namespace travel_mrpt {

using travel::viz::BirdsEyeOptions;
using travel::viz::clusterColour;

/// Copies a raster into `out` (resized, RGB).
void toImage(const travel::viz::Raster& raster, mrpt::img::CImage& out);
/// Copies a picture into `out` (resized, RGB) and writes its text in the 9x15 font.
void toImage(const travel::viz::Picture& picture, mrpt::img::CImage& out);

/// travel::viz::renderBirdsEye into an image (see there).
void renderBirdsEye(const travel::AlignedCloud& points,
                    const std::vector<travel::PointClass>& labels,
                    const std::vector<uint32_t>& cluster_id, const travel::TerrainModel* terrain,
                    const BirdsEyeOptions& opt, mrpt::img::CImage& out);

/// Two panels side by side, separated by a thin gap, into `out`. When a title is non-empty it
/// is written in a header band above its panel. Panels of different heights are top-aligned.
void sideBySide(const mrpt::img::CImage& a, const mrpt::img::CImage& b, const std::string& title_a,
                const std::string& title_b, mrpt::img::CImage& out);

/// Throws std::runtime_error unless `path` ends in .png, .jpg or .jpeg (any case): the names
/// savePicture() can write.
void requirePictureName(const std::string& path);
/// Writes `image` to `path` (PNG or JPEG by its extension) as X.part.png beside it, moved in
/// place once whole (travel::PartFile); on failure std::runtime_error naming `path` and the
/// reason, and the file an earlier write left under `path` stays as it was.
void savePicture(const mrpt::img::CImage& image, const std::string& path);

}  // namespace travel_mrpt
