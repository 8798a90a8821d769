// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/FrameFusion.hpp"

#include <cmath>

namespace travel {

void fuseFrame(const PlacedFrame& frame, const MapSection& map, TraversabilityGrid& grid,
               RayEnds& ends) {
    const AlignedCloud& a = frame.aligned;
    const Result& result = frame.result;
    const TerrainModel& terrain = result.terrain;
    const std::size_t n = std::min({a.x.size(), a.valid.size(), result.labels.size()});
    const float min_h = float(map.obstacle_min_height);
    const float max_h = float(map.obstacle_max_height);
    const float max_ray = float(map.max_ray_length);
    const float sensor_height = float(result.sensor_height);
    ends.clear();
    const auto addEnd = [&](const Eigen::Vector3f& p, std::vector<Eigen::Vector3f>& near_list) {
        const float range = (p - frame.origin).norm();
        if (range > max_ray)  // too long to trust its end: carve up to max_ray only
            ends.far.push_back(frame.origin + (p - frame.origin) * (max_ray / range));
        else
            near_list.push_back(p);
    };

    grid.beginFrame();
    for (std::size_t i = 0; i < n; ++i) {
        if (!a.valid[i] || result.labels[i] != PointClass::Ground) continue;
        const Eigen::Vector3f pa(a.x[i], a.y[i], a.z[i]);
        const Eigen::Vector3f pw = frame.to_world * pa + frame.origin;
        grid.addGround(pw.x(), pw.y(), pw.z(), terrain.groundSlopeDeg(pa.x(), pa.y()));
        addEnd(pw, ends.ground);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!a.valid[i] || result.labels[i] != PointClass::NonGround) continue;
        const Eigen::Vector3f pa(a.x[i], a.y[i], a.z[i]);
        const Eigen::Vector3f pw = frame.to_world * pa + frame.origin;
        float height = terrain.heightAboveGround(pa.x(), pa.y(), pa.z());
        if (!std::isfinite(height)) {
            const long cell = grid.cellIndex(pw.x(), pw.y());
            const uint32_t cluster = i < result.cluster_id.size() ? result.cluster_id[i] : 0;
            if (cell >= 0 && std::isfinite(grid.groundHeightThisFrame(cell)))
                height = pw.z() - grid.groundHeightThisFrame(cell);
            else if (cluster > 0 && cluster <= result.clusters.size() &&
                     std::isfinite(result.clusters[cluster - 1].ground_z))
                height = pa.z() - result.clusters[cluster - 1].ground_z;
            else
                height = pa.z() + sensor_height;
        }
        if (height < min_h) continue;
        if (height <= max_h) grid.addObstacle(pw.x(), pw.y());
        addEnd(pw, ends.obstacle);
    }
    grid.endFrame(frame.time_s, map);
}

}  // namespace travel
