// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "travel/eval/Metrics.hpp"

using travel::ConfusionCounts;
using travel::countGround;
using travel::GroundProtocol;
using travel::PointClass;
using travel::scoresFrom;

namespace {

constexpr PointClass G = PointClass::Ground;
constexpr PointClass N = PointClass::NonGround;
constexpr PointClass O = PointClass::Outlier;
constexpr PointClass I = PointClass::Invalid;
constexpr double kHeight = 1.73;  // vegetation is ground below z = -1.2975

void expectCounts(const ConfusionCounts& c, uint64_t tp, uint64_t fp, uint64_t tn, uint64_t fn) {
    EXPECT_EQ(c.tp, tp);
    EXPECT_EQ(c.fp, fp);
    EXPECT_EQ(c.tn, tn);
    EXPECT_EQ(c.fn, fn);
}

}  // namespace

TEST(Metrics, ProtocolNames) {
    EXPECT_STREQ(travel::protocolName(GroundProtocol::A), "A (Patchwork benchmark)");
    EXPECT_STREQ(travel::protocolName(GroundProtocol::B), "B (Patchwork++)");
}

// One point of each situation, scored under both protocols.
TEST(Metrics, MixedFrame) {
    const std::vector<PointClass> pred = {
        G,  // road, ground                       -> TP
        N,  // terrain, missed                    -> FN
        G,  // car (10), claimed ground           -> FP
        O,  // building (50)                      -> TN
        I,  // parking dropped as invalid         -> FN
        G,  // low vegetation predicted ground    -> A: TP, B: ignored
        N,  // low vegetation missed              -> A: FN, B: ignored
        G,  // high vegetation predicted ground   -> A: FP, B: ignored
        N,  // high vegetation                    -> A: TN, B: ignored
        G,  // unlabeled predicted ground         -> A: TP, B: ignored
        N,  // outlier predicted non-ground       -> ignored in both
        G,  // lane marking with instance bits    -> TP
    };
    const std::vector<uint32_t> gt = {40, 72, 10, 50, 44, 70, 70, 70, 70, 0, 1, 60 | (3u << 16)};
    const std::vector<float> z = {-1.7f, -1.7f,  -1.f, 2.f,   -1.7f, -1.5f,
                                  -1.3f, -1.29f, 0.f,  -1.7f, -1.7f, -1.7f};

    const ConfusionCounts a = countGround(pred, gt, z, kHeight, GroundProtocol::A);
    expectCounts(a, /*tp*/ 4, /*fp*/ 2, /*tn*/ 2, /*fn*/ 3);
    const auto sa = scoresFrom(a);
    EXPECT_DOUBLE_EQ(sa.precision, 100.0 * 4 / 6);
    EXPECT_DOUBLE_EQ(sa.recall, 100.0 * 4 / 7);
    EXPECT_NEAR(sa.f1, 100.0 * 2 * 4 / (2 * 4 + 2 + 3), 1e-9);
    EXPECT_DOUBLE_EQ(sa.accuracy, 100.0 * 6 / 11);

    const ConfusionCounts b = countGround(pred, gt, z, kHeight, GroundProtocol::B);
    expectCounts(b, 2, 1, 1, 2);
    const auto sb = scoresFrom(b);
    EXPECT_DOUBLE_EQ(sb.precision, 100.0 * 2 / 3);
    EXPECT_DOUBLE_EQ(sb.recall, 50.0);
    EXPECT_NEAR(sb.f1, 100.0 * 4 / 7, 1e-9);
    EXPECT_DOUBLE_EQ(sb.accuracy, 50.0);
    // Protocol B does not need z.
    expectCounts(countGround(pred, gt, {}, kHeight, GroundProtocol::B), 2, 1, 1, 2);
}

TEST(Metrics, VegetationThresholdFollowsSensorHeight) {
    const std::vector<PointClass> pred = {G};
    const std::vector<uint32_t> gt = {70};
    // z = -0.5 is below -0.75 * 0.5 = -0.375 for a 0.5 m sensor, but not for a 1.73 m one.
    expectCounts(countGround(pred, gt, {-0.5f}, 0.5, GroundProtocol::A), 1, 0, 0, 0);
    expectCounts(countGround(pred, gt, {-0.5f}, kHeight, GroundProtocol::A), 0, 1, 0, 0);
}

TEST(Metrics, NoGroundAtAll) {
    const std::vector<uint32_t> gt = {10, 50, 51};
    const std::vector<float> z = {0.f, 0.f, 0.f};
    // Nothing claimed: perfect.
    const auto none = countGround({N, N, O}, gt, z, kHeight, GroundProtocol::A);
    expectCounts(none, 0, 0, 3, 0);
    const auto s = scoresFrom(none);
    EXPECT_EQ(s.precision, 100.0);
    EXPECT_EQ(s.recall, 100.0);
    EXPECT_EQ(s.f1, 100.0);
    EXPECT_EQ(s.accuracy, 100.0);
    // Ground claimed where there is none: zero, never NaN.
    const auto wrong = scoresFrom(countGround({G, N, N}, gt, z, kHeight, GroundProtocol::B));
    EXPECT_EQ(wrong.precision, 0.0);
    EXPECT_EQ(wrong.recall, 0.0);
    EXPECT_EQ(wrong.f1, 0.0);
    EXPECT_NEAR(wrong.accuracy, 200.0 / 3, 1e-12);
}

TEST(Metrics, EverythingGround) {
    const std::vector<uint32_t> gt = {40, 44, 48, 49, 60, 72};
    const std::vector<float> z(6, -1.7f);
    const auto all =
        scoresFrom(countGround(std::vector<PointClass>(6, G), gt, z, kHeight, GroundProtocol::A));
    EXPECT_EQ(all.precision, 100.0);
    EXPECT_EQ(all.recall, 100.0);
    EXPECT_EQ(all.f1, 100.0);
    EXPECT_EQ(all.accuracy, 100.0);
    // Nothing predicted ground although everything is: zero, never NaN.
    const auto c = countGround(std::vector<PointClass>(6, N), gt, z, kHeight, GroundProtocol::A);
    expectCounts(c, 0, 0, 0, 6);
    const auto missed = scoresFrom(c);
    EXPECT_EQ(missed.precision, 0.0);
    EXPECT_EQ(missed.recall, 0.0);
    EXPECT_EQ(missed.f1, 0.0);
    EXPECT_EQ(missed.accuracy, 0.0);
}

TEST(Metrics, UnlabeledOnly) {
    const std::vector<uint32_t> gt = {0, 1};
    const std::vector<float> z = {0.f, 0.f};
    // Protocol A credits ground predictions on 0/1, protocol B scores nothing.
    expectCounts(countGround({G, G}, gt, z, kHeight, GroundProtocol::A), 2, 0, 0, 0);
    expectCounts(countGround({N, N}, gt, z, kHeight, GroundProtocol::A), 0, 0, 0, 0);
    expectCounts(countGround({G, G}, gt, z, kHeight, GroundProtocol::B), 0, 0, 0, 0);
}

TEST(Metrics, EmptyInput) {
    const auto c = countGround({}, {}, {}, kHeight, GroundProtocol::A);
    expectCounts(c, 0, 0, 0, 0);
    const auto s = scoresFrom(c);
    EXPECT_EQ(s.precision, 100.0);
    EXPECT_EQ(s.recall, 100.0);
    EXPECT_EQ(s.f1, 100.0);
    EXPECT_EQ(s.accuracy, 100.0);
}

TEST(Metrics, SizeMismatchThrows) {
    EXPECT_THROW(countGround({G}, {40, 40}, {0.f, 0.f}, kHeight, GroundProtocol::A),
                 std::invalid_argument);
    EXPECT_THROW(countGround({G}, {40}, {}, kHeight, GroundProtocol::A), std::invalid_argument);
    EXPECT_THROW(countGround({G}, {40}, {0.f, 0.f}, kHeight, GroundProtocol::B),
                 std::invalid_argument);
}

TEST(Metrics, AccumulateCounts) {
    ConfusionCounts total;
    total += ConfusionCounts{1, 2, 3, 4};
    total += ConfusionCounts{10, 20, 30, 40};
    expectCounts(total, 11, 22, 33, 44);
}

TEST(Metrics, MeanStd) {
    const auto empty = travel::meanStd({});
    EXPECT_EQ(empty.n, 0u);
    EXPECT_EQ(empty.mean, 0.0);
    EXPECT_EQ(empty.std, 0.0);

    const auto one = travel::meanStd({42.0});
    EXPECT_EQ(one.mean, 42.0);
    EXPECT_EQ(one.std, 0.0);

    // Population std of {2, 4, 4, 4, 5, 5, 7, 9} is exactly 2 (sample std would be 2.138).
    const auto m = travel::meanStd({2, 4, 4, 4, 5, 5, 7, 9});
    EXPECT_EQ(m.n, 8u);
    EXPECT_DOUBLE_EQ(m.mean, 5.0);
    EXPECT_DOUBLE_EQ(m.std, 2.0);
}

namespace travel {
namespace {

TEST(Metrics, MedianOfOddEvenAndEmpty) {
    EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);  // mean of the two middle values
    EXPECT_DOUBLE_EQ(median({}), 0.0);
}

}  // namespace
}  // namespace travel
