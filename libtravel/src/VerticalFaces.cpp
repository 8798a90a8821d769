// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/VerticalFaces.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "CpuDispatch.hpp"

namespace travel {
namespace {

// The rings of a face read for its thickness, from its point up.
constexpr int kFaceRings = 8;

// flag[i] = 1 when point i's cell lies in its column's window (spans[col + 1]: lo | rows << 16;
// spans[0] the empty window of the points without a cell), else 0.
TRAVEL_AVX2_CLONES void markInWindows(const int16_t* __restrict row, const int32_t* __restrict col,
                                      const uint32_t* __restrict spans, std::size_t n,
                                      uint8_t* __restrict flag) {
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t span = spans[col[i] + 1];
        const uint32_t r = static_cast<uint32_t>(row[i] - static_cast<int16_t>(span & 0xffffu));
        flag[i] = r < (span >> 16);
    }
}

}  // namespace

int32_t VerticalFaces::climbToFace(const Cell* cell, std::ptrdiff_t stride, int steps, float foot_z,
                                   float foot_range, const std::vector<PointClass>& labels,
                                   float min_rise, int max_gap) {
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
        const float range = std::sqrt(cell->r2);
        // Steeper than 45 degrees: no traversable slope climbs like this.
        if (!(dz > std::fabs(range - prev_range))) return -1;
        risen = risen || cell->z - foot_z >= min_rise;
        if (face < 0 && labels[j] == PointClass::NonGround) face = j;
        if (risen && face >= 0) return face;
        prev_z = cell->z, prev_range = range;
    }
    return -1;
}

float VerticalFaces::faceThickness(const Cell* cell, int rings, float face_range) {
    // Returns 0.5 m or more behind the face went through it (mesh, a window, a gap): not the
    // face. The median absolute deviation from the median: half of the returns lie on one
    // plane at most this thick, whatever a footing's front or a ledge adds to the rest.
    const float behind = face_range + 0.5f;
    float range[kFaceRings];
    int count = 0;
    for (int k = 0; k < rings && k < kFaceRings; ++k) {
        const float r = std::sqrt(cell[k].r2);
        if (cell[k].point >= 0 && r < behind) range[count++] = r;
    }
    if (count < 2) return 0.f;
    std::sort(range, range + count);
    const float median = range[(count - 1) / 2];
    for (int k = 0; k < count; ++k) range[k] = std::fabs(range[k] - median);
    std::sort(range, range + count);
    return range[(count - 1) / 2];
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
    cells_.assign(num_cells, kEmptyCell);
    Cell* cells = cells_.data();
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    const float* z = cloud.z.data();
    for (std::size_t i = 0; i < n; ++i) {
        if (row[i] < 0) continue;
        Cell& cell = cells[static_cast<std::size_t>(row[i]) * cols + col[i]];
        const float r2 = x[i] * x[i] + y[i] * y[i];
        cell.keepNearest(static_cast<int32_t>(i), z[i], r2);
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
                        labels, min_rise, max_gap);
        if (face >= 0) {
            face_feet_.push_back(static_cast<uint32_t>(i));
            foot_faces_.push_back(static_cast<uint32_t>(face));
        }
    }
    finish(labels, counts);
}

void VerticalFaces::unlabelWallFeet(const AlignedCloud& cloud, const RangeImage& image,
                                    const Params& params, const std::vector<int16_t>& bottom_row,
                                    const std::vector<float>& bottom_range,
                                    std::vector<PointClass>& labels,
                                    std::array<std::size_t, 4>& counts) {
    face_feet_.clear(), foot_faces_.clear();
    const float min_rise = static_cast<float>(params.vertical_face_min_rise);
    const int max_gap = params.vertical_face_max_gap;
    const int rows = image.rows(), cols = image.cols();
    if (!(min_rise > 0.f) || rows < 2 || cols < 1) return;
    // The rows a foot's climb can span: the feet lie in eq. 5's band (eps3 above the plane,
    // below the wall's lowest clustered point) and climb min_rise, about 0.45 m of face: 10
    // rings 5 m away at the HDL-64E's 0.5 deg (0.044 m per ring; 0.4 deg above -8.3 deg).
    // Nearer walls keep their lowest feet.
    constexpr int kRowsBelow = 10, kRowsAbove = 10;
    // Each step of a climb rises more than its range changes, and a climb through eq. 5's band
    // (eps3 above the plane, outlier_dist below it) up to the wall's lowest point rises less
    // than this: a foot's xy range is at most this short of that point's.
    const float reach = static_cast<float>(params.ground_dist + params.outlier_dist +
                                           params.vertical_face_min_rise);
    windows_.resize(static_cast<std::size_t>(cols));
    uint32_t num_cells = 0;
    for (int c = 0; c < cols; ++c) {
        Window& w = windows_[c];
        const int bottom = bottom_row[c];
        w = Window{};
        if (bottom <= 0) continue;  // no wall here, or nothing below its lowest point
        const int lo = std::max(0, bottom - kRowsBelow), hi = std::min(rows, bottom + kRowsAbove);
        const float min_range = std::max(0.f, bottom_range[c] - reach);
        w.lo = static_cast<int16_t>(lo), w.rows = static_cast<int16_t>(hi - lo);
        w.feet_below = static_cast<int16_t>(bottom - lo);
        w.begin = num_cells, w.min_r2 = min_range * min_range;
        num_cells += static_cast<uint32_t>(hi - lo);
    }
    if (num_cells == 0) return;
    cells_.assign(num_cells, kEmptyCell);
    Cell* cells = cells_.data();
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();
    const Window* windows = windows_.data();
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    const float* z = cloud.z.data();
    const std::size_t n = labels.size();
    // The points in the windows (the range image has no per-cell index of its points: one
    // pass over every point); spans_[c + 1] is column c's window, lo | rows << 16; spans_[0] is
    // the empty window of the points without a row or column (-1).
    spans_.resize(static_cast<std::size_t>(cols) + 1);
    spans_[0] = 0;
    for (int c = 0; c < cols; ++c)
        spans_[c + 1] = static_cast<uint32_t>(static_cast<uint16_t>(windows_[c].lo)) |
                        static_cast<uint32_t>(windows_[c].rows) << 16;
    const int16_t* rows_of = row.data();
    const int32_t* cols_of = col.data();
    // Flags first (a vectorised loop), then the flagged points eight flags at a time: the
    // points of a window come in runs (a ring crossing the column, or a column's rings), so
    // most words are empty.
    const std::size_t words = (n + 7) / 8;
    window_flags_.resize(words * 8);
    markInWindows(rows_of, cols_of, spans_.data(), n, window_flags_.data());
    std::fill(window_flags_.begin() + static_cast<std::ptrdiff_t>(n), window_flags_.end(), 0);
    in_window_.resize(n);
    uint32_t* in_window = in_window_.data();
    uint32_t num_in = 0;
    const uint8_t* flags = window_flags_.data();
    for (std::size_t k = 0; k < words; ++k) {
        uint64_t word;
        std::memcpy(&word, flags + 8 * k, sizeof word);
        if (word == 0) continue;
        for (uint32_t b = 0; b < 8; ++b) {
            in_window[num_in] = static_cast<uint32_t>(8 * k + b);
            num_in += flags[8 * k + b];
        }
    }
    // Their cells (nearest point in xy, as unlabelFaceFeet()) and the candidate feet: ground
    // points below a wall's lowest point, within reach of it (listed without a branch: they
    // are about a fifth of the points in the windows, unpredictably).
    candidates_.resize(num_in);
    uint32_t* candidates = candidates_.data();
    uint32_t num_candidates = 0;
    const PointClass* label = labels.data();
    for (uint32_t k = 0; k < num_in; ++k) {
        const uint32_t i = in_window[k];
        const Window& w = windows[cols_of[i]];
        const int r = rows_of[i] - w.lo;
        Cell& cell = cells[w.begin + r];
        const float r2 = x[i] * x[i] + y[i] * y[i];
        cell.keepNearest(static_cast<int32_t>(i), z[i], r2);
        candidates[num_candidates] = i;
        num_candidates += (r < w.feet_below) & (r2 >= w.min_r2) & (label[i] == PointClass::Ground);
    }
    candidates_.resize(num_candidates);
    // A wall or fence is one vertical plane: along one azimuth its returns lie at one xy range
    // (within the range noise, about 0.02 m); a hedge scatters them through its depth. The
    // face is read over 8 rings from its point up (0.35-0.7 m of face 5-10 m from an HDL-64E).
    const float max_thickness = static_cast<float>(params.vertical_face_max_thickness);
    for (const uint32_t i : candidates_) {
        const Window& w = windows[col[i]];
        const int above = row[i] - w.lo + 1;
        const int32_t face =
            climbToFace(&cells[w.begin + above], 1, w.rows - above, z[i],
                        std::sqrt(x[i] * x[i] + y[i] * y[i]), labels, min_rise, max_gap);
        if (face < 0) continue;
        if (max_thickness > 0.f) {
            const int face_row = row[face] - w.lo;
            const float face_range = std::sqrt(x[face] * x[face] + y[face] * y[face]);
            const int rings = std::min(kFaceRings, w.rows - face_row);
            if (faceThickness(&cells[w.begin + face_row], rings, face_range) > max_thickness)
                continue;
        }
        face_feet_.push_back(i), foot_faces_.push_back(static_cast<uint32_t>(face));
    }
    finish(labels, counts);
}

}  // namespace travel
