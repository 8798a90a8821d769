// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Unit tests of the building blocks: tri-grid geometry, pre-processing, the edge test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "travel/Errors.hpp"
#include "travel/Pipeline.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/Text.hpp"
#include "travel/TraversableGraphSearch.hpp"
#include "travel/TriGridField.hpp"

namespace travel {
namespace {

Params smallGrid() {
    Params p;
    p.tgf_resolution = 4.0;
    p.max_range = 20.0;  // 10 x 10 cells
    return p;
}

TEST(TriGridField, InteriorNodesHaveFourteenMutualNeighbours) {
    TriGridField field;
    field.configure(smallGrid());
    ASSERT_EQ(field.cellsPerSide(), 10);
    const int n = field.cellsPerSide();
    for (int node = 0; node < field.numNodes(); ++node) {
        const int ix = (node / 4) % n, iy = (node / 4) / n;
        const auto& nb = field.neighbours(node);
        if (ix > 0 && iy > 0 && ix < n - 1 && iy < n - 1) {
            EXPECT_EQ(nb.count, 14) << node;
        }
        std::set<int> unique(nb.ids.begin(), nb.ids.begin() + nb.count);
        EXPECT_EQ(unique.size(), static_cast<std::size_t>(nb.count));
        for (int k = 0; k < nb.count; ++k) {
            // Symmetric relation (the reference's table misses one direction of one pair).
            const auto& back = field.neighbours(nb.ids[k]);
            EXPECT_NE(std::find(back.ids.begin(), back.ids.begin() + back.count, node),
                      back.ids.begin() + back.count);
        }
    }
}

TEST(TriGridField, PointsGoToTheTriangleThatContainsThem) {
    TriGridField field;
    field.configure(smallGrid());
    // The sensor cell spans [0, 4) x [0, 4) (origin -20, r = 4); centre (2, 2).
    const int cell = field.nodeOf(2.f, 2.f) / 4;
    EXPECT_EQ(field.nodeOf(3.5f, 2.1f), 4 * cell + 0);  // east
    EXPECT_EQ(field.nodeOf(2.1f, 3.5f), 4 * cell + 1);  // north
    EXPECT_EQ(field.nodeOf(0.5f, 1.9f), 4 * cell + 2);  // west
    EXPECT_EQ(field.nodeOf(1.9f, 0.5f), 4 * cell + 3);  // south
    EXPECT_EQ(field.nodeOf(25.f, 0.f), -1);
    EXPECT_EQ(field.nodeOf(std::nanf(""), 0.f), -1);
    // Each triangle's corners: the cell centre and two corners of its own side.
    for (int k = 0; k < 4; ++k) {
        float x, y;
        field.vertexXY(field.vertexId(4 * cell + k, 0), x, y);
        EXPECT_FLOAT_EQ(x, 2.f);
        EXPECT_FLOAT_EQ(y, 2.f);
    }
    float x1, y1, x2, y2;
    field.vertexXY(field.vertexId(4 * cell + 0, 1), x1, y1);
    field.vertexXY(field.vertexId(4 * cell + 0, 2), x2, y2);
    EXPECT_FLOAT_EQ(x1, 4.f);
    EXPECT_FLOAT_EQ(x2, 4.f);
    EXPECT_FLOAT_EQ(std::fabs(y1 - y2), 4.f);
}

TEST(TriGridField, EmbeddingAgreesWithNodeOfUpToTheGridEdge) {
    // Points in the outermost half-cell must land in the same triangle as nodeOf() says.
    const Params p = smallGrid();  // grid [-20, 20)
    TriGridField field;
    field.configure(p);
    // All within the 20 m range window (3-D, z = -1), in the outer half-cells and corners.
    const float probes[][2] = {{19.f, 0.5f},  {19.8f, -1.f}, {0.5f, 19.f},   {-1.f, 19.8f},
                               {14.f, 13.9f}, {-19.8f, 0.f}, {2.5f, -19.6f}, {10.f, 10.f}};
    for (const auto& xy : probes) {
        PointCloud cloud;
        cloud.push_back(xy[0], xy[1], -1.f);
        // The node found by embed() itself and the one preprocess() finds for it.
        for (const bool nodes_in_preprocess : {false, true}) {
            AlignedCloud aligned;
            preprocess(cloud, p, {}, aligned, nodes_in_preprocess ? &field.geometry() : nullptr);
            ASSERT_EQ(aligned.node.size(), nodes_in_preprocess ? 1u : 0u);
            if (nodes_in_preprocess) {
                EXPECT_EQ(static_cast<int>(aligned.node[0]), field.nodeOf(xy[0], xy[1]));
            }
            TerrainModel model;
            field.embed(aligned, model);
            int embedded = -1;
            for (int k = 0; k < field.numNodes(); ++k)
                if (model.nodes[k].count == 1) embedded = k;
            EXPECT_EQ(embedded, field.nodeOf(xy[0], xy[1])) << xy[0] << ", " << xy[1];
        }
    }
}

TEST(TriGridField, ValidPointsOnTheRangeEdgeAreInTheEdgeNodes) {
    // A point at exactly +-max_range is valid, so it must be in a node (design.md: every valid
    // point is in a node): where max_range / tgf_resolution is whole (the grid's edge is the
    // range window's), also when 1 / r is inexact in float (r = 7: the edge's grid coordinate
    // rounds above 24), and when float(r) * cells falls short of max_range (r = 0.9, R = 81).
    for (const auto& [r, range] :
         {std::pair{4.0, 20.0}, {7.0, 84.0}, {3.5, 70.0}, {0.9, 81.0}, {2.1, 63.0}, {8.0, 80.0}}) {
        Params p;
        p.tgf_resolution = r;
        p.max_range = range;
        TriGridField field;
        field.configure(p);
        const float R = static_cast<float>(range);
        const float probes[][2] = {{R, 0.f}, {0.f, R}, {-R, 0.f}, {0.f, -R}};
        for (const auto& xy : probes) {
            PointCloud cloud;
            cloud.push_back(xy[0], xy[1], 0.f);
            const int expected = field.nodeOf(xy[0], xy[1]);
            EXPECT_GE(expected, 0) << "r " << r << ", point " << xy[0] << ", " << xy[1];
            for (const bool nodes_in_preprocess : {false, true}) {
                AlignedCloud aligned;
                preprocess(cloud, p, {}, aligned,
                           nodes_in_preprocess ? &field.geometry() : nullptr);
                ASSERT_EQ(aligned.num_valid, 1u);
                if (nodes_in_preprocess) {
                    EXPECT_EQ(static_cast<int>(aligned.node[0]), expected);
                }
                TerrainModel model;
                field.embed(aligned, model);
                int embedded = -1;
                for (int k = 0; k < field.numNodes(); ++k)
                    if (model.nodes[k].count == 1) embedded = k;
                EXPECT_EQ(embedded, expected) << "r " << r << ", point " << xy[0] << ", " << xy[1];
            }
        }
        // Beyond the edge (half a cell past it) is outside.
        EXPECT_EQ(field.nodeOf(-field.originXY() + 0.5f * static_cast<float>(r), 0.f), -1) << r;
    }
}

TEST(TriGridField, HugeAndNonFiniteCoordinatesAreOutside) {
    TriGridField field;
    field.configure(smallGrid());
    EXPECT_EQ(field.nodeOf(1e30f, 0.f), -1);
    EXPECT_EQ(field.nodeOf(0.f, -1e30f), -1);
    EXPECT_EQ(field.nodeOf(std::numeric_limits<float>::infinity(), 0.f), -1);
    EXPECT_EQ(field.nodeOf(0.f, std::nanf("")), -1);
}

TEST(Preprocessing, DeskewWithAbsurdTimesMakesPointsInvalidNotWild) {
    // Absolute timestamps mistaken for relative ones move points by kilometres: they must be
    // invalid afterwards, and the pipeline must not fail.
    PointCloud cloud;
    for (int k = 0; k < 100; ++k) {
        cloud.push_back(5.f + 0.1f * k, 0.f, -1.7f);
        cloud.time.push_back(k < 50 ? 0.001f * k : 1.0e9f);
    }
    FrameInput input;
    input.linear_velocity = Eigen::Vector3d(10, 0, 0);
    input.angular_velocity = Eigen::Vector3d(0, 0, 0.5);
    AlignedCloud out;
    preprocess(cloud, Params{}, input, out);
    EXPECT_EQ(out.num_valid, 50u);
    for (int k = 50; k < 100; ++k) EXPECT_EQ(out.valid[k], 0) << k;
    Pipeline pipeline(Params{});
    Result result;
    pipeline.process(cloud, input, result);
    EXPECT_EQ(result.count(PointClass::Invalid), 50u);
}

TEST(Pipeline, MismatchedFieldSizesAreAnError) {
    PointCloud cloud;
    cloud.push_back(1, 2, 3);
    cloud.y.push_back(4);  // y longer than x
    Pipeline pipeline(Params{});
    Result result;
    EXPECT_THROW(pipeline.process(cloud, {}, result), std::invalid_argument);
}

TEST(Preprocessing, InvalidPointsAreFlagged) {
    Params p;
    p.min_range = 1.0;
    p.max_range = 50.0;
    PointCloud cloud;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    cloud.push_back(10, 0, -1);    // valid
    cloud.push_back(nan, 0, 0);    // NaN
    cloud.push_back(0, inf, 0);    // inf
    cloud.push_back(0, 0, 0);      // no return
    cloud.push_back(0.5f, 0, 0);   // too close
    cloud.push_back(60, 0, 0);     // too far
    cloud.push_back(1e30f, 0, 0);  // overflows to inf when squared
    AlignedCloud out;
    preprocess(cloud, p, {}, out);
    EXPECT_EQ(out.num_valid, 1u);
    EXPECT_EQ(out.valid, (std::vector<uint8_t>{1, 0, 0, 0, 0, 0, 0}));
}

TEST(Preprocessing, AttitudeAlignmentLevelsATiltedSensor) {
    // A sensor rolled by 10 deg sees flat ground 1.5 m below as a tilted plane; with the
    // attitude the aligned points are level again.
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(10 * M_PI / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
    PointCloud cloud;
    for (int i = 1; i <= 10; ++i) {
        const Eigen::Vector3d world(2.0 * i, 1.0 * i - 5, -1.5);
        const Eigen::Vector3d sensor = tilt.transpose() * world;
        cloud.push_back(sensor.x(), sensor.y(), sensor.z());
    }
    FrameInput input;
    input.vehicle_attitude = tilt;
    AlignedCloud out;
    preprocess(cloud, Params{}, input, out);
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_NEAR(out.z[i], -1.5, 1e-4);
    // Yaw of the attitude is ignored: the grid stays in the vehicle frame.
    input.vehicle_attitude =
        Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix() * tilt;
    preprocess(cloud, Params{}, input, out);
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_NEAR(out.z[i], -1.5, 1e-4);
    EXPECT_NEAR(out.x[0], 2.0, 1e-4);
    // An attitude that is no rotation is not used (NaN coordinates kept valid, or every point
    // at the origin, before): the points are as without one, and a valid gravity still levels.
    AlignedCloud plain;
    preprocess(cloud, Params{}, FrameInput{}, plain);
    const Eigen::Matrix3d nan_matrix = Eigen::Matrix3d::Constant(std::nan(""));
    const Eigen::Matrix3d reflection = Eigen::Vector3d(1, 1, -1).asDiagonal();
    for (const Eigen::Matrix3d& bad : {nan_matrix, Eigen::Matrix3d::Zero().eval(), reflection}) {
        input.vehicle_attitude = bad;
        input.gravity_in_sensor.reset();
        preprocess(cloud, Params{}, input, out);
        EXPECT_EQ(out.num_valid, cloud.size());
        for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(out.z[i], plain.z[i]);
        input.gravity_in_sensor = tilt.transpose() * Eigen::Vector3d(0, 0, -9.81);
        preprocess(cloud, Params{}, input, out);
        for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_NEAR(out.z[i], -1.5, 1e-4);
    }
    // Gravity of any finite length levels alike, also where its squared length overflows (it was
    // turned upside down) or underflows (it was ignored).
    input.vehicle_attitude.reset();
    for (const double length : {1e-200, 1e200, 1e308}) {
        input.gravity_in_sensor = tilt.transpose() * Eigen::Vector3d(0, 0, -length);
        EXPECT_TRUE(isUsableGravity(*input.gravity_in_sensor)) << length;
        preprocess(cloud, Params{}, input, out);
        for (std::size_t i = 0; i < cloud.size(); ++i)
            EXPECT_NEAR(out.z[i], -1.5, 1e-4) << "length " << length;
    }
}

TEST(Preprocessing, DeskewUndoesConstantVelocityMotion) {
    // The sensor moves at 10 m/s along x and yaws at 1 rad/s; a static point is observed at
    // time t in the sensor frame of time t. Deskew to t = 0 must recover its position.
    const Eigen::Vector3d v(10, 0, 0), w(0, 0, 1);
    const Eigen::Vector3d world(20, 5, -1.7);
    PointCloud cloud;
    for (int k = 0; k < 10; ++k) {
        const double t = 0.01 * k;
        const Eigen::Matrix3d R =
            Eigen::AngleAxisd(w.norm() * t, w.normalized()).toRotationMatrix();
        const Eigen::Vector3d seen = R.transpose() * (world - v * t);  // pose at t: (R, v t)
        cloud.push_back(seen.x(), seen.y(), seen.z());
        cloud.time.push_back(static_cast<float>(t));
    }
    FrameInput input;
    input.linear_velocity = v;
    input.angular_velocity = w;
    AlignedCloud out;
    preprocess(cloud, Params{}, input, out);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        EXPECT_NEAR(out.x[i], world.x(), 0.02);
        EXPECT_NEAR(out.y[i], world.y(), 0.02);
    }
    Params off;
    off.deskew = false;
    preprocess(cloud, off, input, out);
    EXPECT_GT(std::fabs(out.x[9] - world.x()), 0.5);
}

TriNode planeNode(Eigen::Vector3f mean, Eigen::Vector3f normal) {
    TriNode n;
    n.mean = mean;
    n.normal = normal.normalized();
    n.d = -n.normal.dot(n.mean);
    n.node_class = NodeClass::Terrain;
    return n;
}

TEST(GraphSearch, EdgeTestAcceptsFlatRejectsKerbAndIsSymmetric) {
    const Params p;
    const Eigen::Vector3f up(0, 0, 1);
    const TriNode a = planeNode({0, 0, -1.7f}, up);
    const TriNode flat = planeNode({4, 0, -1.7f}, up);
    const TriNode kerb = planeNode({4, 0, -1.55f}, up);             // 15 cm higher, 4 m away
    const TriNode tilted = planeNode({4, 0, -1.7f}, {0.5f, 0, 1});  // normals 27 deg apart
    EXPECT_TRUE(isTraversableEdge(a, flat, p));
    EXPECT_FALSE(isTraversableEdge(a, kerb, p));
    EXPECT_FALSE(isTraversableEdge(kerb, a, p));
    EXPECT_EQ(isTraversableEdge(a, tilted, p), isTraversableEdge(tilted, a, p));
}

TEST(Params, ValidateRejectsOutOfRangeAndHugeGrids) {
    Params p;
    p.tgf_resolution = -1;
    EXPECT_THROW(p.validate(), ConfigError);
    p = Params{};
    p.min_range = 100, p.max_range = 50;
    EXPECT_THROW(p.validate(), ConfigError);
    p = Params{};
    p.max_range = 2000, p.tgf_resolution = 0.25;  // 16000 cells per side
    EXPECT_THROW(Pipeline{p}, ConfigError);
}

}  // namespace
}  // namespace travel

// Binary bytes given where text is expected are named by where they start; UTF-8 is text.
TEST(Text, NotTextReasonNamesTheFirstByteThatIsNoText) {
    using travel::notTextReason;
    EXPECT_EQ(notTextReason(""), "");
    EXPECT_EQ(notTextReason("key: 1.5\r\n\tother = x # \xC3\xA9 \xE2\x9C\x93 \xF0\x9F\x9A\x97\n"),
              "");
    EXPECT_EQ(notTextReason(std::string("ab\0c", 4)), "byte 0x00 at offset 2");
    EXPECT_EQ(notTextReason("a\x1B[0m"), "byte 0x1B at offset 1");
    EXPECT_EQ(notTextReason("ab\x7F"), "byte 0x7F at offset 2");
    EXPECT_EQ(notTextReason("\xFF"), "byte 0xFF at offset 0");          // never in UTF-8
    EXPECT_EQ(notTextReason("x\xC3"), "byte 0xC3 at offset 1");         // truncated
    EXPECT_EQ(notTextReason("\xC0\x80"), "byte 0xC0 at offset 0");      // overlong NUL
    EXPECT_EQ(notTextReason("\xED\xA0\x80"), "byte 0xED at offset 0");  // a surrogate
    EXPECT_EQ(notTextReason("\xA9"), "byte 0xA9 at offset 0");          // stray continuation
}

// A message echoing user input stays one readable line: control and non-UTF-8 bytes escaped,
// long input cut with its size.
TEST(Text, QuotedExcerptEscapesAndCuts) {
    using travel::quotedExcerpt;
    EXPECT_EQ(travel::printableText("a\x1B[2J\tb\xC3\xA9\xFF"), "a\\x1B[2J\\x09b\xC3\xA9\\xFF");
    EXPECT_EQ(travel::printableText("\xC2\x9B"
                                    "2J \xC2\xA0"),
              "\\xC2\\x9B2J \xC2\xA0");  // C1 CSI
    EXPECT_EQ(quotedExcerpt("abc"), "'abc'");
    EXPECT_EQ(quotedExcerpt("caf\xC3\xA9"), "'caf\xC3\xA9'");
    EXPECT_EQ(quotedExcerpt(std::string("a\0\n\xFF", 4)), "'a\\x00\\x0A\\xFF'");
    EXPECT_EQ(quotedExcerpt(std::string(5000, '9'), 10), "'9999999999'... (5000 bytes)");
    EXPECT_EQ(quotedExcerpt("\xC3\xA9\xC3\xA9\xC3\xA9", 2), "'\xC3\xA9\xC3\xA9'... (6 bytes)");
}

TEST(Text, SplitListKeepsEmptyItems) {
    using V = std::vector<std::string>;
    EXPECT_EQ(travel::splitList("", ','), V{});
    EXPECT_EQ(travel::splitList("a", ','), V{"a"});
    EXPECT_EQ(travel::splitList("a,b,c", ','), (V{"a", "b", "c"}));
    EXPECT_EQ(travel::splitList("a,,b", ','), (V{"a", "", "b"}));
    EXPECT_EQ(travel::splitList("a,b,", ','), (V{"a", "b", ""}));
    EXPECT_EQ(travel::splitList(",", ','), (V{"", ""}));
}
