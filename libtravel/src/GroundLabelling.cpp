// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Point labels (paper eq. 5). With the ground plane (s, d) of the point's node
// (TerrainModel::groundPlane: TTMF's refitted plane of a traversable node) and the signed
// distance e = s.p + d:
//   e < -outlier_dist          -> Outlier (below-ground returns: reflections, multipath)
//   -outlier_dist <= e < eps3  -> Ground
//   otherwise                  -> NonGround
// Points of non-traversable nodes are NonGround. Invalid points stay Invalid. Every point gets
// exactly one class: nothing is dropped (the reference drops out-of-range and outlier points).
//
// Extension of eq. 5 (issue 14, verges): TTMF (Sec. III-D) averages each corner over the planes
// of all reached nodes around it, weighted by w (eq. 1); the heavy, flat road planes pull the
// corners of a verge node down, so a verge rising 0.1-0.5 m beside the road ends up 0.13-0.3 m
// above its refitted plane (80 % of the missed terrain on the dev frames, 2/3 of it on the
// synthetic verges). With label_with_node_plane, a point of a node the search reached (eq. 2
// verified its own plane against its neighbours) is also ground within eps3 of that own plane,
// e = min(e_refit, e_own), but only when the node is clear: no point stands own_plane_clearance
// or more above its own plane. A car, wall, fence or trunk in the node reaches higher, and the
// bases of such objects must not become ground (the unrestricted option lowered the dev-frame
// object coverage 0.933 -> 0.916); grass, verges and kerbs stay below.
#include "travel/GroundLabelling.hpp"

#include <algorithm>
#include <limits>

namespace travel {
namespace {

// Points per class. One counter per class, each a branch-free sum over all labels: a
// ++counts[label] per point would chain the increments of equal labels through memory.
std::array<std::size_t, 4> classCounts(const std::vector<PointClass>& labels) {
    const uint8_t* l = reinterpret_cast<const uint8_t*>(labels.data());
    const std::size_t n = labels.size();
    std::size_t ground = 0, non_ground = 0, outlier = 0;
    for (std::size_t i = 0; i < n; ++i) {
        ground += l[i] == static_cast<uint8_t>(PointClass::Ground) ? 1 : 0;
        non_ground += l[i] == static_cast<uint8_t>(PointClass::NonGround) ? 1 : 0;
        outlier += l[i] == static_cast<uint8_t>(PointClass::Outlier) ? 1 : 0;
    }
    return {n - ground - non_ground - outlier, ground, non_ground, outlier};
}

// True when no point of [begin, end) stands own_plane_clearance or more above the plane
// (s, d): nothing taller than grass or a kerb stands on the node. Branch-free max, vectorised.
bool clearAbovePlane(const float* x, const float* y, const float* z, uint32_t begin, uint32_t end,
                     float s0, float s1, float s2, float d, float clearance) {
    float highest = -std::numeric_limits<float>::infinity();
    for (uint32_t i = begin; i < end; ++i)
        highest = std::max(highest, s0 * x[i] + s1 * y[i] + s2 * z[i] + d);
    return highest < clearance;
}

}  // namespace

std::array<std::size_t, 4> labelPoints(const TriGridField& field, const AlignedCloud& cloud,
                                       const Params& params, const TerrainModel& model,
                                       std::vector<PointClass>& labels) {
    const std::size_t n = cloud.valid.size();
    labels.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        labels[i] = cloud.valid[i] ? PointClass::NonGround : PointClass::Invalid;

    const float* sx = field.sx().data();
    const float* sy = field.sy().data();
    const float* sz = field.sz().data();
    const uint32_t* order = field.order().data();
    const float ground_dist = static_cast<float>(params.ground_dist);
    const float outlier_dist = static_cast<float>(params.outlier_dist);
    const float own_plane_clearance = static_cast<float>(params.own_plane_clearance);
    const int num_nodes = static_cast<int>(model.nodes.size());
    for (int k = 0; k < num_nodes; ++k) {
        const TriNode& node = model.nodes[k];
        const std::optional<GroundPlane> ground = model.groundPlane(k);
        if (!ground || node.count == 0) continue;
        const float s0 = ground->normal.x(), s1 = ground->normal.y();
        const float s2 = ground->normal.z(), d = ground->d;
        // The node's own plane, when the search verified it: a point on either surface is
        // ground. Its signed distance is folded in as min(e, e_own) unless e_own says outlier.
        const float o0 = node.normal.x(), o1 = node.normal.y(), o2 = node.normal.z();
        const uint32_t end = node.begin + node.count;
        const bool own =
            params.label_with_node_plane && node.reached &&
            clearAbovePlane(sx, sy, sz, node.begin, end, o0, o1, o2, node.d, own_plane_clearance);
        const float od = own ? node.d : std::numeric_limits<float>::infinity();
        for (uint32_t i = node.begin; i < end; ++i) {
            const float e_refit = s0 * sx[i] + s1 * sy[i] + s2 * sz[i] + d;
            const float e_own = o0 * sx[i] + o1 * sy[i] + o2 * sz[i] + od;
            const float e = e_own >= -outlier_dist ? std::min(e_refit, e_own) : e_refit;
            labels[order[i]] = classifyByPlaneDistance(e, ground_dist, outlier_dist);
        }
    }
    return classCounts(labels);
}

}  // namespace travel
