// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/viz/Raster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace travel::viz {
namespace {

/// Clips the segment to [0, w-1] x [0, h-1] (Cohen-Sutherland, OpenCV's integer rounding);
/// false when nothing is left.
bool clipLine(int64_t w, int64_t h, int64_t& x1, int64_t& y1, int64_t& x2, int64_t& y2) {
    const int64_t right = w - 1, bottom = h - 1;
    int c1 = (x1 < 0) + (x1 > right) * 2 + (y1 < 0) * 4 + (y1 > bottom) * 8;
    int c2 = (x2 < 0) + (x2 > right) * 2 + (y2 < 0) * 4 + (y2 > bottom) * 8;
    if ((c1 & c2) == 0 && (c1 | c2) != 0) {
        if (c1 & 12) {
            const int64_t a = c1 < 8 ? 0 : bottom;
            x1 += static_cast<int64_t>(static_cast<double>(a - y1) * (x2 - x1) / (y2 - y1));
            y1 = a;
            c1 = (x1 < 0) + (x1 > right) * 2;
        }
        if (c2 & 12) {
            const int64_t a = c2 < 8 ? 0 : bottom;
            x2 += static_cast<int64_t>(static_cast<double>(a - y2) * (x2 - x1) / (y2 - y1));
            y2 = a;
            c2 = (x2 < 0) + (x2 > right) * 2;
        }
        if ((c1 & c2) == 0 && (c1 | c2) != 0) {
            if (c1) {
                const int64_t a = c1 == 1 ? 0 : right;
                y1 += static_cast<int64_t>(static_cast<double>(a - x1) * (y2 - y1) / (x2 - x1));
                x1 = a;
                c1 = 0;
            }
            if (c2) {
                const int64_t a = c2 == 1 ? 0 : right;
                y2 += static_cast<int64_t>(static_cast<double>(a - x2) * (y2 - y1) / (x2 - x1));
                x2 = a;
                c2 = 0;
            }
        }
    }
    return (c1 | c2) == 0;
}

}  // namespace

void Raster::reset(int w, int h, Rgb background) {
    width = std::max(0, w), height = std::max(0, h);
    rgb.resize(3 * static_cast<std::size_t>(width) * height);
    for (std::size_t i = 0; i < rgb.size(); i += 3)
        rgb[i] = background.r, rgb[i + 1] = background.g, rgb[i + 2] = background.b;
}

void Raster::fillRect(int x0, int y0, int x1, int y1, Rgb c) {
    for (int v = std::max(0, y0); v <= std::min(height - 1, y1); ++v)
        for (int u = std::max(0, x0); u <= std::min(width - 1, x1); ++u) set(u, v, c);
}

void Raster::frameRect(int x0, int y0, int x1, int y1, Rgb c) {
    for (int w = 0; w < 2; ++w) {
        line(x0 + w, y0 + w, x1 - w, y0 + w, c);
        line(x1 - w, y0 + w, x1 - w, y1 - w, c);
        line(x1 - w, y1 - w, x0 + w, y1 - w, c);
        line(x0 + w, y1 - w, x0 + w, y0 + w, c);
    }
}

void Raster::line(int x0, int y0, int x1, int y1, Rgb c) {
    int64_t ax = x0, ay = y0, bx = x1, by = y1;
    if (!clipLine(width, height, ax, ay, bx, by)) return;
    // Bresenham, always walked left to right (the pixels of a line do not depend on the order
    // of its ends).
    if (bx < ax) std::swap(ax, bx), std::swap(ay, by);
    int64_t dx = bx - ax, dy = by - ay;
    int step_v = 1;
    if (dy < 0) dy = -dy, step_v = -1;
    const bool steep = dy > dx;
    if (steep) std::swap(dx, dy);
    int64_t err = dx - 2 * dy;
    int64_t u = ax, v = ay;
    for (int64_t i = 0; i <= dx; ++i) {
        set(static_cast<int>(u), static_cast<int>(v), c);
        const bool minor_step = err < 0;
        err += -2 * dy + (minor_step ? 2 * dx : 0);
        if (steep) {
            v += step_v;
            if (minor_step) ++u;
        } else {
            ++u;
            if (minor_step) v += step_v;
        }
    }
}

void Raster::circle(int cx, int cy, int radius, Rgb c) {
    int err = 0, dx = radius, dy = 0, plus = 1, minus = (radius << 1) - 1;
    const auto put = [&](int u, int v) {
        if (inside(u, v)) set(u, v, c);
    };
    while (dx >= dy) {
        put(cx - dx, cy - dy), put(cx + dx, cy - dy), put(cx - dx, cy + dy), put(cx + dx, cy + dy);
        put(cx - dy, cy - dx), put(cx + dy, cy - dx), put(cx - dy, cy + dx), put(cx + dy, cy + dx);
        ++dy;
        err += plus;
        plus += 2;
        const int mask = (err <= 0) - 1;
        err -= minus & mask;
        dx += mask;
        minus -= mask & 2;
    }
}

void Raster::fillTriangle(const std::array<double, 6>& p, Rgb c) {
    const int u0 = std::max(0, static_cast<int>(std::floor(std::min({p[0], p[2], p[4]}))));
    const int u1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({p[0], p[2], p[4]}))));
    const int v0 = std::max(0, static_cast<int>(std::floor(std::min({p[1], p[3], p[5]}))));
    const int v1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({p[1], p[3], p[5]}))));
    const auto edge = [](double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    };
    const double area = edge(p[0], p[1], p[2], p[3], p[4], p[5]);
    if (std::abs(area) < 1e-9) return;
    for (int v = v0; v <= v1; ++v) {
        for (int u = u0; u <= u1; ++u) {
            const double px = u + 0.5, py = v + 0.5;
            const double e0 = edge(p[2], p[3], p[4], p[5], px, py) / area;
            const double e1 = edge(p[4], p[5], p[0], p[1], px, py) / area;
            const double e2 = edge(p[0], p[1], p[2], p[3], px, py) / area;
            if (e0 < 0 || e1 < 0 || e2 < 0) continue;
            set(u, v, c);
        }
    }
}

}  // namespace travel::viz
