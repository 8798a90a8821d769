// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/viz/BirdsEye.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace travel::viz {
namespace {

constexpr Rgb kGround{40, 165, 40}, kNonGround{220, 0, 0}, kUnclustered{120, 120, 120},
    kOutlier{0, 60, 255}, kNodeFill{244, 236, 196}, kNodeEdge{205, 170, 90};
constexpr Rgb kWhite{255, 255, 255}, kRing{205, 205, 205}, kBlack{0, 0, 0},
    kTextBoxFrame{190, 190, 190};

// Well-separated hues, none of them green (ground) or blue (outliers), so that a cluster is
// never mistaken for a class.
constexpr std::array<Rgb, 12> kPalette = {{{230, 25, 75},
                                           {245, 130, 48},
                                           {145, 30, 180},
                                           {240, 50, 230},
                                           {0, 160, 180},
                                           {170, 110, 40},
                                           {128, 0, 0},
                                           {200, 160, 0},
                                           {250, 110, 160},
                                           {90, 60, 170},
                                           {0, 110, 110},
                                           {210, 80, 20}}};

Rgb paletteColour(uint32_t id) {
    // Knuth's multiplicative hash: neighbouring ids (often neighbouring objects) get unrelated
    // colours.
    const uint32_t h = id * 2654435761u;
    return kPalette[(h >> 16) % kPalette.size()];
}

/// Largest of 1, 2, 5 x 10^k metres not longer than `max_metres`.
double niceLength(double max_metres) {
    double best = 0.1;
    for (double decade = 0.1; decade <= 1e4; decade *= 10)
        for (double m : {1.0, 2.0, 5.0})
            if (m * decade <= max_metres) best = m * decade;
    return best;
}

/// Metric (x forward, y left) to pixel (u right, v down), sensor at the centre.
struct Projection {
    double centre, mpp;
    double u(double y) const { return centre - y / mpp; }
    double v(double x) const { return centre - x / mpp; }
};

/// Faint fills (pass 0) or outlines (pass 1) of the traversable nodes.
void drawNodes(Raster& img, const TerrainModel& terrain, const Projection& proj, int pass) {
    if (!terrain.usable()) return;
    const auto corners = [&](std::size_t node) {
        const std::array<Eigen::Vector2f, 3> c = terrain.triangleCorners(static_cast<int>(node));
        return std::array<double, 6>{proj.u(c[0].y()), proj.v(c[0].x()), proj.u(c[1].y()),
                                     proj.v(c[1].x()), proj.u(c[2].y()), proj.v(c[2].x())};
    };
    if (pass == 0) {
        for (std::size_t k = 0; k < terrain.nodes.size(); ++k)
            if (terrain.nodes[k].traversable) img.fillTriangle(corners(k), kNodeFill);
        return;
    }
    const auto px = [](double a) { return static_cast<int>(std::lround(a)); };
    for (std::size_t k = 0; k < terrain.nodes.size(); ++k) {
        if (!terrain.nodes[k].traversable) continue;
        const auto p = corners(k);
        img.line(px(p[0]), px(p[1]), px(p[2]), px(p[3]), kNodeEdge);
        img.line(px(p[2]), px(p[3]), px(p[4]), px(p[5]), kNodeEdge);
        img.line(px(p[4]), px(p[5]), px(p[0]), px(p[1]), kNodeEdge);
    }
}

/// A white box with a light frame behind text, so that it stays readable over points.
void textBox(Raster& img, int x0, int y0, int x1, int y1) {
    img.fillRect(x0, y0, x1, y1, kWhite);
    img.frameRect(x0, y0, x1, y1, kTextBoxFrame);
}

uint32_t packed(const Rgb& c) {
    return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b;
}

}  // namespace

uint32_t clusterColour(uint32_t id) {
    return packed(paletteColour(id));
}

uint32_t clusterColour(const ClusterSummary& cluster) {
    return clusterColour(cluster.track_id != 0 ? cluster.track_id : cluster.id);
}

uint32_t pointColour(PointClass c, uint32_t cluster_id, bool any_cluster) {
    switch (c) {
        case PointClass::Ground:
            return packed(kGround);
        case PointClass::Outlier:
            return packed(kOutlier);
        case PointClass::NonGround:
            return cluster_id    ? clusterColour(cluster_id)
                   : any_cluster ? packed(kUnclustered)
                                 : packed(kNonGround);
        default:
            return 0;
    }
}

Picture renderBirdsEye(const float* x, const float* y, std::size_t n,
                       const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id, const TerrainModel* terrain,
                       const BirdsEyeOptions& opt) {
    if (labels.size() != n)
        throw std::invalid_argument("renderBirdsEye: " + std::to_string(labels.size()) +
                                    " labels for " + std::to_string(n) + " points");
    if (!cluster_id.empty() && cluster_id.size() != n)
        throw std::invalid_argument("renderBirdsEye: " + std::to_string(cluster_id.size()) +
                                    " cluster ids for " + std::to_string(n) + " points");
    if (opt.size_px < 64 || !(opt.metres_per_pixel > 0) || !std::isfinite(opt.metres_per_pixel))
        throw std::invalid_argument("renderBirdsEye: size must be >= 64 px and scale > 0");

    const int size = opt.size_px;
    const double mpp = opt.metres_per_pixel;
    const bool clustered = !cluster_id.empty();
    Picture picture;
    Raster& out = picture.raster;
    out.reset(size, size, kWhite);
    const Projection proj{size / 2.0, mpp};
    const int centre = size / 2;

    const bool nodes = terrain && opt.draw_nodes;
    if (nodes && opt.fill_nodes) drawNodes(out, *terrain, proj, 0);

    const double bar_m = niceLength(0.25 * size * mpp);
    // Range rings every scale-bar length help reading distances.
    if (opt.range_rings)
        for (int k = 1; k * bar_m / mpp < size; ++k)
            out.circle(centre, centre, static_cast<int>(std::lround(k * bar_m / mpp)), kRing);

    // Ground first, then outliers, then obstacles: what matters for navigation stays on top.
    const int s = std::max(1, opt.point_px);
    const auto plot = [&](std::size_t i, const Rgb& colour) {
        const int u = static_cast<int>(std::lround(proj.u(y[i])));
        const int v = static_cast<int>(std::lround(proj.v(x[i])));
        if (u < s || v < s || u >= size - s || v >= size - s) return;
        out.fillRect(u - s / 2, v - s / 2, u - s / 2 + s - 1, v - s / 2 + s - 1, colour);
    };
    for (PointClass pass : {PointClass::Ground, PointClass::Outlier, PointClass::NonGround}) {
        const Rgb colour = pass == PointClass::Ground    ? kGround
                           : pass == PointClass::Outlier ? kOutlier
                           : clustered                   ? kUnclustered
                                                         : kNonGround;
        for (std::size_t i = 0; i < n; ++i) {
            if (labels[i] != pass) continue;
            if (pass == PointClass::NonGround && clustered && cluster_id[i] != 0) continue;
            plot(i, colour);
        }
        // Node outlines over the ground (dense near the sensor, it would hide them) but under
        // the obstacles.
        if (pass == PointClass::Ground && nodes) drawNodes(out, *terrain, proj, 1);
    }
    // Clustered points last, in their cluster's colour.
    if (clustered)
        for (std::size_t i = 0; i < n; ++i)
            if (cluster_id[i] != 0) plot(i, paletteColour(cluster_id[i]));

    if (opt.sensor_marker) {
        out.fillRect(centre - 3, centre - 3, centre + 3, centre + 3, kBlack);
        // A 2-px wide heading tick, 14 px long, with round (1-px) caps.
        out.fillRect(centre - 1, centre - 14, centre + 1, centre, kBlack);
        out.set(centre, centre - 15, kBlack);
    }

    // Text boxes are laid out for a 9-px wide font with 15-px lines.
    int y_text = 4;
    if (!opt.title.empty()) {
        const int w = std::min(size - 1, 12 + 9 * static_cast<int>(opt.title.size()));
        textBox(out, 0, 0, w, 22);
        picture.text.push_back({6, y_text + 1, opt.title});
        y_text = 28;
    }
    if (opt.legend) {
        std::vector<std::pair<std::string, Rgb>> entries = {{"ground", kGround}};
        if (nodes) entries.push_back({"traversable node", kNodeEdge});
        if (clustered) {
            entries.push_back({"cluster (colour per id)", kPalette[0]});
            entries.push_back({"non-ground, no cluster", kUnclustered});
        } else {
            entries.push_back({"non-ground", kNonGround});
        }
        entries.push_back({"outlier", kOutlier});
        std::size_t longest = 0;
        for (const auto& e : entries) longest = std::max(longest, e.first.size());
        const int row = 18;
        textBox(out, 0, y_text - 2, 34 + 9 * static_cast<int>(longest) + 6,
                y_text + row * static_cast<int>(entries.size()) + 2);
        for (std::size_t k = 0; k < entries.size(); ++k) {
            const int yk = y_text + row * static_cast<int>(k);
            if (clustered && k == (nodes ? 2u : 1u)) {
                // The cluster swatch shows a few palette colours: "one colour each".
                for (int j = 0; j < 4; ++j)
                    out.fillRect(6 + 6 * j, yk + 3, 11 + 6 * j, yk + 13, kPalette[j * 3]);
            } else if (nodes && k == 1) {
                out.fillRect(6, yk + 3, 28, yk + 13, kNodeFill);
                out.frameRect(6, yk + 3, 28, yk + 13, kNodeEdge);
            } else {
                out.fillRect(6, yk + 3, 28, yk + 13, entries[k].second);
            }
            picture.text.push_back({34, yk + 1, entries[k].first});
        }
    }
    if (opt.scale_bar) {
        const int bar_px = static_cast<int>(std::lround(bar_m / mpp));
        char text[96];
        std::snprintf(text, sizeof text, "%g m   (1 px = %g m, up = forward)", bar_m, mpp);
        const int y_bar = size - 12;
        textBox(out, 0, y_bar - 24,
                std::min(size - 1,
                         std::max(bar_px + 20,
                                  16 + 9 * static_cast<int>(std::char_traits<char>::length(text)))),
                size - 1);
        out.fillRect(10, y_bar - 2, 10 + bar_px, y_bar + 1, kBlack);
        picture.text.push_back({10, y_bar - 20, text});
    }
    return picture;
}

Picture renderBirdsEye(const PointCloud& points, const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id, const TerrainModel* terrain,
                       const BirdsEyeOptions& opt) {
    if (points.y.size() != points.x.size())
        throw std::invalid_argument("renderBirdsEye: x and y differ in size");
    return renderBirdsEye(points.x.data(), points.y.data(), points.size(), labels, cluster_id,
                          terrain, opt);
}

Picture renderBirdsEye(const AlignedCloud& points, const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id, const TerrainModel* terrain,
                       const BirdsEyeOptions& opt) {
    if (points.y.size() != points.x.size())
        throw std::invalid_argument("renderBirdsEye: x and y differ in size");
    return renderBirdsEye(points.x.data(), points.y.data(), points.x.size(), labels, cluster_id,
                          terrain, opt);
}

Picture renderClassChanges(const float* x, const float* y, std::size_t n,
                           const std::vector<PointClass>& golden_labels,
                           const std::vector<uint8_t>& changed, const BirdsEyeOptions& opt) {
    if (changed.size() != n)
        throw std::invalid_argument("renderClassChanges: " + std::to_string(changed.size()) +
                                    " change flags for " + std::to_string(n) + " points");
    Picture picture = renderBirdsEye(x, y, n, golden_labels, {}, nullptr, opt);
    Raster& out = picture.raster;
    const Rgb kChanged = kBlack;
    const int size = opt.size_px;
    const Projection proj{size / 2.0, opt.metres_per_pixel};
    // One pixel larger than the other points: a changed point stays visible over its neighbours.
    const int s = std::max(1, opt.point_px) + 1;
    for (std::size_t i = 0; i < n; ++i) {
        if (!changed[i]) continue;
        const int u = static_cast<int>(std::lround(proj.u(y[i])));
        const int v = static_cast<int>(std::lround(proj.v(x[i])));
        if (u < s || v < s || u >= size - s || v >= size - s) continue;
        out.fillRect(u - s / 2, v - s / 2, u - s / 2 + s - 1, v - s / 2 + s - 1, kChanged);
    }
    if (opt.legend) {  // top right, apart from renderBirdsEye's legend
        const std::string text = "class changed";
        const int w = 34 + 9 * static_cast<int>(text.size()) + 6;
        textBox(out, size - 1 - w, 0, size - 1, 22);
        out.fillRect(size - w + 5, 6, size - w + 27, 16, kChanged);
        picture.text.push_back({size - w + 33, 5, text});
    }
    return picture;
}

Picture renderClassChanges(const LabelledFrame& golden, const std::vector<uint8_t>& changed,
                           const BirdsEyeOptions& opt) {
    const std::size_t n = golden.size();
    if (golden.x.size() != n || golden.y.size() != n || golden.z.size() != n)
        throw std::invalid_argument("renderClassChanges: the frame's vectors differ in size");
    std::vector<float> x(n), y(n);
    const Eigen::Matrix3f& r = golden.alignedRotation;
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3f p = r * Eigen::Vector3f(golden.x[i], golden.y[i], golden.z[i]);
        x[i] = p.x(), y[i] = p.y();
    }
    std::vector<PointClass> labels(n);
    for (std::size_t i = 0; i < n; ++i) labels[i] = static_cast<PointClass>(golden.labels[i] & 3u);
    return renderClassChanges(x.data(), y.data(), n, labels, changed, opt);
}

}  // namespace travel::viz
