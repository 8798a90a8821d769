// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "nav/TopView.hpp"

#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "nav/Collision.hpp"

namespace travel::navsim {
namespace {

using mrpt::img::TColor;

struct View {
    double x0, y1, mpp;  // world x of column 0, world y of row 0
    int u(double x) const { return static_cast<int>(std::lround((x - x0) / mpp)); }
    int v(double y) const { return static_cast<int>(std::lround((y1 - y) / mpp)); }
};

/// Fills a convex polygon (world coordinates) pixel by pixel.
void fillPolygon(mrpt::img::CImage& img, const View& view, const std::vector<Eigen::Vector2d>& poly,
                 const TColor& colour) {
    double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    for (const auto& p : poly)
        xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x()), ymin = std::min(ymin, p.y()),
        ymax = std::max(ymax, p.y());
    const int w = static_cast<int>(img.getWidth()), h = static_cast<int>(img.getHeight());
    for (int v = std::max(0, view.v(ymax)); v <= std::min(h - 1, view.v(ymin)); ++v)
        for (int u = std::max(0, view.u(xmin)); u <= std::min(w - 1, view.u(xmax)); ++u) {
            const Eigen::Vector2d p(view.x0 + (u + 0.5) * view.mpp, view.y1 - (v + 0.5) * view.mpp);
            if (polygonDistance({p}, poly) == 0.0) img.setPixel(u, v, colour);
        }
}

void outline(mrpt::img::CImage& img, const View& view, const std::vector<Eigen::Vector2d>& poly,
             const TColor& colour, int width) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const auto &a = poly[i], &b = poly[(i + 1) % poly.size()];
        img.line(view.u(a.x()), view.v(a.y()), view.u(b.x()), view.v(b.y()), colour, width);
    }
}

}  // namespace

void renderTopView(const World& world, const std::vector<Eigen::Vector2d>& footprint,
                   const RunReport* report, const TopViewOptions& opt, mrpt::img::CImage& img) {
    const Eigen::Vector4d ext = worldExtent(world);
    const double mpp = opt.metres_per_pixel;
    const int w = std::max(16, static_cast<int>(std::ceil((ext[2] - ext[0]) / mpp)));
    const int h = std::max(16, static_cast<int>(std::ceil((ext[3] - ext[1]) / mpp)));
    img.resize(w, h, mrpt::img::CH_RGB);
    const View view{ext[0], ext[3], mpp};

    // Terrain: brightness from height, hill shading from the gradient (light from the north-west),
    // so that steps show as lines and ramps as shaded bands.
    double hmin = 1e9, hmax = -1e9;
    std::vector<float> height(static_cast<std::size_t>(w) * h);
    for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u) {
            const double z =
                world.scene.terrainHeight(ext[0] + (u + 0.5) * mpp, ext[3] - (v + 0.5) * mpp);
            height[static_cast<std::size_t>(v) * w + u] = static_cast<float>(z);
            hmin = std::min(hmin, z), hmax = std::max(hmax, z);
        }
    const double range = std::max(0.5, hmax - hmin);
    for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u) {
            const auto at = [&](int uu, int vv) {
                uu = std::clamp(uu, 0, w - 1), vv = std::clamp(vv, 0, h - 1);
                return height[static_cast<std::size_t>(vv) * w + uu];
            };
            const double gx = (at(u + 1, v) - at(u - 1, v)) / (2 * mpp);
            const double gy = (at(u, v - 1) - at(u, v + 1)) / (2 * mpp);
            const double shade = std::clamp(1.0 + 0.8 * (gx - gy) / std::sqrt(2.0), 0.55, 1.25);
            const double level = (at(u, v) - hmin) / range;  // 0 low .. 1 high
            const auto c = [&](double base) {
                return static_cast<uint8_t>(std::clamp(base * shade, 0.0, 255.0));
            };
            img.setPixel(u, v,
                         TColor(c(215 - 60 * level), c(225 - 35 * level), c(200 - 80 * level)));
        }

    // 1 m grid, faint.
    for (double x = std::ceil(ext[0]); x <= ext[2]; x += 1.0)
        img.line(view.u(x), 0, view.u(x), h - 1, TColor(200, 200, 190), 1);
    for (double y = std::ceil(ext[1]); y <= ext[3]; y += 1.0)
        img.line(0, view.v(y), w - 1, view.v(y), TColor(200, 200, 190), 1);

    // Obstacles: kerbs orange, the rest dark grey.
    for (const auto& o : world.obstacles) {
        // Movers: drawn with the run, where they were (below).
        if (o.moving && report != nullptr && !report->trajectory.empty()) continue;
        const bool kerb = o.what.rfind("kerb", 0) == 0;
        const TColor colour = kerb ? TColor(235, 140, 20) : TColor(70, 70, 80);
        if (o.radius > 0)
            img.filledRectangle(
                view.u(o.polygon[0].x() - o.radius), view.v(o.polygon[0].y() + o.radius),
                view.u(o.polygon[0].x() + o.radius), view.v(o.polygon[0].y() - o.radius), colour);
        else
            fillPolygon(img, view, o.polygon, colour);
    }

    // Map source: what the map knew at the end (traversable cells tinted green, obstacle cells
    // red) and every planned path (earlier plans pale, the last one magenta).
    if (report != nullptr && !report->map_cells.empty()) {
        const double res = report->map_resolution;
        for (int v = 0; v < h; ++v)
            for (int u = 0; u < w; ++u) {
                const double x = ext[0] + (u + 0.5) * mpp, y = ext[3] - (v + 0.5) * mpp;
                const int ix = int(std::floor((x - report->map_min_x) / res));
                const int iy = int(std::floor((y - report->map_min_y) / res));
                if (ix < 0 || iy < 0 || ix >= report->map_size_x || iy >= report->map_size_y)
                    continue;
                const uint8_t cell = report->map_cells[std::size_t(iy) * report->map_size_x + ix];
                if (cell == 0) continue;
                const uint8_t* px = img(u, v);  // BGR
                const TColor tint = cell == 2 ? TColor(230, 20, 20) : TColor(40, 200, 60);
                const double a = cell == 2 ? 0.6 : 0.25;
                const auto mix = [a](uint8_t from, uint8_t to) {
                    return static_cast<uint8_t>((1 - a) * from + a * to);
                };
                img.setPixel(u, v,
                             TColor(mix(px[2], tint.R), mix(px[1], tint.G), mix(px[0], tint.B)));
            }
        const auto& plans = report->planned_paths;
        for (std::size_t k = 0; k < plans.size(); ++k) {
            const bool last = k + 1 == plans.size();
            const TColor colour = last ? TColor(220, 0, 220) : TColor(230, 160, 230);
            for (std::size_t i = 1; i < plans[k].size(); ++i)
                img.line(view.u(plans[k][i - 1].x()), view.v(plans[k][i - 1].y()),
                         view.u(plans[k][i].x()), view.v(plans[k][i].y()), colour, last ? 2 : 1);
        }
    }

    // Start (green) and goal (red ring of the goal tolerance's size).
    img.drawCircle(view.u(world.start.x()), view.v(world.start.y()), 6, TColor(0, 150, 0), 3);
    img.drawCircle(view.u(world.goal.x()), view.v(world.goal.y()),
                   std::max(4, static_cast<int>(0.4 / mpp)), TColor(210, 0, 0), 3);
    img.drawMark(view.u(world.goal.x()), view.v(world.goal.y()), TColor(210, 0, 0), '+', 9, 2);

    if (report != nullptr && !report->trajectory.empty()) {
        const auto& tr = report->trajectory;
        for (std::size_t i = 1; i < tr.size(); ++i)
            img.line(view.u(tr[i - 1].x), view.v(tr[i - 1].y), view.u(tr[i].x), view.v(tr[i].y),
                     TColor(20, 60, 230), 3);
        // Footprints every 2 s, and the final one; the movers where they were then (purple
        // outlines, filled at the end).
        World live = world;
        const auto drawMovers = [&](double t, bool last) {
            placeMovers(live, t);
            for (const Mover& m : live.movers) {
                const auto& poly = live.obstacles[m.obstacle].polygon;
                if (last) fillPolygon(img, view, poly, TColor(150, 40, 170));
                outline(img, view, poly, TColor(150, 40, 170), last ? 2 : 1);
            }
        };
        for (std::size_t i = 0; i < tr.size(); i += static_cast<std::size_t>(20)) {
            outline(img, view, placeFootprint(footprint, {tr[i].x, tr[i].y, tr[i].yaw}),
                    TColor(90, 110, 200), 1);
            drawMovers(tr[i].t, false);
        }
        drawMovers(tr.back().t, true);
        const auto& last = tr.back();
        const TColor end = report->outcome == Outcome::Collision ? TColor(230, 0, 0)
                           : report->outcome == Outcome::Goal    ? TColor(0, 140, 0)
                                                                 : TColor(200, 120, 0);
        outline(img, view, placeFootprint(footprint, {last.x, last.y, last.yaw}), end, 3);
    }

    // Caption: title, the outcome, the numbers, the detail; each line cut to the picture's width
    // (MRPT's default font: 9 px per character).
    int line_y = 4;
    const std::size_t max_chars = static_cast<std::size_t>(std::max(4, (w - 10) / 9));
    const auto text = [&](std::string s, const TColor& colour) {
        if (s.size() > max_chars) s = s.substr(0, max_chars - 2) + "..";
        img.filledRectangle(2, line_y - 2, std::min(w - 1, 8 + 9 * static_cast<int>(s.size())),
                            line_y + 12, TColor(255, 255, 255));
        img.textOut(5, line_y, s, colour);
        line_y += 16;
    };
    if (!opt.title.empty()) text(opt.title, TColor(0, 0, 0));
    if (report != nullptr) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "%s after %.1f s", toString(report->outcome), report->time);
        text(buf, TColor(0, 0, 0));
        std::snprintf(buf, sizeof buf, "path %.1f m, min clearance %.2f m", report->path_length,
                      report->min_clearance);
        text(buf, TColor(0, 0, 0));
        if (report->min_mover_clearance < 1e9) {
            std::snprintf(buf, sizeof buf, "min clearance to the movers %.2f m",
                          report->min_mover_clearance);
            text(buf, TColor(0, 0, 0));
        }
        if (!report->detail.empty()) text(report->detail, TColor(90, 90, 90));
    }
}

}  // namespace travel::navsim
