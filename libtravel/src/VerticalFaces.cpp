// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/VerticalFaces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace travel {

int32_t VerticalFaces::climbToFace(const Cell* cell, std::ptrdiff_t stride, int steps, float foot_z,
                                   float foot_range, const AlignedCloud& cloud,
                                   const std::vector<PointClass>& labels, float min_rise,
                                   int max_gap) {
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    float prev_z = foot_z, prev_range = foot_range;
    bool risen = false;
    int32_t face = -1;  // the first non-ground point of the climb
    int missing = 0;    // consecutive rings without a return
    for (; steps > 0; --steps, cell += stride) {
        const int32_t j = cell->point;
        // No return on this ring: foliage, mesh or dark paint let part of the rays pass or
        // absorb them. The climb resumes from its last point on the next ring that returned,
        // at most max_gap rings on (the steepness test spans the gap).
        if (j < 0) {
            if (++missing > max_gap) return -1;
            continue;
        }
        missing = 0;
        const float dz = cell->z - prev_z;
        if (!(dz > 0.f)) return -1;
        const float range = std::sqrt(x[j] * x[j] + y[j] * y[j]);
        // Steeper than 45 degrees: no traversable slope climbs like this.
        if (!(dz > std::fabs(range - prev_range))) return -1;
        risen = risen || cell->z - foot_z >= min_rise;
        if (face < 0 && labels[j] == PointClass::NonGround) face = j;
        if (risen && face >= 0) return face;
        prev_z = cell->z, prev_range = range;
    }
    return -1;
}

void VerticalFaces::finish(std::vector<PointClass>& labels,
                           std::array<std::size_t, 4>& counts) const {
    for (const uint32_t i : face_feet_) labels[i] = PointClass::NonGround;
    counts[static_cast<int>(PointClass::Ground)] -= face_feet_.size();
    counts[static_cast<int>(PointClass::NonGround)] += face_feet_.size();
}

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
    if (!(min_rise > 0.f) || params.vertical_face_min_length > 0.0 || rows < 2 || cols < 1) return;
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
        const int above = row[i] + 1;
        if (above >= rows) continue;
        const Cell& next = cells[static_cast<std::size_t>(above) * cols + col[i]];
        // Most ground points: the next ring returned and is not higher (checked before any
        // square root).
        if (next.point >= 0 ? !(next.z > z[i]) : max_gap == 0) continue;
        // A foot within range noise of its ground plane is on the ground as far as the scan
        // tells (the road before a car's sill or tyre): it stays ground.
        if (foot_height && foot_height[i] < min_foot) continue;
        const int32_t face =
            climbToFace(&next, cols, rows - above, z[i], std::sqrt(x[i] * x[i] + y[i] * y[i]),
                        cloud, labels, min_rise, max_gap);
        if (face >= 0) {
            face_feet_.push_back(static_cast<uint32_t>(i));
            foot_faces_.push_back(static_cast<uint32_t>(face));
        }
    }
    finish(labels, counts);
}

void VerticalFaces::unlabelWallFeet(const AlignedCloud& cloud, const RangeImage& image,
                                    const Params& params, const std::vector<int16_t>& bottom_row,
                                    std::vector<PointClass>& labels,
                                    std::array<std::size_t, 4>& counts) {
    face_feet_.clear(), foot_faces_.clear();
    const float min_rise = static_cast<float>(params.vertical_face_min_rise);
    const int max_gap = params.vertical_face_max_gap;
    const int rows = image.rows(), cols = image.cols();
    if (!(min_rise > 0.f) || rows < 2 || cols < 1) return;
    // The rows a foot's climb can span: the feet lie in eq. 5's band (eps3 above the plane,
    // below the wall's lowest clustered point) and climb min_rise; 0.5 m of face is 16 rings
    // 1.8 m away at 1 ring per 1 mrad (OS1-128's 0.35 deg: 1.8 m -> 0.5 m / 16). Closer walls
    // keep their lowest feet.
    constexpr int kRowsBelow = 16, kRowsAbove = 16;
    window_lo_.assign(static_cast<std::size_t>(cols), 0);
    window_rows_.assign(static_cast<std::size_t>(cols), 0);
    window_begin_.resize(static_cast<std::size_t>(cols));
    uint32_t num_cells = 0;
    for (int c = 0; c < cols; ++c) {
        window_begin_[c] = num_cells;
        const int bottom = bottom_row[c];
        if (bottom <= 0) continue;  // no wall here, or nothing below its lowest point
        const int lo = std::max(0, bottom - kRowsBelow), hi = std::min(rows, bottom + kRowsAbove);
        window_lo_[c] = static_cast<int16_t>(lo), window_rows_[c] = static_cast<int16_t>(hi - lo);
        num_cells += static_cast<uint32_t>(hi - lo);
    }
    if (num_cells == 0) return;
    cells_.assign(num_cells, Cell{std::numeric_limits<float>::quiet_NaN(), -1});
    Cell* cells = cells_.data();
    candidates_.clear();
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();
    const int16_t* lo = window_lo_.data();
    const int16_t* num_rows = window_rows_.data();
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    const float* z = cloud.z.data();
    const std::size_t n = labels.size();
    // The windows' cells (nearest point in xy, as unlabelFaceFeet()) and the ground points
    // below each wall's lowest point. A point without a row has row -1: below every window.
    for (std::size_t i = 0; i < n; ++i) {
        const int c = col[i] < 0 ? 0 : col[i];
        const unsigned r = static_cast<unsigned>(row[i] - lo[c]);
        if (r >= static_cast<unsigned>(num_rows[c])) continue;
        Cell& cell = cells[window_begin_[c] + r];
        const int32_t k = cell.point;
        if (k < 0 || x[i] * x[i] + y[i] * y[i] < x[k] * x[k] + y[k] * y[k])
            cell.point = static_cast<int32_t>(i), cell.z = z[i];
        if (labels[i] == PointClass::Ground && row[i] < bottom_row[c])
            candidates_.push_back(static_cast<uint32_t>(i));
    }
    for (const uint32_t i : candidates_) {
        const int c = col[i];
        const int above = row[i] - lo[c] + 1;
        const int32_t face =
            climbToFace(&cells[window_begin_[c] + above], 1, num_rows[c] - above, z[i],
                        std::sqrt(x[i] * x[i] + y[i] * y[i]), cloud, labels, min_rise, max_gap);
        if (face >= 0) face_feet_.push_back(i), foot_faces_.push_back(static_cast<uint32_t>(face));
    }
    finish(labels, counts);
}

}  // namespace travel
