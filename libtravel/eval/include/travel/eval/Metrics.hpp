// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Ground segmentation scores against SemanticKITTI labels (semantic class = label & 0xFFFF).
// Ground classes: 40 road, 44 parking, 48 sidewalk, 49 other-ground, 60 lane-marking,
// 72 terrain. 70 vegetation, 0 unlabeled and 1 outlier are handled by the protocol:
//
//  Protocol A (Patchwork / Ground-Segmentation-Benchmark, as used by TRAVEL):
//    vegetation is ground when its z < -0.75 * sensor_height (z in the sensor frame, as read
//    from the .bin) and non-ground otherwise; 0/1 points predicted ground are true positives,
//    0/1 points predicted non-ground are not scored.
//  Protocol B (Patchwork++): 0, 1 and 70 are not scored at all.
//
// Predicted ground is PointClass::Ground only; NonGround, Outlier and Invalid (including
// points dropped by pre-processing) are predicted non-ground.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "travel/PointCloud.hpp"

namespace travel {

/// SemanticKITTI ground classes: 40 road, 44 parking, 48 sidewalk, 49 other-ground,
/// 60 lane-marking, 72 terrain (semantic = label & 0xFFFF).
inline bool isSemanticKittiGround(uint32_t semantic) {
    switch (semantic) {
        case 40:
        case 44:
        case 48:
        case 49:
        case 60:
        case 72:
            return true;
        default:
            return false;
    }
}

enum class GroundProtocol { A, B };

/// "A (Patchwork benchmark)" or "B (Patchwork++)".
const char* protocolName(GroundProtocol protocol);

/// Ground is the positive class.
struct ConfusionCounts {
    uint64_t tp = 0, fp = 0, tn = 0, fn = 0;

    ConfusionCounts& operator+=(const ConfusionCounts& o) {
        tp += o.tp, fp += o.fp, tn += o.tn, fn += o.fn;
        return *this;
    }
};

/// Scores in percent, [0, 100], never NaN. When a denominator is zero:
///  - precision, tp + fp = 0 (nothing predicted ground): 100 if fn = 0 (nothing to find and
///    nothing claimed), else 0 (ground was missed entirely);
///  - recall, tp + fn = 0 (no ground in the truth): 100 if fp = 0, else 0 (ground was claimed
///    where there is none);
///  - f1 = 2 P R / (P + R), and 0 when P + R = 0;
///  - accuracy = (tp + tn) / (tp + fp + tn + fn), and 100 when nothing was scored.
/// So a frame without any scored point scores 100 everywhere, and a frame without ground
/// scores 100 only if no point was predicted ground.
struct GroundScores {
    double precision = 0, recall = 0, f1 = 0, accuracy = 0;
    uint64_t points = 0;  ///< the points scored (tp + fp + tn + fn); 0: nothing to score
};

/// Counts per point: pred[i] against the SemanticKITTI label gt_labels[i], z[i] being the point's
/// height in the sensor frame (only used by protocol A; for protocol B `z` may be empty).
/// Throws std::invalid_argument if the sizes differ.
ConfusionCounts countGround(const std::vector<PointClass>& pred,
                            const std::vector<uint32_t>& gt_labels, const std::vector<float>& z,
                            double sensor_height, GroundProtocol protocol);

GroundScores scoresFrom(const ConfusionCounts& counts);

/// Mean and population standard deviation (divides by n, not n - 1) of per-frame values.
/// n = 0 gives mean = std = 0.
struct MeanStd {
    double mean = 0, std = 0;
    std::size_t n = 0;
};
MeanStd meanStd(const std::vector<double>& values);

/// Median (the mean of the two middle values for an even count); 0 for no values.
double median(std::vector<double> values);

}  // namespace travel
