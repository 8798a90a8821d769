// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Node-wise terrain model (paper Sec. III-B).
//   LPR   = mean z of the lowest `lpr_num_points` points of the node.
//   seeds = points with LPR - seed_margin_below_lpr <= z < LPR + seed_margin_above_lpr.
//   PCA plane of the seeds (normal s = eigenvector of the smallest eigenvalue, s.z >= 0), then
//   `plane_fit_iterations - 1` times: re-select points with s.p + d < plane_inlier_dist, refit.
//   Weight (eq. 1): w = l2 (l1 + l2) / (l1 l3) with l1 >= l2 >= l3 (planar, cohesive nodes
//   weigh more; a tiny l3 of a perfect plane is guarded).
//   Class: fewer than node_min_points points -> Unknown (no plane is fitted); normal within
//   max_slope of vertical -> Terrain; else Obstacle.
#include "travel/NodeFitting.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "CpuDispatch.hpp"

namespace travel {
namespace {

using detail::anyLane;
using detail::kLanes;
using detail::LaneMask;
using detail::Lanes;
using detail::loadLanes;
using detail::oneWhere;

struct Moments {
    double n = 0, sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
};

// Moments of the points for which `inside(x, y, z)` is 1 (it returns 1 or 0). Branch-free with
// kLanes independent float accumulators per moment (vector values kept in registers: as arrays
// of lanes, GCC spilled them to the stack on every point block); the coordinates are node-local
// (a few metres), where float sums keep ample precision. Lanes are summed in double.
template <class Predicate>
TRAVEL_INTO_CALLER Moments accumulate(const float* x, const float* y, const float* z,
                                      uint32_t count, const float origin[3], Predicate inside) {
    Lanes n = {}, sx = {}, sy = {}, sz = {}, sxx = {}, sxy = {}, sxz = {}, syy = {}, syz = {},
          szz = {};
    uint32_t i = 0;
    for (; i + kLanes <= count; i += kLanes) {
        const Lanes px = loadLanes(x + i) - origin[0], py = loadLanes(y + i) - origin[1];
        const Lanes pz = loadLanes(z + i) - origin[2];
        const Lanes m = inside.lanes(px, py, pz);
        // The selected point q = m p (m is 0 or 1): q q^T is m p p^T bit for bit (a left-out
        // point adds +-0 to sums that start at +0), and p is dead after q, which keeps the
        // 10 accumulators and q in the 16 vector registers.
        const Lanes qx = m * px, qy = m * py, qz = m * pz;
        n += m, sx += qx, sy += qy, sz += qz;
        sxx += qx * qx, sxy += qx * qy, sxz += qx * qz;
        syy += qy * qy, syz += qy * qz, szz += qz * qz;
    }
    for (; i < count; ++i) {  // tail, into lane 0
        const float qx = x[i] - origin[0], qy = y[i] - origin[1], qz = z[i] - origin[2];
        if (inside(qx, qy, qz) == 0.f) continue;
        n[0] += 1.f, sx[0] += qx, sy[0] += qy, sz[0] += qz;
        sxx[0] += qx * qx, sxy[0] += qx * qy, sxz[0] += qx * qz;
        syy[0] += qy * qy, syz[0] += qy * qz, szz[0] += qz * qz;
    }
    Moments mo;
    for (int l = 0; l < kLanes; ++l) {
        mo.n += n[l], mo.sx += sx[l], mo.sy += sy[l], mo.sz += sz[l], mo.sxx += sxx[l];
        mo.sxy += sxy[l], mo.sxz += sxz[l], mo.syy += syy[l], mo.syz += syz[l], mo.szz += szz[l];
    }
    return mo;
}

// The selections below return 1.f (selected) or 0.f: accumulate() multiplies by them.

// The seeds: points within the band [lo, hi) around the LPR (node-local z). A product of two
// 0/1 selects: `pz >= lo && pz < hi` compiled to two unpredictable branches per point and kept
// accumulate()'s lane loop from vectorising.
struct SeedBand {
    float lo, hi;
    float operator()(float, float, float pz) const {
        return (pz >= lo ? 1.f : 0.f) * (pz < hi ? 1.f : 0.f);
    }
    Lanes lanes(const Lanes&, const Lanes&, const Lanes& pz) const {
        return oneWhere((pz >= lo) & (pz < hi));
    }
};

// The refit's points: s.p + d_local < plane_inlier_dist, written as s.p < limit.
struct BelowPlane {
    float a, b, c, limit;
    float operator()(float px, float py, float pz) const {
        return a * px + b * py + c * pz < limit ? 1.f : 0.f;
    }
    Lanes lanes(const Lanes& px, const Lanes& py, const Lanes& pz) const {
        return oneWhere(a * px + b * py + c * pz < limit);
    }
};

// True when `before` and `after` select the same points (same node-local coordinates as
// accumulate(), so the same float results). Stops at the first block of kLanes that differs.
// The blocks go through the selections' lane versions (the same floats and comparisons: a
// scalar loop over the lanes was not vectorised, and was a third of the stage).
template <class Before, class After>
TRAVEL_INTO_CALLER bool sameSelection(const float* x, const float* y, const float* z,
                                      uint32_t count, const float origin[3], Before before,
                                      After after) {
    uint32_t i = 0;
    for (; i + kLanes <= count; i += kLanes) {
        const Lanes px = loadLanes(x + i) - origin[0], py = loadLanes(y + i) - origin[1];
        const Lanes pz = loadLanes(z + i) - origin[2];
        if (anyLane(before.lanes(px, py, pz) != after.lanes(px, py, pz))) return false;
    }
    for (; i < count; ++i) {
        const float px = x[i] - origin[0], py = y[i] - origin[1], pz = z[i] - origin[2];
        if (before(px, py, pz) != after(px, py, pz)) return false;
    }
    return true;
}

struct Plane {
    Eigen::Vector3d normal, mean_local, eigenvalues;  // eigenvalues descending (l1, l2, l3)
    double d_local = 0;                               // s.p_local + d_local = 0
};

bool fitPlane(double line_node_ratio, const Moments& m, Plane& plane) {
    if (m.n < 3) return false;
    const double inv = 1.0 / m.n;
    const Eigen::Vector3d mean(m.sx * inv, m.sy * inv, m.sz * inv);
    Eigen::Matrix3d cov;
    cov(0, 0) = m.sxx * inv - mean.x() * mean.x();
    cov(0, 1) = cov(1, 0) = m.sxy * inv - mean.x() * mean.y();
    cov(0, 2) = cov(2, 0) = m.sxz * inv - mean.x() * mean.z();
    cov(1, 1) = m.syy * inv - mean.y() * mean.y();
    cov(1, 2) = cov(2, 1) = m.syz * inv - mean.y() * mean.z();
    cov(2, 2) = m.szz * inv - mean.z() * mean.z();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(cov);  // closed form for 3x3: much faster than the iterative solver
    Eigen::Vector3d s = solver.eigenvectors().col(0);
    const Eigen::Vector3d ev = solver.eigenvalues();  // ascending
    if (ev(1) < line_node_ratio * ev(2)) {
        // Points along a line (one ring crossing the node): the PCA normal can spin freely
        // about the line, so noise decides its tilt. The line fixes the slope along itself
        // only; assume no cross slope: the normal closest to vertical that is perpendicular
        // to the line.
        const Eigen::Vector3d line = solver.eigenvectors().col(2);
        const Eigen::Vector3d level = Eigen::Vector3d::UnitZ() - line.z() * line;
        if (level.norm() > 1e-6) s = level.normalized();
    }
    if (!s.allFinite()) return false;
    if (s.z() < 0) s = -s;
    plane.normal = s;
    plane.mean_local = mean;
    plane.d_local = -s.dot(mean);
    plane.eigenvalues = {std::max(ev(2), 0.0), std::max(ev(1), 0.0), std::max(ev(0), 0.0)};
    return true;
}

BelowPlane belowPlane(const Plane& plane, double inlier_dist) {
    return {static_cast<float>(plane.normal.x()), static_cast<float>(plane.normal.y()),
            static_cast<float>(plane.normal.z()), static_cast<float>(inlier_dist - plane.d_local)};
}

// The k lowest values seen so far, ascending, in lowest[0..k): a new value v sinks through them
// as through a min/max network. A value not below lowest[k - 1] leaves them unchanged.
TRAVEL_INTO_CALLER void sinkThrough(float v, float* lowest, int k) {
    for (int j = 0; j < k; ++j) {
        const float lo = std::min(lowest[j], v);
        v = std::max(lowest[j], v);
        lowest[j] = lo;
    }
}

double sumAscending(const float* lowest, int k) {
    double sum = 0;
    for (int j = 0; j < k; ++j) sum += lowest[j];
    return sum;
}

// Mean of the K lowest of count >= K values, K a compile-time constant: the network is unrolled
// and its K values stay in registers. (An insertion sort degenerates here: sensors often deliver
// a node's points in decreasing z, so every point would be inserted at the front.)
template <int K>
TRAVEL_INTO_CALLER float lowestMean(const float* z, uint32_t count) {
    float lowest[K];
    const float inf = std::numeric_limits<float>::infinity();
    for (int j = 0; j < K; ++j) lowest[j] = inf;
    uint32_t i = 0;
    if (count >= 2 * kLanes) {
        // kLanes networks side by side, branch-free: lane l keeps the K lowest of the values
        // at l, l + kLanes, ... (the same min/max selects as sinkThrough). The K lowest of all
        // are among the lanes' K lowest: those go through the scalar network below. Equal values
        // may be kept in another order, which changes neither the values kept nor their sum
        // (only +0 and -0 compare equal and differ, and they change the sum only when all K
        // lowest values are zeros).
        Lanes low[K];
        for (int j = 0; j < K; ++j) low[j] = Lanes{} + inf;
        for (; i + kLanes <= count; i += kLanes) {
            Lanes v = loadLanes(z + i);
            for (int j = 0; j < K; ++j) {
                const Lanes lo = v < low[j] ? v : low[j];
                v = low[j] < v ? v : low[j];
                low[j] = lo;
            }
        }
        for (int j = 0; j < K; ++j)
            for (int l = 0; l < kLanes; ++l)
                if (low[j][l] < lowest[K - 1]) sinkThrough(low[j][l], lowest, K);
    }
    for (; i < count; ++i)
        if (z[i] < lowest[K - 1]) sinkThrough(z[i], lowest, K);
    return static_cast<float>(sumAscending(lowest, K) / K);
}

// Mean of the k lowest values (LPR), k small.
TRAVEL_INTO_CALLER float lowestPointRepresentative(const float* z, uint32_t count, int k) {
    constexpr int kMax = 64;  // lpr_num_points' upper bound (Params.hpp): the array below
    k = std::min({k, static_cast<int>(count), kMax});
    switch (k) {  // the usual lpr_num_points; the same values and sum as the loop below
        case 3:
            return lowestMean<3>(z, count);
        case 4:
            return lowestMean<4>(z, count);
        case 5:
            return lowestMean<5>(z, count);
        case 6:
            return lowestMean<6>(z, count);
        case 8:
            return lowestMean<8>(z, count);
        default:
            break;
    }
    float lowest[kMax];
    for (int j = 0; j < k; ++j) lowest[j] = std::numeric_limits<float>::infinity();
    for (uint32_t i = 0; i < count; ++i)
        if (z[i] < lowest[k - 1]) sinkThrough(z[i], lowest, k);
    return static_cast<float>(sumAscending(lowest, k) / k);
}

}  // namespace

// With AVX2 (CpuDispatch.hpp) the moment passes' 8 float lanes are one register per moment.
TRAVEL_AVX2_CLONES
void fitNodes(const TriGridField& field, const Params& params, TerrainModel& model) {
    const float* sx = field.sx().data();
    const float* sy = field.sy().data();
    const float* sz = field.sz().data();
    const double cos_max_slope = std::cos(params.max_slope_deg * M_PI / 180.0);
    // Only the nodes with points (embed()'s list): an empty node's cache line is never read.
    // The loop waits on memory at each node's first load (its TriNode, 112 bytes apart from
    // the last one's or more, and its first points), so it asks for them ahead: the TriNode
    // kNodesAhead nodes on (its two lines, written by the fit) and the next node's first line
    // of each coordinate array (its points follow the current node's).
    constexpr std::size_t kNodesAhead = 4;
    const std::vector<uint32_t>& occupied = field.occupiedNodes();
    const std::size_t num_occupied = occupied.size();
    for (std::size_t j = 0; j < num_occupied; ++j) {
        const uint32_t id = occupied[j];
        TriNode& node = model.nodes[id];
        if (j + kNodesAhead < num_occupied) {
            const char* ahead =
                reinterpret_cast<const char*>(&model.nodes[occupied[j + kNodesAhead]]);
            __builtin_prefetch(ahead, 1), __builtin_prefetch(ahead + 63, 1);
        }
        const uint32_t end = node.begin + node.count;
        __builtin_prefetch(sz + end), __builtin_prefetch(sx + end), __builtin_prefetch(sy + end);
        const float* x = sx + node.begin;
        const float* y = sy + node.begin;
        const float* z = sz + node.begin;
        node.lpr = lowestPointRepresentative(z, node.count, params.lpr_num_points);
        if (node.count < static_cast<uint32_t>(params.node_min_points)) {
            // Too few points for a reliable plane. TTMF may still give the node a plane.
            node.node_class = NodeClass::Unknown;
            continue;
        }
        // Node-local origin: cell centre in xy, LPR in z.
        const Eigen::Vector2f c = model.cellCenter(static_cast<int>(id / 4));
        const float origin[3] = {c.x(), c.y(), node.lpr};
        const SeedBand seeds{-static_cast<float>(params.seed_margin_below_lpr),
                             static_cast<float>(params.seed_margin_above_lpr)};
        Plane plane;
        bool ok =
            fitPlane(params.line_node_ratio, accumulate(x, y, z, node.count, origin, seeds), plane);
        BelowPlane fitted_from{};  // the selection of the last refit
        for (int it = 1; ok && it < params.plane_fit_iterations; ++it) {
            const BelowPlane inliers = belowPlane(plane, params.plane_inlier_dist);
            // The same points as the last fit give the same plane: the iteration has converged
            // (a check pass costs a fraction of a moment pass and its eigen solve).
            const bool converged =
                it == 1 ? sameSelection(x, y, z, node.count, origin, seeds, inliers)
                        : sameSelection(x, y, z, node.count, origin, fitted_from, inliers);
            if (converged) break;
            Plane next;
            if (!fitPlane(params.line_node_ratio, accumulate(x, y, z, node.count, origin, inliers),
                          next))
                break;
            plane = next;
            fitted_from = inliers;
        }
        if (!ok) {
            node.node_class = NodeClass::Unknown;
            continue;
        }
        node.normal = plane.normal.cast<float>();
        node.mean = Eigen::Vector3f(static_cast<float>(plane.mean_local.x() + origin[0]),
                                    static_cast<float>(plane.mean_local.y() + origin[1]),
                                    static_cast<float>(plane.mean_local.z() + origin[2]));
        node.d = -node.normal.dot(node.mean);
        node.eigenvalues = plane.eigenvalues.cast<float>();
        const double l1 = plane.eigenvalues(0), l2 = plane.eigenvalues(1);
        const double l3 = plane.eigenvalues(2);
        // eq. 1; the 1e-6 m^2 floor on l3 keeps noise-free planes finite and comparable.
        node.weight = static_cast<float>(l2 * (l1 + l2) / (std::max(l1, 1e-12) * (l3 + 1e-6)));
        node.node_class =
            plane.normal.z() >= cos_max_slope ? NodeClass::Terrain : NodeClass::Obstacle;
    }
}

}  // namespace travel
