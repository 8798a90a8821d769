// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Euclidean clustering (as in PCL's EuclideanClusterExtraction; Rusu, PhD thesis 2009,
// Sec. 6.2): the NonGround points closer than a tolerance are connected; each connected
// component is a cluster. Breadth-first search over radius queries of a nanoflann k-d tree.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"

namespace travel::eval {

struct EuclideanOptions {
    double tolerance = 0.5;  ///< [m] points nearer than this are in the same cluster
};

class EuclideanClustering {
  public:
    explicit EuclideanClustering(const EuclideanOptions& options = {});
    ~EuclideanClustering();
    EuclideanClustering(EuclideanClustering&&) noexcept;
    EuclideanClustering& operator=(EuclideanClustering&&) noexcept;

    /// Clusters the NonGround points of `aligned`. cluster_id: one entry per point, 1..K by
    /// first point, 0 for other points and too small/large clusters.
    void cluster(const AlignedCloud& aligned, const std::vector<PointClass>& labels,
                 const Params& params, std::vector<uint32_t>& cluster_id);

    const EuclideanOptions& options() const { return options_; }

  private:
    struct Tree;  // nanoflann stays out of this header
    EuclideanOptions options_;
    std::unique_ptr<Tree> tree_;
    std::vector<uint32_t> queue_, count_, new_id_;
};

}  // namespace travel::eval
