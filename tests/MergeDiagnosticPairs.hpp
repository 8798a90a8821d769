// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-eval merges' diagnosis (eval::mergedParts) names, for each part of a merged cluster,
// the linkage rule of TRAVEL's object stage that can join it to the rest and the pair of points
// that satisfies it. The check here recomputes that claim from the rule's definition (Sec. IV:
// T_horz on one ring; T_vert within T_ring rows and T_ext columns, also range-scaled by the
// rows' spacing; the occlusion and seam linkages) on what the stage linked on: the pipeline's
// range-image rows and columns (built on its own validity mask), its aligned coordinates, its
// rows' spacing (RunClustering::ringSpacing()) and its parameters. A diagnosis that searched
// other rows (a range image rebuilt beside the pipeline), other coordinates or other thresholds
// would name pairs that fail here.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <vector>

#include "travel/Pipeline.hpp"
#include "travel/eval/MergeDiagnostics.hpp"

namespace travel::test {

/// Checks every part's linking pair against `pipeline` (which processed the parts' cloud
/// last) and `cluster_id` (what mergedParts was given); returns how many pairs were checked
/// (a part with no point within T_ring rows of the rest has none).
inline std::size_t expectPairsSatisfyTheirRule(const std::vector<eval::MergedPart>& parts,
                                               const std::vector<uint32_t>& cluster_id,
                                               const Pipeline& pipeline) {
    const std::vector<int16_t>& row = pipeline.rangeImage().row();
    const std::vector<int32_t>& col = pipeline.rangeImage().col();
    const AlignedCloud& a = pipeline.aligned();
    const Params& params = pipeline.params();
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
        const double t_v = params.vertical_merge_dist;
        switch (p.rule) {
            case eval::LinkRule::Horizontal:
                EXPECT_TRUE(same_row);
                EXPECT_LT(std::sqrt(d2), params.horizontal_merge_dist + 1e-6);
                break;
            case eval::LinkRule::Vertical:
                EXPECT_TRUE(vertical_neighbours);
                EXPECT_LT(std::sqrt(d2), t_v + 1e-6);
                break;
            case eval::LinkRule::RangeScaledVertical: {
                EXPECT_TRUE(vertical_neighbours);
                // R dtheta, R the upper point's range.
                const double gap = range(row[j] > row[i] ? j : i) *
                                   pipeline.clustering().ringSpacing(row[i], row[j]);
                EXPECT_GT(gap, 0.0);
                EXPECT_LT(d2 - gap * gap, t_v * t_v + 1e-4);
                break;
            }
            case eval::LinkRule::Occlusion:
                EXPECT_TRUE(same_row);
                EXPECT_LT(std::fabs(range(i) - range(j)), params.horizontal_merge_dist + 1e-6);
                EXPECT_LT(std::sqrt(d2), params.occlusion_max_gap + 1e-6);
                break;
            case eval::LinkRule::Seam:
                EXPECT_TRUE(same_row);
                EXPECT_LT(std::sqrt(d2), params.seam_max_shift + 1e-6);
                break;
            case eval::LinkRule::Indirect:  // the closest pair: no rule joins it directly
                if (same_row) {
                    EXPECT_GE(std::sqrt(d2), params.horizontal_merge_dist - 1e-6);
                }
                if (vertical_neighbours) {
                    EXPECT_GE(std::sqrt(d2), t_v - 1e-6);
                }
                break;
        }
        EXPECT_EQ(p.ring_spacing, pipeline.clustering().ringSpacing(row[i], row[j]));
        ++checked;
    }
    return checked;
}

}  // namespace travel::test
