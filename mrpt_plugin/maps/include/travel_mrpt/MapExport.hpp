// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Exports of a CTraversabilityMap in formats other tools read:
//   .bt             OctoMap binary (octomap::OcTree::readBinary, octovis)
//   .gridmap.gz     serialized COccupancyGridMap2D (MRPT apps and planners): traversable cells
//                   free (1), obstacle cells occupied (0), unknown 0.5
//   _height.gridmap.gz  serialized CHeightGridMap2D: mean ground height and its spread per cell
//   PNGs            traversability (green traversable, red obstacle, grey unknown), the
//                   occupancy grid as MRPT draws it, ground height (jet colour map, black =
//                   no ground); north (+y) up, +x right
//   .3Dscene        COpenGLScene for SceneViewer3D (grid texture + obstacle voxels)
// Every function throws std::runtime_error naming the file on failure. Each file is written
// beside its name and moved in place (travel::PartFile): a failed export leaves no part file,
// and the file of an earlier export under the name as it was.
#pragma once

#include <string>
#include <vector>

namespace mrpt::img {
class CImage;
}
namespace mrpt::maps {
class COccupancyGridMap2D;
class CHeightGridMap2D;
}  // namespace mrpt::maps

namespace travel_mrpt {

class CTraversabilityMap;

/// Same extent and resolution as the map's grid.
void toOccupancyGrid(const CTraversabilityMap& map, mrpt::maps::COccupancyGridMap2D& out);
void toHeightGrid(const CTraversabilityMap& map, mrpt::maps::CHeightGridMap2D& out);

/// One pixel per cell (travel::viz::traversabilityRaster, heightRaster). north_up: row 0 = max_y
/// (pictures); else row 0 = min_y (textures).
mrpt::img::CImage traversabilityImage(const CTraversabilityMap& map, bool north_up = true);
/// Ground height in jet colours over [z_lo, z_hi] (auto: observed range when z_lo >= z_hi).
mrpt::img::CImage heightImage(const CTraversabilityMap& map, double z_lo = 0, double z_hi = 0);

void saveOctoMap(const CTraversabilityMap& map, const std::string& path);
void saveOccupancyGridGz(const CTraversabilityMap& map, const std::string& path);
void saveHeightGridGz(const CTraversabilityMap& map, const std::string& path);
void save3DScene(const CTraversabilityMap& map, const std::string& path);

/// Writes every export with this prefix (see CTraversabilityMap::
/// saveMetricMapRepresentationToFile) and returns the paths written. PNGs are enlarged so the
/// longer side is at least min_png_side pixels.
std::vector<std::string> exportAll(const CTraversabilityMap& map, const std::string& prefix,
                                   int min_png_side = 800);

}  // namespace travel_mrpt
