// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// TTMF (paper Sec. III-D). Each reached (traversable) node i votes, at each of its three
// triangle corners v, the height of its own plane there, with weight w_i / dist_xy(m_i, v)
// (nearer, more planar nodes count more; the distance is floored at 1 cm so a mean sitting on a
// corner cannot divide by zero). A corner's height is the weighted mean of its votes.
// Every node whose three corners have heights gets the plane through them (normal = cross
// product, flipped up; mean = centroid of the corners) and is traversable when that plane is
// within max_slope of level - the reference's re-classification, which recovers the ground under
// and around objects (obstacle / unknown nodes surrounded by traversable ones).
// Decision: empty nodes also get a refitted plane when their corners are known (useful to map
// layers), but are never marked traversable: nothing was observed there.
#include "travel/TerrainModelFitting.hpp"

#include <cmath>
#include <limits>

#include "Prefault.hpp"

namespace travel {

void TerrainModelFitting::reserve(const TriGridField& field) {
    const std::size_t vertices = static_cast<std::size_t>(field.numVertices());
    detail::prefault(vote_weight_, vertices), detail::prefault(vote_weighted_z_, vertices);
}

void TerrainModelFitting::run(const TriGridField& field, const Params& params,
                              TerrainModel& model) {
    const int num_nodes = static_cast<int>(model.nodes.size());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    if (!params.ttmf) {
        for (TriNode& node : model.nodes) {
            node.corner_z.setConstant(nan);
            node.refitted = false;
            node.refit_normal = node.normal, node.refit_mean = node.mean, node.refit_d = node.d;
            node.traversable = node.reached;
        }
        return;
    }
    vote_weight_.assign(field.numVertices(), 0.0);
    vote_weighted_z_.assign(field.numVertices(), 0.0);
    // Votes of the reached nodes, in ascending order (the order of the sums): only nodes with
    // points (embed()'s list) can be reached, so the empty ones' cache lines are not read.
    for (const uint32_t occupied : field.occupiedNodes()) {
        const int id = static_cast<int>(occupied);
        const TriNode& node = model.nodes[id];
        if (!node.reached) continue;
        for (int k = 0; k < 3; ++k) {
            const int v = field.vertexId(id, k);
            float vx, vy;
            field.vertexXY(v, vx, vy);
            const double dist =
                std::max(0.01, std::hypot(double(vx) - node.mean.x(), double(vy) - node.mean.y()));
            const double w = static_cast<double>(node.weight) / dist;
            vote_weight_[v] += w;
            vote_weighted_z_[v] += w * planeHeightAt(node.normal, node.d, vx, vy);
        }
    }
    const double cos_max_slope = std::cos(params.max_slope_deg * M_PI / 180.0);
    for (int id = 0; id < num_nodes; ++id) {
        TriNode& node = model.nodes[id];
        node.refitted = false;
        node.traversable = false;
        Eigen::Vector3f corners[3];
        bool complete = true;
        for (int k = 0; k < 3; ++k) {
            const int v = field.vertexId(id, k);
            if (!(vote_weight_[v] > 0.0)) {
                complete = false;
                node.corner_z[k] = nan;
                continue;
            }
            field.vertexXY(v, corners[k].x(), corners[k].y());
            corners[k].z() = static_cast<float>(vote_weighted_z_[v] / vote_weight_[v]);
            node.corner_z[k] = corners[k].z();
        }
        if (!complete) continue;
        Eigen::Vector3f s = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
        const float len = s.norm();
        if (!(len > 0.f)) continue;
        s /= len;
        if (s.z() < 0.f) s = -s;
        node.refitted = true;
        node.refit_normal = s;
        node.refit_mean = (corners[0] + corners[1] + corners[2]) / 3.f;
        node.refit_d = -s.dot(node.refit_mean);
        node.traversable = node.count > 0 && s.z() >= cos_max_slope;
    }
}

}  // namespace travel
