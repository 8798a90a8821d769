// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Where under-segmentation comes from: every cluster holding points of more than one
// ground-truth group, broken down into its parts, each with the linkage rule of RunClustering
// that can have joined it to the rest of the cluster (travel-eval merges).
//
// - Groups: the points of a cluster grouped by GT object (groundTruthObjects(): semantic,
//   instance, Euclidean split); points of no kept GT object (ground classes, unlabeled, tiny
//   objects) are grouped by semantic class. The largest group of a cluster is its owner; every
//   other group of at least min_part_points points is a part.
// - Linkage, inferred from the geometry of the closest point pairs between the part and the rest
//   of the cluster, on what the pipeline's object stage linked on: its range image (rows,
//   columns, sweep start: Pipeline::rangeImage()), its aligned coordinates and its rows'
//   elevations (RunClustering::ringSpacing()), in this order: horizontal (same ring, closer
//   than T_horz), vertical (rings 1..T_ring apart, columns at most T_ext apart, not across the
//   0/360-degree seam, closer than T_vert), range-scaled vertical (closer than
//   sqrt(T_vert^2 + (R dtheta)^2), R the upper point's range, dtheta one ring's spacing), occlusion
//   (same ring, closer than occlusion_max_gap, ranges within T_horz), seam (same ring, both within
//   4 columns of the sweep start, closer than seam_max_shift), else indirect (see-through, a feet
//   attachment or a chain through a third group). An estimate, not a trace of the union-find: it
//   names the loosest rule the closest pairs need.
// - For each part: the depth jump |range_part - range_rest| of its linking pair, which tells a
//   surface continued across rings (small) from an object in front of another (large).
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"

namespace travel {
class Pipeline;
}

namespace travel::eval {

enum class LinkRule : uint8_t {
    Horizontal,
    Vertical,
    RangeScaledVertical,
    Occlusion,
    Seam,
    Indirect
};
const char* toString(LinkRule rule);

/// SemanticKITTI class name of a semantic id ("car", "vegetation", ...; "class-N" if unknown).
std::string semanticName(uint32_t semantic);

struct MergedPart {
    uint32_t cluster = 0;
    uint32_t owner_semantic = 0, part_semantic = 0;
    std::size_t cluster_points = 0, owner_points = 0, part_points = 0;
    bool part_is_object = false;  ///< a kept GT object (else a class remainder, e.g. road)
    /// Owner and part have the same SemanticKITTI label (class and instance): one instance
    /// (or, instance 0, one stuff class) that the GT's Euclidean split cut in two, not a merge
    /// of two instances.
    bool same_label = false;
    float range = 0;  ///< median range of the part's points [m]
    LinkRule rule = LinkRule::Indirect;
    float link_distance = 0;  ///< 3-D distance of the linking pair [m]
    float depth_jump = 0;     ///< |range difference| of the linking pair [m]
    int row_gap = 0;          ///< rings between the linking pair's points
    /// The linking pair: input indices of its point in the part and in the rest of the
    /// cluster, and their range-image rows (Pipeline::rangeImage().row()).
    uint32_t part_point = 0, rest_point = 0;
    int part_row = -1, rest_row = -1;
    /// dtheta between the pair's rows (RunClustering::ringSpacing()) [rad]; 0 on one row or
    /// where a row has no run.
    float ring_spacing = 0;
};

/// Parts of every cluster with more than one group (see the file comment), ordered by cluster.
/// cluster_id, gt_labels and the cloud (sensor frame, as read) are indexed alike; `pipeline`
/// processed `cloud` last, with its object stage on (params.cluster_objects): the linkage is
/// read on its range image, aligned coordinates, rows' elevations and parameters in use.
/// cluster_id is usually its Result's, or any grouping of the same points. Throws
/// std::invalid_argument when the pipeline's last frame has another size or no object stage.
std::vector<MergedPart> mergedParts(const std::vector<uint32_t>& cluster_id,
                                    const std::vector<uint32_t>& gt_labels, const PointCloud& cloud,
                                    const Pipeline& pipeline, std::size_t min_part_points = 5);

/// One CSV row per part (header when `header`): frame, cluster, owner and part classes and
/// points, range, rule, link distance, depth jump, row gap.
void writeMergedPartsCsv(std::ostream& csv, const std::string& frame,
                         const std::vector<MergedPart>& parts, bool header);

/// Aggregates parts over frames by (owner class, part class, range band, rule).
class MergeTable {
  public:
    void add(const std::vector<MergedPart>& parts);
    /// Markdown tables: by rule, by class pair, and the `top` largest (pair, range, rule) rows,
    /// each with parts, part points and clusters.
    std::string markdown(std::size_t top = 40) const;

  private:
    struct Row {
        std::string key;
        std::size_t parts = 0, points = 0;
        double depth_jump = 0;  // sum, for the mean
    };
    std::vector<Row> by_rule_, by_pair_, by_all_;
    std::size_t clusters_ = 0;
    static void addTo(std::vector<Row>& rows, const std::string& key, const MergedPart& part);
};

}  // namespace travel::eval
