// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/Metrics.hpp"

#include <algorithm>

#include <cmath>
#include <stdexcept>
#include <string>

#include "travel/EnumNames.hpp"

namespace travel {

namespace {

constexpr uint32_t kUnlabeled = 0;
constexpr uint32_t kOutlier = 1;
constexpr uint32_t kVegetation = 70;

// 100 * num / den, or `if_empty` when den = 0.
double percent(uint64_t num, uint64_t den, double if_empty) {
    return den == 0 ? if_empty : 100.0 * static_cast<double>(num) / static_cast<double>(den);
}

constexpr EnumName<GroundProtocol> kProtocolNames[] = {
    {GroundProtocol::A, "A (Patchwork benchmark)"}, {GroundProtocol::B, "B (Patchwork++)"}};

}  // namespace

const char* protocolName(GroundProtocol protocol) {
    return nameOf(kProtocolNames, protocol);
}

ConfusionCounts countGround(const std::vector<PointClass>& pred,
                            const std::vector<uint32_t>& gt_labels, const std::vector<float>& z,
                            double sensor_height, GroundProtocol protocol) {
    const bool z_optional = protocol == GroundProtocol::B && z.empty();
    if (pred.size() != gt_labels.size() || (!z_optional && z.size() != gt_labels.size())) {
        throw std::invalid_argument("countGround: sizes differ (" + std::to_string(pred.size()) +
                                    " predictions, " + std::to_string(gt_labels.size()) +
                                    " labels, " + std::to_string(z.size()) + " z)");
    }
    const double vegetation_ground_below = -0.75 * sensor_height;

    ConfusionCounts counts;
    for (std::size_t i = 0; i < pred.size(); ++i) {
        const uint32_t semantic = gt_labels[i] & 0xFFFFu;
        const bool predicted_ground = pred[i] == PointClass::Ground;
        bool truly_ground = false;
        if (semantic == kUnlabeled || semantic == kOutlier) {
            // No truth: protocol A credits a ground prediction, otherwise not scored.
            if (protocol == GroundProtocol::A && predicted_ground) ++counts.tp;
            continue;
        } else if (semantic == kVegetation) {
            if (protocol == GroundProtocol::B) continue;
            // Low vegetation (grass) is ground under protocol A.
            truly_ground = static_cast<double>(z[i]) < vegetation_ground_below;
        } else {
            truly_ground = isSemanticKittiGround(semantic);
        }
        if (truly_ground) {
            ++(predicted_ground ? counts.tp : counts.fn);
        } else {
            ++(predicted_ground ? counts.fp : counts.tn);
        }
    }
    return counts;
}

GroundScores scoresFrom(const ConfusionCounts& c) {
    GroundScores s;
    s.precision = percent(c.tp, c.tp + c.fp, c.fn == 0 ? 100.0 : 0.0);
    s.recall = percent(c.tp, c.tp + c.fn, c.fp == 0 ? 100.0 : 0.0);
    const double pr_sum = s.precision + s.recall;
    s.f1 = pr_sum > 0 ? 2.0 * s.precision * s.recall / pr_sum : 0.0;
    s.accuracy = percent(c.tp + c.tn, c.tp + c.tn + c.fp + c.fn, 100.0);
    s.points = c.tp + c.tn + c.fp + c.fn;
    return s;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    const double upper = values[mid];
    if (values.size() % 2) return upper;
    return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + mid));
}

MeanStd meanStd(const std::vector<double>& values) {
    MeanStd result;
    result.n = values.size();
    if (values.empty()) return result;
    double sum = 0;
    for (double v : values) sum += v;
    result.mean = sum / static_cast<double>(values.size());
    // Two passes: summing squared deviations avoids the cancellation of E[x^2] - E[x]^2.
    double squared_deviations = 0;
    for (double v : values) squared_deviations += (v - result.mean) * (v - result.mean);
    result.std = std::sqrt(squared_deviations / static_cast<double>(values.size()));
    return result;
}

}  // namespace travel
