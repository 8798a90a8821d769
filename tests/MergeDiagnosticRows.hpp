// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-eval merges' diagnosis (eval::mergedParts) names the linkage rules of TRAVEL's object
// stage, so it must read the rows that stage linked on: each linking pair's rows are the
// pipeline's range-image rows (Pipeline::rangeImage(), built on the pipeline's own validity
// mask) and its ring spacing the clustering's (RunClustering::ringSpacing(), from the rows'
// mean elevations over the clustered points). A range image rebuilt beside the pipeline, or
// rows' elevations averaged over other points, would put points in other rows and scale the
// range-scaled vertical rule otherwise: another diagnosis.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <vector>

#include "travel/Pipeline.hpp"
#include "travel/eval/MergeDiagnostics.hpp"

namespace travel::test {

/// Checks every part's linking pair against `pipeline` (which processed the parts' cloud
/// last); returns how many pairs were checked (parts with no pair within T_ring rows have
/// none).
inline std::size_t expectPartsOnTheClusteringRows(const std::vector<eval::MergedPart>& parts,
                                                  const Pipeline& pipeline) {
    const std::vector<int16_t>& row = pipeline.rangeImage().row();
    const RunClustering& clustering = pipeline.clustering();
    std::size_t checked = 0;
    for (const eval::MergedPart& p : parts) {
        if (p.part_row < 0) continue;
        EXPECT_EQ(p.part_row, row[p.part_point]) << "point " << p.part_point;
        EXPECT_EQ(p.rest_row, row[p.rest_point]) << "point " << p.rest_point;
        EXPECT_EQ(p.row_gap, std::abs(p.part_row - p.rest_row));
        EXPECT_EQ(p.ring_spacing, clustering.ringSpacing(p.part_row, p.rest_row))
            << "rows " << p.part_row << ", " << p.rest_row;
        ++checked;
    }
    return checked;
}

}  // namespace travel::test
