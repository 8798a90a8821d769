// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The terrain API (travel/TerrainModel.hpp): node lookup, triangle corners, the ground rule,
// height above the local ground and steps between nodes, on hand-built models with exact
// expectations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "travel/TerrainModel.hpp"

namespace travel {
namespace {

/// 4 x 4 cells of 2 m, lower-left corner (-4, -4): cell (ix, iy) spans
/// [-4 + 2 ix, -2 + 2 ix) x [-4 + 2 iy, -2 + 2 iy).
TerrainModel smallModel() {
    TerrainModel t;
    t.resolution = 2.f;
    t.cells_per_side = 4;
    t.origin_xy = -4.f;
    t.nodes.assign(static_cast<std::size_t>(t.numNodes()), TriNode{});
    return t;
}

/// Makes node k traversable terrain on the plane z = z0 + gx x (both the own and the refit
/// plane), with points spread 0.5 m in the second direction.
void makeGround(TerrainModel& t, int k, float z0, float gx = 0.f) {
    TriNode& n = t.nodes[static_cast<std::size_t>(k)];
    const Eigen::Vector3f s = Eigen::Vector3f(-gx, 0.f, 1.f).normalized();
    const auto c = t.triangleCorners(k);
    const Eigen::Vector2f m = (c[0] + c[1] + c[2]) / 3.f;
    n.node_class = NodeClass::Terrain;
    n.traversable = true;
    n.count = 10;
    n.normal = n.refit_normal = s;
    n.mean = n.refit_mean = Eigen::Vector3f(m.x(), m.y(), z0 + gx * m.x());
    n.d = n.refit_d = -s.dot(n.mean);
    n.eigenvalues = Eigen::Vector3f(1.f, 0.25f, 0.f);
}

TEST(TerrainModel, NodeAtFindsTheTriangleAndRejectsOutside) {
    const TerrainModel t = smallModel();
    // Cell (2, 2) spans [0, 2) x [0, 2), centre (1, 1), cell index 10.
    EXPECT_EQ(t.nodeAt(1.9f, 1.1f), 40 + 0);  // east
    EXPECT_EQ(t.nodeAt(1.1f, 1.9f), 40 + 1);  // north
    EXPECT_EQ(t.nodeAt(0.1f, 0.9f), 40 + 2);  // west
    EXPECT_EQ(t.nodeAt(0.9f, 0.1f), 40 + 3);  // south
    EXPECT_EQ(t.nodeAt(-4.f, -4.f), 2);       // lower-left corner, on a diagonal: east/west wins
    // The grid is closed like the range window: the upper edge is in the last cells.
    EXPECT_EQ(t.nodeAt(4.f, 1.f), 4 * (2 * 4 + 3) + 0);  // cell (3, 2), east
    EXPECT_EQ(t.nodeAt(1.f, 4.f), 4 * (3 * 4 + 2) + 1);  // cell (2, 3), north
    EXPECT_EQ(t.nodeAt(4.001f, 1.f), -1);
    EXPECT_EQ(t.nodeAt(-4.01f, 0.f), -1);
    EXPECT_EQ(t.nodeAt(std::nanf(""), 0.f), -1);
    EXPECT_EQ(t.nodeAt(0.f, 1e30f), -1);
    EXPECT_EQ(TerrainModel{}.nodeAt(0.f, 0.f), -1);  // no grid
}

TEST(TerrainModel, TriangleCornersAreTheCentreAndTheSideCorners) {
    const TerrainModel t = smallModel();
    const Eigen::Vector2f expected[4][3] = {{{1, 1}, {2, 0}, {2, 2}},
                                            {{1, 1}, {2, 2}, {0, 2}},
                                            {{1, 1}, {0, 2}, {0, 0}},
                                            {{1, 1}, {0, 0}, {2, 0}}};
    for (int tri = 0; tri < 4; ++tri) {
        const auto c = t.triangleCorners(40 + tri);
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(c[k].x(), expected[tri][k].x()) << tri << " " << k;
            EXPECT_EQ(c[k].y(), expected[tri][k].y()) << tri << " " << k;
        }
        // Every point of the triangle's interior maps back to it.
        const Eigen::Vector2f inside = (c[0] + c[1] + c[2]) / 3.f;
        EXPECT_EQ(t.nodeAt(inside.x(), inside.y()), 40 + tri);
    }
}

TEST(TerrainModel, GroundPlaneIsTheLabellingPlaneOfTraversableNodes) {
    TerrainModel t = smallModel();
    makeGround(t, 40, -1.f);
    ASSERT_TRUE(t.groundPlane(40));
    EXPECT_FLOAT_EQ(t.groundPlane(40)->heightAt(1.5f, 1.f), -1.f);
    // The refit plane, not the node's own one.
    t.nodes[40].refit_d = 1.5f;  // z = -1.5
    EXPECT_FLOAT_EQ(t.groundPlane(40)->heightAt(1.5f, 1.f), -1.5f);
    // Traversable after TTMF counts even when the node's own fit was not terrain.
    t.nodes[40].node_class = NodeClass::Unknown;
    EXPECT_TRUE(t.groundPlane(40));
    t.nodes[40].traversable = false;
    EXPECT_FALSE(t.groundPlane(40));
    EXPECT_FALSE(t.groundPlane(41));  // empty node
}

TEST(TerrainModel, HeightAboveGroundTakesTheHighestGroundAround) {
    TerrainModel t = smallModel();
    EXPECT_TRUE(std::isnan(t.heightAboveGround(1.f, 1.f, 0.f)));  // no ground anywhere
    makeGround(t, 40, -1.f);                                      // cell (2, 2): z = -1
    EXPECT_FLOAT_EQ(t.heightAboveGround(1.5f, 1.f, 0.5f), 1.5f);
    EXPECT_FLOAT_EQ(t.heightAboveGround(1.f, 1.9f, 0.5f), 1.5f);  // other triangle, same cell
    makeGround(t, 4 * 11 + 2, -0.8f);  // east neighbour cell (3, 2): z = -0.8 (higher)
    EXPECT_FLOAT_EQ(t.heightAboveGround(1.5f, 1.f, 0.5f), 1.3f);
    makeGround(t, 4 * 15 + 3, 0.f);  // diagonal cell (3, 3) does not count
    EXPECT_FLOAT_EQ(t.heightAboveGround(1.5f, 1.f, 0.5f), 1.3f);
    EXPECT_TRUE(std::isnan(t.heightAboveGround(-3.f, -3.f, 0.f)));  // cell (0, 0): none around
    EXPECT_TRUE(std::isnan(t.heightAboveGround(5.f, 0.f, 0.f)));    // outside
}

TEST(TerrainModel, StepBetweenNeighboursNeedsAllThreeMeasures) {
    TerrainModel t = smallModel();
    // East triangle of cell (2, 2) and west triangle of cell (3, 2) share the edge x = 2.
    const int a = 40, b = 4 * 11 + 2;
    makeGround(t, a, -0.8f);
    makeGround(t, b, -1.f);
    EXPECT_NEAR(t.stepBetween(a, b, 0.05f), 0.2f, 1e-6f);
    EXPECT_NEAR(t.stepBetween(b, a, 0.05f), -0.2f, 1e-6f);
    // No shared edge (cell (0, 0)), or a node whose own fit is not terrain: no step.
    makeGround(t, 0, 0.f);
    EXPECT_EQ(t.stepBetween(a, 0, 0.05f), 0.f);
    t.nodes[b].node_class = NodeClass::Obstacle;
    EXPECT_EQ(t.stepBetween(a, b, 0.05f), 0.f);
    t.nodes[b].node_class = NodeClass::Terrain;
    // Points spread less than min_spread: the plane's tilt is unknown.
    EXPECT_EQ(t.stepBetween(a, b, 0.6f), 0.f);
    // A tilted plane that is only higher at the edge (its mean is on b's plane): vetoed.
    // a's mean is at x = 5/3; its plane z = -1 + 0.4 (x - 5/3) stands 0.133 m above b's at x = 2.
    makeGround(t, a, -1.f - 0.4f * 5.f / 3.f, 0.4f);
    EXPECT_NEAR(t.stepBetween(a, b, 0.05f), 0.f, 1e-6f);
}

}  // namespace
}  // namespace travel

TEST(TerrainModel, LastGridCoordIsTheFloatBelowTheCellCount) {
    travel::TriGridGeometry g;
    for (int n : {1, 2, 3, 20, 24, 91, 160, 1024, 8000}) {
        g.cells_per_side = n;
        EXPECT_EQ(g.lastGridCoord(), std::nextafter(static_cast<float>(n), 0.f)) << n;
    }
}
