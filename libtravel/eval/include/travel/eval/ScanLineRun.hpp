// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Scan Line Run (SLR) clustering: Zermas, Izzat, Papanikolopoulos, ICRA 2017, Sec. III-B.
// The non-ground points of each scan line (ring of travel::RangeImage, in column order) form
// runs: consecutive points closer than Th_run. The first and last run of a line are linked
// when their ends are closer than Th_run (the line is circular). Going down from the top line,
// every point of a run looks for its nearest non-ground point on the line above; when that is
// nearer than Th_merge, the run takes its label. Label equivalences go through a union-find.
// (Giving each run its own label and uniting it with every label it inherits yields the same
// classes as the paper's "smallest label + equivalence table".)
#pragma once

#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"

namespace travel::eval {

struct SlrOptions {
    double run_threshold = 0.5;    ///< Th_run [m] (paper: 0.5)
    double merge_threshold = 1.0;  ///< Th_merge [m] (paper: 1.0)
};

class ScanLineRun {
  public:
    explicit ScanLineRun(const SlrOptions& options = {});

    /// Clusters the NonGround points. `cloud` is the input (sensor frame, for azimuths),
    /// `aligned` its pre-processed copy (distances), `image` its range image. cluster_id gets
    /// one entry per point: 1..K by first point, 0 for other points and too small/large
    /// clusters (params.min_cluster_size, max_cluster_size).
    void cluster(const PointCloud& cloud, const AlignedCloud& aligned, const RangeImage& image,
                 const std::vector<PointClass>& labels, const Params& params,
                 std::vector<uint32_t>& cluster_id);

    const SlrOptions& options() const { return options_; }

  private:
    int find(int run);

    SlrOptions options_;
    std::vector<uint32_t> cell_begin_;  // non-ground points by (row, column): offsets
    std::vector<uint32_t> sorted_;      // ... and their input indices
    std::vector<int32_t> point_run_;    // run of each sorted point
    std::vector<int32_t> parent_;       // union-find over runs
    std::vector<float> offset_sin2_;    // sin^2 of column offsets
    std::vector<uint32_t> count_, new_id_;
};

}  // namespace travel::eval
