// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/MapExport.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/img/color_maps.h>
#include <mrpt/maps/CHeightGridMap2D.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "travel/io/BinaryFile.hpp"
#include "travel/viz/GridPictures.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/GzFileOutput.hpp"

namespace travel_mrpt {
namespace {

travel::viz::Rgb jet(float t) {
    const mrpt::img::TColor c = mrpt::img::colormap(mrpt::img::cmJET, t);
    return {c.R, c.G, c.B};
}

/// Enlarged so that the longer side has at least min_side pixels, as a CImage.
mrpt::img::CImage pngImage(const travel::viz::Raster& raster, int min_side) {
    const int side = std::max(raster.width, raster.height);
    mrpt::img::CImage img;
    toImage(travel::viz::enlarge(raster, side > 0 ? (min_side + side - 1) / side : 1), img);
    return img;
}

template <class T>
void writeSerializedGz(const T& object, const std::string& path) {
    travel::PartFile part(path);  // a failed write leaves neither a cut file nor a part file
    GzFileOutput file(part.part(), part.path());
    auto archive = mrpt::serialization::archiveFrom(file);
    archive << object;
    file.close();
    part.commit();
}

}  // namespace

void toOccupancyGrid(const CTraversabilityMap& map, mrpt::maps::COccupancyGridMap2D& out) {
    const TraversabilityGrid& grid = map.grid();
    const GridGeometry& g = grid.geometry();
    out.setSize(float(g.min_x), float(g.max_x), float(g.min_y), float(g.max_y), float(g.resolution),
                0.5f);
    for (int iy = 0; iy < grid.sizeY(); ++iy)
        for (int ix = 0; ix < grid.sizeX(); ++ix) {
            const CellState st = map.state(grid.cellIndex(ix, iy));
            if (st == CellState::Unknown) continue;
            out.setPos(grid.cellCenterX(ix), grid.cellCenterY(iy),
                       st == CellState::Traversable ? 1.0f : 0.0f);
        }
}

void toHeightGrid(const CTraversabilityMap& map, mrpt::maps::CHeightGridMap2D& out) {
    const TraversabilityGrid& grid = map.grid();
    const GridGeometry& g = grid.geometry();
    out.setSize(g.min_x, g.max_x, g.min_y, g.max_y, g.resolution);
    out.fill(mrpt::maps::THeightGridmapCell());
    for (int iy = 0; iy < grid.sizeY(); ++iy)
        for (int ix = 0; ix < grid.sizeX(); ++ix) {
            const long c = grid.cellIndex(ix, iy);
            const float h = grid.groundHeight(c);
            if (!std::isfinite(h)) continue;
            auto* cell = out.cellByPos(grid.cellCenterX(ix), grid.cellCenterY(iy));
            if (!cell) continue;
            const float spread = grid.groundSpread(c);
            cell->h = h;
            cell->var = spread;
            cell->u = h;
            cell->v = h * h + spread * spread;
            cell->w = 1;  // observed
        }
}

mrpt::img::CImage traversabilityImage(const CTraversabilityMap& map, bool north_up) {
    mrpt::img::CImage img;
    toImage(travel::viz::traversabilityRaster(map.grid(), map.options(), north_up), img);
    return img;
}

mrpt::img::CImage heightImage(const CTraversabilityMap& map, double z_lo, double z_hi) {
    mrpt::img::CImage img;
    toImage(travel::viz::heightRaster(map.grid(), z_lo, z_hi, jet), img);
    return img;
}

void saveOctoMap(const CTraversabilityMap& map, const std::string& path) {
    // Through a stream: OctoMap's writeBinaryConst(path) does not check its writes.
    travel::writeThroughPartFile(path,
                                 [&](std::ostream& out) { map.octree().writeBinaryConst(out); });
}

void saveOccupancyGridGz(const CTraversabilityMap& map, const std::string& path) {
    mrpt::maps::COccupancyGridMap2D grid;
    toOccupancyGrid(map, grid);
    writeSerializedGz(grid, path);
}

void saveHeightGridGz(const CTraversabilityMap& map, const std::string& path) {
    mrpt::maps::CHeightGridMap2D grid;
    toHeightGrid(map, grid);
    writeSerializedGz(grid, path);
}

void save3DScene(const CTraversabilityMap& map, const std::string& path) {
    mrpt::opengl::COpenGLScene scene;
    auto objects = mrpt::opengl::CSetOfObjects::Create();
    map.getVisualizationInto(*objects);
    scene.insert(objects);
    writeSerializedGz(scene, path);  // what COpenGLScene::saveToFile writes, checked
}

std::vector<std::string> exportAll(const CTraversabilityMap& map, const std::string& prefix,
                                   int min_png_side) {
    std::vector<std::string> written;
    const auto note = [&](const std::string& path) { written.push_back(path); };

    saveOctoMap(map, prefix + ".bt");
    note(prefix + ".bt");
    saveOccupancyGridGz(map, prefix + "_grid.gridmap.gz");
    note(prefix + "_grid.gridmap.gz");
    saveHeightGridGz(map, prefix + "_height.gridmap.gz");
    note(prefix + "_height.gridmap.gz");
    savePicture(
        pngImage(travel::viz::traversabilityRaster(map.grid(), map.options()), min_png_side),
        prefix + "_traversability.png");
    note(prefix + "_traversability.png");
    {
        mrpt::maps::COccupancyGridMap2D grid;
        toOccupancyGrid(map, grid);
        mrpt::img::CImage image;
        grid.getAsImage(image);  // what saveAsBitmapFile writes
        savePicture(image, prefix + "_occupancy.png");
        note(prefix + "_occupancy.png");
    }
    savePicture(pngImage(travel::viz::heightRaster(map.grid(), 0, 0, jet), min_png_side),
                prefix + "_height.png");
    note(prefix + "_height.png");
    save3DScene(map, prefix + ".3Dscene");
    note(prefix + ".3Dscene");
    return written;
}

}  // namespace travel_mrpt
