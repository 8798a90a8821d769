// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "nav/Collision.hpp"

#include <algorithm>
#include <cmath>

namespace travel::navsim {
namespace {

double pointSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

/// Point inside a convex polygon of either orientation (boundary counts as inside).
bool inside(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& poly) {
    int sign = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d& a = poly[i];
        const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
        const double c = (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
        if (c == 0) continue;
        const int s = c > 0 ? 1 : -1;
        if (sign == 0) sign = s;
        if (s != sign) return false;
    }
    return true;
}

bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
    const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
        return u.x() * v.y() - u.y() * v.x();
    };
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

}  // namespace

std::vector<Eigen::Vector2d> placeFootprint(const std::vector<Eigen::Vector2d>& footprint,
                                            const Eigen::Vector3d& pose) {
    const double c = std::cos(pose.z()), s = std::sin(pose.z());
    std::vector<Eigen::Vector2d> out;
    out.reserve(footprint.size());
    for (const auto& p : footprint)
        out.emplace_back(pose.x() + c * p.x() - s * p.y(), pose.y() + s * p.x() + c * p.y());
    return out;
}

double polygonDistance(const std::vector<Eigen::Vector2d>& a,
                       const std::vector<Eigen::Vector2d>& b) {
    if (a.empty() || b.empty()) return 1e9;
    if (inside(a[0], b) || inside(b[0], a)) return 0.0;
    double best = 1e9;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto &a0 = a[i], &a1 = a[(i + 1) % a.size()];
        for (std::size_t j = 0; j < b.size(); ++j) {
            const auto &b0 = b[j], &b1 = b[(j + 1) % b.size()];
            if (segmentsCross(a0, a1, b0, b1)) return 0.0;
            best = std::min({best, pointSegment(a0, b0, b1), pointSegment(b0, a0, a1)});
        }
    }
    return best;
}

Clearance clearance(const std::vector<Eigen::Vector2d>& placed, const World& world,
                    bool movers_only) {
    Clearance out;
    for (const auto& o : world.obstacles) {
        if (movers_only && !o.moving) continue;
        double d;
        if (o.radius > 0) {
            const Eigen::Vector2d& c = o.polygon.front();
            double edge = 1e9;
            for (std::size_t i = 0; i < placed.size(); ++i)
                edge = std::min(edge, pointSegment(c, placed[i], placed[(i + 1) % placed.size()]));
            d = inside(c, placed) ? 0.0 : std::max(0.0, edge - o.radius);
        } else {
            d = polygonDistance(placed, o.polygon);
        }
        if (d < out.distance) {
            out.distance = d;
            out.nearest = o.what;
        }
    }
    return out;
}

}  // namespace travel::navsim
