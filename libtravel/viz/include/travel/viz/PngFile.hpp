// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A Raster saved as PNG without an image library (the apps that do not link MRPT's CImage):
// 8-bit RGB, zlib stream of stored (uncompressed) deflate blocks, so the file is about
// 3 bytes per pixel. Any PNG reader opens it; recompress it for documentation if size matters.
#pragma once

#include <string>

#include "travel/viz/Raster.hpp"

namespace travel::viz {

/// Writes `raster` to `path` through a part file (travel::writeThroughPartFile); throws
/// std::runtime_error naming the file when it cannot, the previous file under the name kept.
void writePng(const Raster& raster, const std::string& path);

}  // namespace travel::viz
