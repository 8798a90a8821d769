// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/MapExport.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/img/color_maps.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CHeightGridMap2D.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "travel_mrpt/CTraversabilityMap.hpp"

namespace travel_mrpt {
namespace {

void putPixel(mrpt::img::CImage& img, int u, int v, uint8_t r, uint8_t g, uint8_t b) {
    uint8_t* q = img.ptr<uint8_t>(unsigned(u), unsigned(v));
    q[0] = b, q[1] = g, q[2] = r;  // CImage stores BGR
}

template <class T>
void writeSerializedGz(const T& object, const std::string& path) {
    mrpt::io::CFileGZOutputStream file;
    if (!file.open(path)) throw std::runtime_error(path + ": cannot open for writing");
    auto archive = mrpt::serialization::archiveFrom(file);
    archive << object;
    file.close();
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
    const TraversabilityGrid& grid = map.grid();
    mrpt::img::CImage img(grid.sizeX(), grid.sizeY(), mrpt::img::CH_RGB);
    for (int iy = 0; iy < grid.sizeY(); ++iy)
        for (int ix = 0; ix < grid.sizeX(); ++ix) {
            const int v = north_up ? grid.sizeY() - 1 - iy : iy;
            const long c = grid.cellIndex(ix, iy);
            switch (map.state(c)) {
                case CellState::Traversable:
                    putPixel(img, ix, v, 70, 175, 70);
                    break;
                case CellState::Obstacle:
                    putPixel(img, ix, v, 215, 45, 35);
                    break;
                case CellState::Unknown:
                    if (grid.observed(c))
                        putPixel(img, ix, v, 140, 140, 140);  // seen, undecided
                    else
                        putPixel(img, ix, v, 45, 45, 45);
                    break;
            }
        }
    return img;
}

mrpt::img::CImage heightImage(const CTraversabilityMap& map, double z_lo, double z_hi) {
    const TraversabilityGrid& grid = map.grid();
    if (!(z_lo < z_hi)) {
        z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
        for (std::size_t c = 0; c < grid.cellCount(); ++c) {
            const float h = grid.groundHeight(long(c));
            if (std::isfinite(h))
                z_lo = std::min(z_lo, double(h)), z_hi = std::max(z_hi, double(h));
        }
        if (!(z_lo < z_hi)) z_lo = 0, z_hi = 1;
    }
    mrpt::img::CImage img(grid.sizeX(), grid.sizeY(), mrpt::img::CH_RGB);
    for (int iy = 0; iy < grid.sizeY(); ++iy)
        for (int ix = 0; ix < grid.sizeX(); ++ix) {
            const float h = grid.groundHeight(grid.cellIndex(ix, iy));
            const int v = grid.sizeY() - 1 - iy;
            if (!std::isfinite(h)) {
                putPixel(img, ix, v, 0, 0, 0);
                continue;
            }
            const float t = float(std::clamp((h - z_lo) / (z_hi - z_lo), 0.0, 1.0));
            const mrpt::img::TColor c = mrpt::img::colormap(mrpt::img::cmJET, t);
            putPixel(img, ix, v, c.R, c.G, c.B);
        }
    return img;
}

mrpt::img::CImage enlarge(const mrpt::img::CImage& image, int factor) {
    factor = std::max(1, factor);
    if (factor == 1) return image.makeDeepCopy();
    const int w = int(image.getWidth()), h = int(image.getHeight());
    mrpt::img::CImage big(w * factor, h * factor, mrpt::img::CH_RGB);
    for (int v = 0; v < h * factor; ++v)
        for (int u = 0; u < w * factor; ++u) {
            const uint8_t* p = image.ptr<uint8_t>(unsigned(u / factor), unsigned(v / factor));
            uint8_t* q = big.ptr<uint8_t>(unsigned(u), unsigned(v));
            q[0] = p[0], q[1] = p[1], q[2] = p[2];
        }
    return big;
}

void saveOctoMap(const CTraversabilityMap& map, const std::string& path) {
    if (!map.octree().writeBinaryConst(path))
        throw std::runtime_error(path + ": cannot write the OctoMap");
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
    if (!scene.saveToFile(path)) throw std::runtime_error(path + ": cannot write the 3-D scene");
}

void savePng(const mrpt::img::CImage& image, const std::string& path) {
    if (!image.saveToFile(path)) throw std::runtime_error(path + ": cannot write picture");
}

std::vector<std::string> exportAll(const CTraversabilityMap& map, const std::string& prefix,
                                   int min_png_side) {
    std::vector<std::string> written;
    const auto note = [&](const std::string& path) { written.push_back(path); };
    const int side = std::max(map.grid().sizeX(), map.grid().sizeY());
    const int factor = side > 0 ? std::max(1, (min_png_side + side - 1) / side) : 1;

    saveOctoMap(map, prefix + ".bt");
    note(prefix + ".bt");
    saveOccupancyGridGz(map, prefix + "_grid.gridmap.gz");
    note(prefix + "_grid.gridmap.gz");
    saveHeightGridGz(map, prefix + "_height.gridmap.gz");
    note(prefix + "_height.gridmap.gz");
    savePng(enlarge(traversabilityImage(map), factor), prefix + "_traversability.png");
    note(prefix + "_traversability.png");
    {
        mrpt::maps::COccupancyGridMap2D grid;
        toOccupancyGrid(map, grid);
        if (!grid.saveAsBitmapFile(prefix + "_occupancy.png"))
            throw std::runtime_error(prefix + "_occupancy.png: cannot write picture");
        note(prefix + "_occupancy.png");
    }
    savePng(enlarge(heightImage(map), factor), prefix + "_height.png");
    note(prefix + "_height.png");
    save3DScene(map, prefix + ".3Dscene");
    note(prefix + ".3Dscene");
    return written;
}

}  // namespace travel_mrpt
