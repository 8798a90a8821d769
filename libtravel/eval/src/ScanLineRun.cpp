// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/ScanLineRun.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "travel/eval/Segmenter.hpp"

namespace travel::eval {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

ScanLineRun::ScanLineRun(const SlrOptions& options) : options_(options) {}

int ScanLineRun::find(int run) {
    while (parent_[run] != run) run = parent_[run] = parent_[parent_[run]];  // path halving
    return run;
}

void ScanLineRun::cluster(const PointCloud& cloud, const AlignedCloud& aligned,
                          const RangeImage& image, const std::vector<PointClass>& labels,
                          const Params& params, std::vector<uint32_t>& cluster_id) {
    const std::size_t n = labels.size();
    cluster_id.assign(n, 0u);
    const int rows = image.rows(), cols = image.cols();
    if (rows <= 0 || cols <= 0) return;
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();

    // Counting sort of the non-ground points by (row, column): each scan line in azimuth order.
    const std::size_t cells = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    cell_begin_.assign(cells + 1, 0u);
    const auto isCandidate = [&](std::size_t i) {
        return labels[i] == PointClass::NonGround && row[i] >= 0 && col[i] >= 0;
    };
    const auto cellOf = [&](std::size_t i) {
        return static_cast<std::size_t>(row[i]) * static_cast<std::size_t>(cols) +
               static_cast<std::size_t>(col[i]);
    };
    for (std::size_t i = 0; i < n; ++i)
        if (isCandidate(i)) ++cell_begin_[cellOf(i) + 1];
    for (std::size_t c = 0; c < cells; ++c) cell_begin_[c + 1] += cell_begin_[c];
    sorted_.resize(cell_begin_[cells]);
    {
        // Fill through a moving cursor per cell; stable, so ties keep input order.
        point_run_.assign(cells, 0);  // reused as the cursor, reset below
        for (std::size_t i = 0; i < n; ++i) {
            if (!isCandidate(i)) continue;
            const std::size_t c = cellOf(i);
            sorted_[cell_begin_[c] + static_cast<uint32_t>(point_run_[c]++)] =
                static_cast<uint32_t>(i);
        }
    }
    point_run_.assign(sorted_.size(), -1);
    parent_.clear();

    const auto dist2 = [&](uint32_t a, uint32_t b) {
        const float dx = aligned.x[a] - aligned.x[b], dy = aligned.y[a] - aligned.y[b],
                    dz = aligned.z[a] - aligned.z[b];
        return dx * dx + dy * dy + dz * dz;
    };
    const float run2 = static_cast<float>(options_.run_threshold * options_.run_threshold);
    const float merge2 = static_cast<float>(options_.merge_threshold * options_.merge_threshold);
    const double column_angle = 2.0 * kPi / cols;
    // sin^2 of a column offset, up to a quarter turn (the search never goes further).
    offset_sin2_.resize(static_cast<std::size_t>(cols / 4 + 3));
    for (std::size_t d = 0; d < offset_sin2_.size(); ++d)
        offset_sin2_[d] = static_cast<float>(std::pow(std::sin(d * column_angle), 2));
    const auto unite = [&](int a, int b) {
        a = find(a), b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the smaller label wins
    };

    // From the top scan line down: each line's runs inherit from the line above.
    for (int r = rows - 1; r >= 0; --r) {
        const std::size_t line_begin = cell_begin_[static_cast<std::size_t>(r) * cols];
        const std::size_t line_end = cell_begin_[static_cast<std::size_t>(r + 1) * cols];
        if (line_begin == line_end) continue;
        const int first_run = static_cast<int>(parent_.size());
        // Runs: consecutive non-ground points of the line closer than Th_run.
        for (std::size_t k = line_begin; k < line_end; ++k) {
            if (k == line_begin || dist2(sorted_[k - 1], sorted_[k]) >= run2)
                parent_.push_back(static_cast<int32_t>(parent_.size()));
            point_run_[k] = static_cast<int32_t>(parent_.size()) - 1;
        }
        const int last_run = static_cast<int>(parent_.size()) - 1;
        // Circular line: the last run continues into the first across the seam.
        if (last_run > first_run && dist2(sorted_[line_end - 1], sorted_[line_begin]) < run2)
            unite(last_run, first_run);

        if (r + 1 >= rows) continue;
        const std::size_t above_row = static_cast<std::size_t>(r + 1) * cols;
        if (cell_begin_[above_row] == cell_begin_[above_row + cols]) continue;
        // Label propagation: each point's nearest non-ground point on the line above, searched
        // over the columns that can hold a point within Th_merge (azimuth +- asin(Th / r_xy)),
        // outwards from the point's column. A point delta columns away is at least
        // r_xy sin((delta - 1) column_angle) away (distance to that azimuth's half-plane), so
        // the search stops once that exceeds the best distance found: still the exact nearest.
        for (std::size_t k = line_begin; k < line_end; ++k) {
            const uint32_t i = sorted_[k];
            const double range_xy = std::hypot(cloud.x[i], cloud.y[i]);
            int half_width = cols;
            if (range_xy > options_.merge_threshold)
                half_width = static_cast<int>(std::ceil(
                                 std::asin(options_.merge_threshold / range_xy) / column_angle)) +
                             1;
            float best = std::numeric_limits<float>::max();
            int32_t best_run = -1;
            const auto scan = [&](std::size_t from, std::size_t to) {
                for (std::size_t q = from; q < to; ++q) {
                    const float d2 = dist2(i, sorted_[q]);
                    if (d2 < best) best = d2, best_run = point_run_[q];
                }
            };
            if (2 * half_width + 1 >= cols) {
                scan(cell_begin_[above_row], cell_begin_[above_row + cols]);
            } else {
                const float r2 = static_cast<float>(range_xy * range_xy);
                for (int delta = 0; delta <= half_width; ++delta) {
                    if (delta >= 2 && r2 * offset_sin2_[delta - 1] >= std::min(best, merge2)) break;
                    const std::size_t right =
                        above_row + static_cast<std::size_t>((col[i] + delta) % cols);
                    scan(cell_begin_[right], cell_begin_[right + 1]);
                    if (delta == 0) continue;
                    const std::size_t left =
                        above_row + static_cast<std::size_t>((col[i] - delta + cols) % cols);
                    scan(cell_begin_[left], cell_begin_[left + 1]);
                }
            }
            if (best_run >= 0 && best < merge2) unite(point_run_[k], best_run);
        }
    }

    for (std::size_t k = 0; k < sorted_.size(); ++k)
        cluster_id[sorted_[k]] = static_cast<uint32_t>(find(point_run_[k])) + 1;
    renumberClusters(cluster_id, static_cast<uint32_t>(parent_.size()), params.min_cluster_size,
                     params.max_cluster_size, count_, new_id_);
}

}  // namespace travel::eval
