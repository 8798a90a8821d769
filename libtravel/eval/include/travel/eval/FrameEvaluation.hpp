// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One evaluated frame, the unit of travel-kitti and travel-eval: a KITTI scan is read,
// segmented by any method (travel::eval::Segmenter), and, given its SemanticKITTI labels, scored
// for ground under both protocols and for objects; EvaluationAccumulator aggregates the frames.
//
//   travel::eval::FrameEvaluation frame;  // buffers reused across frames
//   travel::eval::EvaluationAccumulator totals;
//   for (...) {
//       travel::eval::evaluateFrame(scan, label, *segmenter, frame);
//       totals.add(frame);
//   }
//   const travel::eval::EvaluationSummary s = totals.summary();
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"
#include "travel/eval/Metrics.hpp"
#include "travel/eval/ObjectMetrics.hpp"
#include "travel/eval/Segmenter.hpp"
#include "travel/io/ScanIO.hpp"  // ScanFormat

namespace travel::eval {

/// Both ground protocols, in the order every report prints them (index p of the arrays below).
constexpr GroundProtocol kGroundProtocols[2] = {GroundProtocol::A, GroundProtocol::B};

struct FrameEvaluation {
    PointCloud cloud;                           ///< the scan as read
    Segmentation segmentation;                  ///< the method's labels, cluster ids and times
    std::vector<uint32_t> ground_truth;         ///< SemanticKITTI labels; empty when not scored
    std::array<std::size_t, 4> class_counts{};  ///< points per PointClass
    uint32_t clusters = 0;  ///< number of clusters (ids are 1..K, so the highest id)
    /// The method has an object stage on this frame (it spent time clustering or found a
    /// cluster); ground-only methods' object scores describe no clustering and are not reported.
    bool clustered = false;
    bool scored = false;     ///< ground truth was given (a label other than 0): scores are set
    GroundScores ground[2];  ///< per kGroundProtocols
    ObjectScores objects;    ///< clusters against the ground-truth objects

    std::size_t count(PointClass c) const { return class_counts[static_cast<int>(c)]; }
};

/// Reads the scan `scan_path` (readScan() in `format`), segments it with `segmenter` and, when
/// `label_path` is not empty, reads its SemanticKITTI labels and scores ground under both protocols
/// (protocol A's vegetation rule with the height the segmenter used, Segmentation::sensor_height)
/// and objects. `frame`'s buffers are reused.
/// Every error names the scan (or the label file).
void evaluateFrame(const std::string& scan_path, const std::string& label_path,
                   Segmenter& segmenter, FrameEvaluation& frame,
                   ScanFormat format = ScanFormat::Auto);

/// Over the scored frames: mean and std of each ground score per protocol (over the frames with
/// a point to score under that protocol); over the scored
/// frames with an object stage: the per-frame entropy sums and the pooled object summary.
struct EvaluationSummary {
    MeanStd precision[2], recall[2], f1[2], accuracy[2];  ///< per kGroundProtocols
    MeanStd use, ose;                                     ///< per-frame sums (paper eqs. 6-7)
    ObjectSummary objects;
    double ground_ms = 0, objects_ms = 0;  ///< medians over the scored frames
    bool clusters = false;                 ///< any scored frame had an object stage
};

class EvaluationAccumulator {
  public:
    /// Adds a frame; unscored frames (no ground truth) are not counted.
    void add(const FrameEvaluation& frame);
    EvaluationSummary summary() const;

  private:
    std::vector<double> ground_[2][4];  // [protocol][precision, recall, f1, accuracy]
    std::vector<double> use_, ose_, ground_ms_, objects_ms_;
    ObjectScoreAccumulator objects_;
    bool clusters_ = false;
};

}  // namespace travel::eval
