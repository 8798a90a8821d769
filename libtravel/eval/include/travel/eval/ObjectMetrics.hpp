// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Above-ground object segmentation scores against SemanticKITTI labels (semantic class =
// label & 0xFFFF, instance id = label >> 16). Predicted cluster id 0 means "no cluster".
//
// 1. Over- / under-segmentation entropy (TRAVEL paper eqs. 6-7, natural log).
//    - Object points: semantic class neither ground {40, 44, 48, 49, 60, 72} nor unlabeled /
//      outlier {0, 1}, with finite x, y, z. Every other class is an object class (things 10-32,
//      252-259 and stuff such as 50 building, 51 fence, 70 vegetation, 71 trunk, 80 pole,
//      81 traffic-sign, 99 other-object).
//    - GT objects: the object points grouped by (semantic, instance), each group split into
//      Euclidean clusters (single linkage, distance <= gt_cluster_distance, default 0.5 m), so
//      that e.g. every "building" point (instance 0) of a scene is not one object. Objects with
//      fewer than min_gt_object_points points (default 10, our minimum cluster size) are
//      ignored: their points take no part in OSE or USE. GT objects are built from all object
//      points whatever the prediction, so they are the same for every method.
//    - Scored points: the points of the kept GT objects that are predicted NonGround (with the
//      default entropy_on_predicted_nonground = true). The entropies then score the object
//      segmentation on its input, as the paper's "non-ground points"; ground errors are left to
//      the ground metrics (otherwise grass, class 70, correctly labelled ground under protocol A
//      would dominate the OSE). With false, every point of a kept GT object is scored and an
//      object point predicted ground or outlier counts as unclustered.
//    - Unclustered scored points (cluster id 0) are singleton labels in the OSE: an object with
//      k of its N points unclustered gets k (1/N) ln N from them, so dropping points costs the
//      maximum and a fully dropped object scores ln N (as one shared "unclustered" label a fully
//      dropped object would score 0, like a perfect one). Consistently, they are singleton
//      clusters in the USE, which contribute 0 and are not counted as clusters.
//    - OSE of an object of N scored points split into labels of N_i points:
//      -sum (N_i/N) ln(N_i/N). USE of a cluster of M scored points (its points outside the
//      scored set do not count) holding GT objects with M_i points: -sum (M_i/M) ln(M_i/M).
//      The frame values are the sums over objects / clusters (the paper's numbers) and the means
//      (sum / count). Objects without a scored point and clusters without a scored point are not
//      counted; a mean over zero objects / clusters is 0.
//
// 2. Instance coverage and purity (thing classes 10-32 and 252-259 with instance id != 0, grouped
//    by (semantic, instance), no Euclidean split, at least min_instance_points = 50 points, all
//    points of the instance whatever their predicted class or coordinates):
//    - best cluster: the non-zero cluster id holding most of the instance's points (ties: the
//      smaller id); 0 when no point of the instance is clustered;
//    - coverage = points in the best cluster / instance points (unclustered points count
//      against it); 0 without a clustered point;
//    - purity = points of the instance in the best cluster / all points of the best cluster (any
//      class, ground-labelled ones included, any predicted class). An instance without a clustered
//      point has purity 0, is excluded from the purity mean and from `merged` (it was not merged
//      into anything; its failure is counted by its coverage 0 and in `split`);
//    - split: coverage <= 0.5, no cluster holds a strict majority of the instance (missed
//      instances included); merged: purity <= 0.5, the instance is not a strict majority of its
//      best cluster (clustered instances only). So an instance cut in two equal halves is split,
//      and two equal instances in one cluster are both merged.
//    Means over zero instances are 0. No output is ever NaN.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "travel/PointCloud.hpp"

namespace travel {

struct ObjectEvalOptions {
    /// GT objects: single-linkage Euclidean distance [m] within one (semantic, instance) group.
    double gt_cluster_distance = 0.5;
    /// GT objects with fewer points are ignored by OSE / USE.
    std::size_t min_gt_object_points = 10;
    /// Instances with fewer points are ignored by coverage / purity.
    std::size_t min_instance_points = 50;
    /// OSE / USE score only the GT object points predicted NonGround (see the file comment).
    bool entropy_on_predicted_nonground = true;
};

/// Over- / under-segmentation entropy of one frame (natural log).
struct SegmentationEntropy {
    double ose_sum = 0, use_sum = 0;    ///< paper eqs. 6-7: sums over objects / clusters
    double ose_mean = 0, use_mean = 0;  ///< ose_sum / num_gt_objects, use_sum / num_clusters
    std::size_t num_gt_objects = 0;     ///< GT objects with at least one scored point
    std::size_t num_clusters = 0;       ///< non-zero cluster ids with at least one scored point
    std::size_t num_points = 0;         ///< scored points
};

/// Coverage and purity of one GT thing instance.
struct InstanceScore {
    uint32_t semantic = 0, instance = 0;
    std::size_t points = 0;
    double coverage = 0, purity = 0;
    uint32_t best_cluster = 0;  ///< 0 = no point of the instance is clustered
};

struct ObjectScores {
    SegmentationEntropy entropy;
    /// Instances with >= min_instance_points points, ordered by (semantic, instance).
    std::vector<InstanceScore> instances;
    double mean_coverage = 0;           ///< over all instances
    double mean_purity = 0;             ///< over the clustered instances
    std::size_t clustered = 0;          ///< instances with best_cluster != 0
    std::size_t split = 0, merged = 0;  ///< coverage <= 0.5, purity <= 0.5 (see above)
};

/// How the points of one group (a GT instance, a golden cluster) lie in the clusters of a
/// labelling: the non-zero cluster holding most of them (ties: the smaller id) and how many.
struct GroupInClusters {
    std::size_t points = 0;      ///< points of the group
    uint32_t best_cluster = 0;   ///< 0 = no point of the group is clustered
    std::size_t best_count = 0;  ///< points of the group in best_cluster
    /// No cluster holds a strict majority of the group (unclustered groups included).
    bool split() const { return 2 * best_count <= points; }
    /// A clustered group that is no strict majority of its best cluster (of `cluster_points`
    /// points). Integer tests: exactly half is "no majority" without rounding doubt.
    bool mergedInto(std::size_t cluster_points) const {
        return best_cluster != 0 && 2 * best_count <= cluster_points;
    }
};

/// The group of n points whose k-th point is in cluster cluster_of(k) (0 = none); the ids must
/// come in ascending order.
template <class ClusterOf>
GroupInClusters locateGroup(std::size_t n, ClusterOf&& cluster_of) {
    GroupInClusters g;
    g.points = n;
    for (std::size_t a = 0; a < n;) {
        std::size_t b = a;
        while (b < n && cluster_of(b) == cluster_of(a)) ++b;
        // Ascending ids and a strict '>': ties go to the smaller id.
        if (cluster_of(a) != 0 && b - a > g.best_count) {
            g.best_count = b - a;
            g.best_cluster = cluster_of(a);
        }
        a = b;
    }
    return g;
}

/// Scores one frame. All vectors are indexed like the input cloud: cluster_id[i] the predicted
/// cluster (0 = none), pred[i] the predicted class, gt_labels[i] the SemanticKITTI label, x/y/z
/// the point. Deterministic. Throws std::invalid_argument if the sizes differ or
/// gt_cluster_distance is not a positive finite number.
ObjectScores evaluateObjects(const std::vector<uint32_t>& cluster_id,
                             const std::vector<PointClass>& pred,
                             const std::vector<uint32_t>& gt_labels, const std::vector<float>& x,
                             const std::vector<float>& y, const std::vector<float>& z,
                             const ObjectEvalOptions& options = {});

inline ObjectScores evaluateObjects(const std::vector<uint32_t>& cluster_id,
                                    const std::vector<PointClass>& pred,
                                    const std::vector<uint32_t>& gt_labels, const PointCloud& cloud,
                                    const ObjectEvalOptions& options = {}) {
    return evaluateObjects(cluster_id, pred, gt_labels, cloud.x, cloud.y, cloud.z, options);
}

/// GT object id per point (1-based, ordered by the smallest point index of each object; 0 = not
/// in a kept GT object), as used by the entropies. Exposed for tests and visualisation.
std::vector<uint32_t> groundTruthObjects(const std::vector<uint32_t>& gt_labels,
                                         const std::vector<float>& x, const std::vector<float>& y,
                                         const std::vector<float>& z,
                                         const ObjectEvalOptions& options = {});

/// Scores over several frames.
///  - Entropy: *_per_frame is the mean over frames of the frame sums (the paper's reported
///    value); *_per_object / use_per_cluster pool every object / cluster of every frame
///    (total entropy / total count), so a frame with many objects weighs more.
///  - Instances: pooled over all instances of all frames (not a mean of frame means, which
///    would give a frame with 2 instances the weight of a frame with 30).
/// Zero frames, objects or instances give 0.
struct ObjectSummary {
    std::size_t frames = 0;
    double ose_per_frame = 0, use_per_frame = 0;
    double ose_per_object = 0, use_per_cluster = 0;
    std::size_t gt_objects = 0, clusters = 0;
    std::size_t instances = 0, clustered = 0, split = 0, merged = 0;
    double mean_coverage = 0, mean_purity = 0;
};

class ObjectScoreAccumulator {
  public:
    void add(const ObjectScores& frame);
    ObjectSummary summary() const;

  private:
    std::size_t frames_ = 0, gt_objects_ = 0, clusters_ = 0;
    std::size_t instances_ = 0, clustered_ = 0, split_ = 0, merged_ = 0;
    double ose_ = 0, use_ = 0, coverage_ = 0, purity_ = 0;
};

}  // namespace travel
