// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/VerticalFaces.hpp"

#include <algorithm>
#include <cmath>

namespace travel {

void VerticalFaces::unlabelFaceFeet(const AlignedCloud& cloud, const RangeImage& image,
                                    const Params& params, std::vector<PointClass>& labels,
                                    std::array<std::size_t, 4>& counts) {
    face_feet_.clear(), foot_faces_.clear();
    const float min_rise = static_cast<float>(params.vertical_face_min_rise);
    const int rows = image.rows(), cols = image.cols();
    if (!(min_rise > 0.f) || rows < 2 || cols < 1) return;
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();
    const std::size_t n = labels.size();
    cell_point_.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols), -1);
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    const float* z = cloud.z.data();
    // One point per cell: the nearest (xy), so that the choice does not depend on the order
    // of the points (nor on invalid points between them).
    for (std::size_t i = 0; i < n; ++i) {
        if (row[i] < 0) continue;
        int32_t& cell = cell_point_[static_cast<std::size_t>(row[i]) * cols + col[i]];
        if (cell < 0 || x[i] * x[i] + y[i] * y[i] < x[cell] * x[cell] + y[cell] * y[cell])
            cell = static_cast<int32_t>(i);
    }
    // The labels of eq. 5 are read, not changed, in this pass: a foot's face is a non-ground
    // point of eq. 5, never another foot.
    for (std::size_t i = 0; i < n; ++i) {
        if (labels[i] != PointClass::Ground || row[i] < 0) continue;
        std::size_t prev = i;
        float prev_range = std::hypot(x[i], y[i]);
        bool risen = false;
        int32_t face = -1;  // the first non-ground point of the climb
        for (int r = row[i] + 1; r < rows; ++r) {
            const int32_t j = cell_point_[static_cast<std::size_t>(r) * cols + col[i]];
            if (j < 0) break;
            const float range = std::hypot(x[j], y[j]);
            const float dz = z[j] - z[prev];
            // Steeper than 45 degrees: no traversable slope climbs like this.
            if (!(dz > std::fabs(range - prev_range))) break;
            risen = risen || z[j] - z[i] >= min_rise;
            if (face < 0 && labels[j] == PointClass::NonGround) face = j;
            if (risen && face >= 0) {
                face_feet_.push_back(static_cast<uint32_t>(i));
                foot_faces_.push_back(static_cast<uint32_t>(face));
                break;
            }
            prev = static_cast<std::size_t>(j), prev_range = range;
        }
    }
    for (const uint32_t i : face_feet_) labels[i] = PointClass::NonGround;
    counts[static_cast<int>(PointClass::Ground)] -= face_feet_.size();
    counts[static_cast<int>(PointClass::NonGround)] += face_feet_.size();
}

}  // namespace travel
