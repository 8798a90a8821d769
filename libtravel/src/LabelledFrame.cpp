// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/LabelledFrame.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <stdexcept>
#include <string>

namespace travel {

void TerrainSummary::assign(const TerrainModel& model) {
    static_cast<TriGridGeometry&>(*this) = model;
    nodes.clear();
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const TriNode& node = model.nodes[i];
        if (node.node_class == NodeClass::Empty) continue;
        TerrainNodeRecord r;
        r.index = static_cast<uint32_t>(i);
        r.node_class = node.node_class;
        r.traversable = node.traversable;
        r.refitted = node.refitted;
        r.normal = node.refitted ? node.refit_normal : node.normal;
        r.d = node.refitted ? node.refit_d : node.d;
        r.mean = node.refitted ? node.refit_mean : node.mean;
        r.corner_z = node.corner_z;
        nodes.push_back(r);
    }
}

std::size_t TerrainSummary::numTraversable() const {
    return static_cast<std::size_t>(std::count_if(
        nodes.begin(), nodes.end(), [](const TerrainNodeRecord& n) { return n.traversable; }));
}

bool TerrainSummary::triangle3D(const TerrainNodeRecord& node,
                                std::array<Eigen::Vector3f, 3>& out) const {
    if (!hasCells()) return false;
    const std::array<Eigen::Vector2f, 3> xy = triangleCorners(static_cast<int>(node.index));
    for (int k = 0; k < 3; ++k) {
        const float h = planeHeightAt(node.normal, node.d, xy[k].x(), xy[k].y());
        if (!std::isfinite(h)) return false;
        out[k] = {xy[k].x(), xy[k].y(), h};
    }
    return true;
}

void LabelledFrame::assign(const PointCloud& cloud, const Result& result,
                           const Eigen::Matrix3f& aligned_rotation) {
    const std::size_t n = cloud.size();
    if (result.labels.size() != n || (!result.cluster_id.empty() && result.cluster_id.size() != n))
        throw std::invalid_argument("CObservationTravelLabels::assign: the result has " +
                                    std::to_string(result.labels.size()) + " labels and " +
                                    std::to_string(result.cluster_id.size()) +
                                    " cluster ids for a cloud of " + std::to_string(n) +
                                    " points (expected equal sizes)");
    if (cloud.y.size() != n || cloud.z.size() != n)
        throw std::invalid_argument("CObservationTravelLabels::assign: x, y, z sizes differ");

    x.assign(cloud.x.begin(), cloud.x.end());
    y.assign(cloud.y.begin(), cloud.y.end());
    z.assign(cloud.z.begin(), cloud.z.end());
    if (cloud.intensity.size() == n)
        intensity.assign(cloud.intensity.begin(), cloud.intensity.end());
    else
        intensity.assign(n, 0.f);
    labels.resize(n);
    for (std::size_t i = 0; i < n; ++i) labels[i] = static_cast<uint8_t>(result.labels[i]);
    if (result.cluster_id.empty())
        clusterId.assign(n, 0u);
    else
        clusterId.assign(result.cluster_id.begin(), result.cluster_id.end());
    clusters.assign(result.clusters.begin(), result.clusters.end());
    terrain.assign(result.terrain);
    alignedRotation = aligned_rotation;
    timings = result.timings;
}

std::size_t LabelledFrame::count(PointClass c) const {
    return static_cast<std::size_t>(
        std::count(labels.begin(), labels.end(), static_cast<uint8_t>(c)));
}

void LabelledFrame::describe(std::ostream& o) const {
    const std::ios_base::fmtflags old_flags = o.flags();
    const std::streamsize old_precision = o.precision();
    const std::size_t n = labels.size();
    const auto percent = [n](std::size_t k) { return n ? 100.0 * k / n : 0.0; };
    o << "Points: " << n << "\n" << std::fixed << std::setprecision(1);
    for (PointClass c :
         {PointClass::Ground, PointClass::NonGround, PointClass::Outlier, PointClass::Invalid}) {
        const std::size_t k = count(c);
        o << "  " << std::left << std::setw(10) << toString(c) << std::right << std::setw(8) << k
          << "  (" << percent(k) << " %)\n";
    }
    o << "Clusters: " << clusters.size() << "\n";
    if (!clusters.empty()) {
        std::vector<const ClusterSummary*> largest;
        largest.reserve(clusters.size());
        for (const auto& c : clusters) largest.push_back(&c);
        const std::size_t shown = std::min<std::size_t>(5, largest.size());
        std::partial_sort(
            largest.begin(), largest.begin() + shown, largest.end(),
            [](const auto* a, const auto* b) { return a->num_points > b->num_points; });
        o << "  largest (aligned frame, m): id, points, centroid, size\n" << std::setprecision(2);
        for (std::size_t k = 0; k < shown; ++k) {
            const auto& c = *largest[k];
            const Eigen::Vector3f size = c.aabb_max - c.aabb_min;
            o << "  #" << c.id << "  " << c.num_points << "  (" << c.centroid.x() << ", "
              << c.centroid.y() << ", " << c.centroid.z() << ")  " << size.x() << " x " << size.y()
              << " x " << size.z() << "\n";
        }
        // Tracking (travel::Tracker): only when something was tracked, so untracked frames
        // read as before.
        std::size_t tracked = 0, moving = 0;
        for (const auto& c : clusters) tracked += c.track_id != 0, moving += c.moving;
        if (tracked) {
            o << "  tracked: " << tracked << " clusters, " << moving
              << " moving (id -> track, velocity m/s):";
            for (const auto& c : clusters)
                if (c.moving)
                    o << "  #" << c.id << " -> " << c.track_id << " (" << c.velocity.x() << ", "
                      << c.velocity.y() << ")";
            o << "\n";
        }
    }
    o << std::setprecision(2) << "Terrain: " << terrain.nodes.size() << " non-empty nodes, "
      << terrain.numTraversable() << " traversable (cells of " << terrain.resolution << " m, "
      << terrain.cells_per_side << " per side)\n";
    const StageTimings& t = timings;
    o << "Timings [ms]: ground " << t.ground_total << " (preprocess " << t.preprocess
      << ", embedding " << t.embedding << ", node fitting " << t.node_fitting << ", graph search "
      << t.graph_search << ", TTMF " << t.ttmf << ", labelling " << t.labelling << ")\n";
    o << "              objects " << t.objects_total << " (range image " << t.range_image
      << ", horizontal " << t.horizontal << ", vertical " << t.vertical << ", clusters "
      << t.clusters << ")\n";
    o.flags(old_flags);
    o.precision(old_precision);
}

}  // namespace travel
