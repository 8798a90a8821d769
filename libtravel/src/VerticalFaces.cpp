// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/VerticalFaces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace travel {

void VerticalFaces::unlabelFaceFeet(const AlignedCloud& cloud, const RangeImage& image,
                                    const Params& params, std::vector<PointClass>& labels,
                                    std::array<std::size_t, 4>& counts,
                                    const std::vector<float>* heights) {
    face_feet_.clear(), foot_faces_.clear();
    const float min_rise = static_cast<float>(params.vertical_face_min_rise);
    const int max_gap = params.vertical_face_max_gap;
    const float min_foot = static_cast<float>(params.vertical_face_min_foot_height);
    const float* foot_height = min_foot > 0.f && heights ? heights->data() : nullptr;
    const int rows = image.rows(), cols = image.cols();
    if (!(min_rise > 0.f) || rows < 2 || cols < 1) return;
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();
    const std::size_t n = labels.size();
    const std::size_t num_cells = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    // Each cell's point (the nearest in xy, so that the choice depends neither on the order of
    // the points nor on invalid points between them) and its height; an empty cell has a NaN
    // height, which no climb passes.
    cells_.assign(num_cells, Cell{std::numeric_limits<float>::quiet_NaN(), -1});
    Cell* cells = cells_.data();
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    const float* z = cloud.z.data();
    for (std::size_t i = 0; i < n; ++i) {
        if (row[i] < 0) continue;
        Cell& cell = cells[static_cast<std::size_t>(row[i]) * cols + col[i]];
        const int32_t k = cell.point;
        if (k < 0 || x[i] * x[i] + y[i] * y[i] < x[k] * x[k] + y[k] * y[k])
            cell.point = static_cast<int32_t>(i), cell.z = z[i];
    }
    // The labels of eq. 5 are read, not changed, in this pass: a foot's face is a non-ground
    // point of eq. 5, never another foot.
    for (std::size_t i = 0; i < n; ++i) {
        if (labels[i] != PointClass::Ground || row[i] < 0) continue;
        const float foot_z = z[i];
        std::size_t c = static_cast<std::size_t>(row[i] + 1) * cols + col[i];
        if (c >= num_cells) continue;
        // Most ground points: the next ring returned and is not higher (checked before any
        // square root).
        if (cells[c].point >= 0 ? !(cells[c].z > foot_z) : max_gap == 0) continue;
        // A foot within range noise of its ground plane is on the ground as far as the scan
        // tells (the road before a car's sill or tyre): it stays ground.
        if (foot_height && foot_height[i] < min_foot) continue;
        float prev_z = foot_z, prev_range = std::sqrt(x[i] * x[i] + y[i] * y[i]);
        bool risen = false;
        int32_t face = -1;  // the first non-ground point of the climb
        int missing = 0;    // consecutive rings without a return
        for (; c < num_cells; c += cols) {
            const int32_t j = cells[c].point;
            // No return on this ring: foliage, mesh or dark paint let part of the rays pass
            // or absorb them. The climb resumes from its last point on the next ring that
            // returned, at most max_gap rings on (the steepness test spans the gap).
            if (j < 0) {
                if (++missing > max_gap) break;
                continue;
            }
            missing = 0;
            const float dz = cells[c].z - prev_z;
            if (!(dz > 0.f)) break;
            const float range = std::sqrt(x[j] * x[j] + y[j] * y[j]);
            // Steeper than 45 degrees: no traversable slope climbs like this.
            if (!(dz > std::fabs(range - prev_range))) break;
            risen = risen || cells[c].z - foot_z >= min_rise;
            if (face < 0 && labels[j] == PointClass::NonGround) face = j;
            if (risen && face >= 0) {
                face_feet_.push_back(static_cast<uint32_t>(i));
                foot_faces_.push_back(static_cast<uint32_t>(face));
                break;
            }
            prev_z = cells[c].z, prev_range = range;
        }
    }
    for (const uint32_t i : face_feet_) labels[i] = PointClass::NonGround;
    counts[static_cast<int>(PointClass::Ground)] -= face_feet_.size();
    counts[static_cast<int>(PointClass::NonGround)] += face_feet_.size();
}

}  // namespace travel
