// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/FrameEvaluation.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>

#include "travel/eval/KittiIO.hpp"

namespace travel::eval {

void evaluateFrame(const std::string& scan_path, const std::string& label_path,
                   Segmenter& segmenter, FrameEvaluation& frame, ScanFormat format) {
    const PointCloud& cloud = frame.cloud;
    const Segmentation& out = frame.segmentation;
    try {
        readScan(scan_path, frame.cloud, format);
        segmenter.segment(cloud, frame.segmentation);
        frame.class_counts = {};
        for (const PointClass c : out.labels) ++frame.class_counts[static_cast<int>(c) & 3];
        frame.clusters = out.cluster_id.empty()
                             ? 0
                             : *std::max_element(out.cluster_id.begin(), out.cluster_id.end());
        frame.clustered = out.objects_ms > 0 || frame.clusters > 0;
        frame.scored = !label_path.empty();
        frame.ground_truth.clear();
        frame.ground[0] = frame.ground[1] = GroundScores{};  // not the last frame's
        frame.objects = ObjectScores{};
        if (!frame.scored) return;
        frame.ground_truth = readLabelFile(label_path, cloud.size());
        // A label file of zeros (class 0, "unlabeled", everywhere) holds no ground truth: both
        // protocols would score it 100 and average that in.
        frame.scored = std::any_of(frame.ground_truth.begin(), frame.ground_truth.end(),
                                   [](uint32_t label) { return (label & 0xFFFF) != 0; });
        if (!frame.scored) return;
        for (int p = 0; p < 2; ++p)
            frame.ground[p] = scoresFrom(countGround(out.labels, frame.ground_truth, cloud.z,
                                                     out.sensor_height, kGroundProtocols[p]));
        frame.objects = evaluateObjects(out.cluster_id, out.labels, frame.ground_truth, cloud);
    } catch (const std::exception& e) {
        // Name the scan in every error (the pipeline's own messages do not know it).
        const std::string what = e.what();
        const bool named = what.find(scan_path) != std::string::npos ||
                           (!label_path.empty() && what.find(label_path) != std::string::npos);
        throw std::runtime_error(named ? what : scan_path + ": " + what);
    }
}

void EvaluationAccumulator::add(const FrameEvaluation& frame) {
    if (!frame.scored) return;
    for (int p = 0; p < 2; ++p) {
        // A frame whose labels leave nothing to score under this protocol (all unlabelled,
        // say) scores 100 by convention; it says nothing about the method: not averaged.
        if (frame.ground[p].points == 0) continue;
        ground_[p][0].push_back(frame.ground[p].precision);
        ground_[p][1].push_back(frame.ground[p].recall);
        ground_[p][2].push_back(frame.ground[p].f1);
        ground_[p][3].push_back(frame.ground[p].accuracy);
    }
    ground_ms_.push_back(frame.segmentation.ground_ms);
    if (!frame.clustered) return;
    clusters_ = true;
    objects_.add(frame.objects);
    use_.push_back(frame.objects.entropy.use_sum);
    ose_.push_back(frame.objects.entropy.ose_sum);
    objects_ms_.push_back(frame.segmentation.objects_ms);
}

EvaluationSummary EvaluationAccumulator::summary() const {
    EvaluationSummary s;
    for (int p = 0; p < 2; ++p) {
        s.precision[p] = meanStd(ground_[p][0]);
        s.recall[p] = meanStd(ground_[p][1]);
        s.f1[p] = meanStd(ground_[p][2]);
        s.accuracy[p] = meanStd(ground_[p][3]);
    }
    s.use = meanStd(use_);
    s.ose = meanStd(ose_);
    s.objects = objects_.summary();
    s.ground_ms = median(ground_ms_);
    s.objects_ms = median(objects_ms_);
    s.clusters = clusters_;
    return s;
}

}  // namespace travel::eval
