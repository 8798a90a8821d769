// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A plain RGB8 image and the few drawing primitives the bird's-eye pictures need. No image
// library: the MRPT layer copies the pixels into an mrpt::img::CImage to save them.
//
// Lines and circles follow OpenCV's rasterisation rules (8-connected Bresenham after clipping
// to the image; the midpoint circle), which is what mrpt::img::CImage used to draw them with:
// pictures stay pixel-identical to the ones written before the drawing moved here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace travel::viz {

struct Rgb {
    uint8_t r, g, b;
};

struct Raster {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  ///< row-major, 3 bytes (R, G, B) per pixel

    /// Resizes to w x h and paints every pixel `background`.
    void reset(int w, int h, Rgb background);
    bool inside(int u, int v) const { return u >= 0 && v >= 0 && u < width && v < height; }
    /// Offset of pixel (u, v)'s red byte in `rgb`. Unchecked: (u, v) must be inside.
    std::size_t index(int u, int v) const {
        return 3 * (static_cast<std::size_t>(v) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(u));
    }
    /// Unchecked: (u, v) must be inside.
    void set(int u, int v, Rgb c) {
        uint8_t* p = &rgb[index(u, v)];
        p[0] = c.r, p[1] = c.g, p[2] = c.b;
    }
    Rgb at(int u, int v) const {
        const uint8_t* p = &rgb[index(u, v)];
        return {p[0], p[1], p[2]};
    }

    /// Filled rectangle, corners included, clipped to the image.
    void fillRect(int x0, int y0, int x1, int y1, Rgb c);
    /// 2-px frame inside the rectangle's edge (what mrpt::img::CImage::rectangle draws at
    /// width 1, which the pictures were designed with).
    void frameRect(int x0, int y0, int x1, int y1, Rgb c);
    /// 1-px 8-connected line from (x0, y0) to (x1, y1), both ends included.
    void line(int x0, int y0, int x1, int y1, Rgb c);
    /// 1-px circle outline.
    void circle(int cx, int cy, int radius, Rgb c);
    /// Solid triangle (u0, v0, u1, v1, u2, v2) in pixel coordinates: the pixels whose centre
    /// lies inside it.
    void fillTriangle(const std::array<double, 6>& p, Rgb c);
};

}  // namespace travel::viz
