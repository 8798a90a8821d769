// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-eval merges' diagnosis (eval::mergedParts) names, for each part of a merged cluster,
// the linkage rule of TRAVEL's object stage that can join it to the rest and the pair of points
// that satisfies it. The check here recomputes that claim from the rules' distance tests
// (Sec. IV: T_horz on one ring; T_vert within T_ring rows and T_ext columns, also range-scaled
// by the rows' spacing; the occlusion linkage's gap and depth, not the occluder it needs between
// the two ends, which the diagnosis does not look for either; the seam linkage's distance and
// columns) and the closest pair of an 'indirect' part failing them, on what the stage linked
// on: the pipeline's range-image rows and columns (built on its own validity mask), its aligned
// coordinates, its rows' spacing (RunClustering::ringSpacing()) and its parameters. A diagnosis
// that searched other rows (a range image rebuilt beside the pipeline), other coordinates or
// other thresholds would name pairs that fail here.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <vector>

#include "travel/Pipeline.hpp"
#include "travel/eval/MergeDiagnostics.hpp"

namespace travel::test {

/// Checks every part's linking pair against `pipeline` (which processed the parts' cloud
/// last) and `cluster_id` (what mergedParts was given); returns how many pairs were checked
/// (not counted: a part with no point within T_ring rows of the rest, and an 'indirect' part
/// whose closest pair is neither on one ring nor within T_ext columns).
inline std::size_t expectPairsSatisfyTheirRule(const std::vector<eval::MergedPart>& parts,
                                               const std::vector<uint32_t>& cluster_id,
                                               const Pipeline& pipeline) {
    const std::vector<int16_t>& row = pipeline.rangeImage().row();
    const std::vector<int32_t>& col = pipeline.rangeImage().col();
    const AlignedCloud& a = pipeline.aligned();
    const Params& params = pipeline.params();
    auto sq = [](double v) { return v * v; };
    // RunClustering's seam linkage: both ends within kSeamColumns of the sweep's start column.
    const int seam_col = pipeline.rangeImage().sweepStartColumn(),
              cols = pipeline.rangeImage().cols();
    auto nearSeam = [&](uint32_t i) {
        if (seam_col < 0) return false;
        const int d = std::abs(col[i] - seam_col) % cols;
        return std::min(d, cols - d) <= RunClustering::kSeamColumns;
    };
    auto range = [&](uint32_t i) {
        return std::sqrt(double(a.x[i]) * a.x[i] + double(a.y[i]) * a.y[i] +
                         double(a.z[i]) * a.z[i]);
    };
    std::size_t checked = 0;
    for (const eval::MergedPart& p : parts) {
        if (p.part_row < 0) continue;
        const uint32_t i = p.part_point, j = p.rest_point;
        SCOPED_TRACE(::testing::Message() << "cluster " << p.cluster << ", points " << i << ", "
                                          << j << ", rule " << eval::toString(p.rule));
        EXPECT_EQ(cluster_id[i], p.cluster);
        EXPECT_EQ(cluster_id[j], p.cluster);
        EXPECT_EQ(p.part_row, row[i]);
        EXPECT_EQ(p.rest_row, row[j]);
        EXPECT_EQ(p.row_gap, std::abs(row[i] - row[j]));
        const double dx = a.x[i] - a.x[j], dy = a.y[i] - a.y[j], dz = a.z[i] - a.z[j];
        const double d2 = dx * dx + dy * dy + dz * dz;
        EXPECT_NEAR(p.link_distance, std::sqrt(d2), 1e-4);
        EXPECT_NEAR(p.depth_jump, std::fabs(range(i) - range(j)), 1e-4);
        const bool same_row = row[i] == row[j];
        const bool vertical_neighbours =
            !same_row && std::abs(row[i] - row[j]) <= params.vertical_ring_span &&
            std::abs(col[i] - col[j]) <= params.vertical_column_extension;
        const double t_h = params.horizontal_merge_dist, t_v = params.vertical_merge_dist;
        const double depth_jump = std::fabs(range(i) - range(j));
        // R dtheta of the range-scaled rule, R the upper point's range.
        const double forced =
            range(row[j] > row[i] ? j : i) * pipeline.clustering().ringSpacing(row[i], row[j]);
        const bool occlusion = same_row && depth_jump < t_h && d2 < sq(params.occlusion_max_gap);
        const bool seam = same_row && d2 < sq(params.seam_max_shift) && nearSeam(i) && nearSeam(j);
        switch (p.rule) {
            case eval::LinkRule::Horizontal:
                EXPECT_TRUE(same_row);
                EXPECT_LT(d2, sq(t_h) + 1e-6);
                break;
            case eval::LinkRule::Vertical:
                EXPECT_TRUE(vertical_neighbours);
                EXPECT_LT(d2, sq(t_v) + 1e-6);
                break;
            case eval::LinkRule::RangeScaledVertical:
                EXPECT_TRUE(vertical_neighbours);
                EXPECT_GT(forced, 0.0);
                EXPECT_LT(d2 - sq(forced), sq(t_v) + 1e-4);
                break;
            case eval::LinkRule::Occlusion:
                EXPECT_TRUE(occlusion);
                break;
            case eval::LinkRule::Seam:
                EXPECT_TRUE(seam);
                break;
            case eval::LinkRule::Indirect:
                // The closest pair: no rule joins it directly. Nothing to check when it is
                // neither on one ring nor within the vertical update's window.
                if (!same_row && !vertical_neighbours) continue;
                if (same_row) {
                    EXPECT_GE(d2, sq(t_h) - 1e-6);
                    EXPECT_FALSE(occlusion);
                    EXPECT_FALSE(seam);
                } else {
                    EXPECT_GE(d2, sq(t_v) - 1e-6);
                    EXPECT_GE(d2 - sq(forced), sq(t_v) - 1e-4);
                }
                break;
        }
        EXPECT_EQ(p.ring_spacing, pipeline.clustering().ringSpacing(row[i], row[j]));
        ++checked;
    }
    return checked;
}

}  // namespace travel::test
