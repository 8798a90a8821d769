// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The 2-D traversability grid of CTraversabilityMap, free of MRPT (Eigen/std only). Each frame
// adds classified world points, then endFrame() fuses that frame's per-cell summary into the
// cells: one log-odds update per cell and frame (not per point, so dense near-range cells do
// not outvote far ones), ground height statistics, slope from the TRAVEL terrain model and the
// step height seen inside the cell.
//
// It takes the two parts of the map section that concern it (travel/Config.hpp declares every
// key once): GridGeometry (extent, cell size) and GridFusionParams (fusion rules); a
// travel::MapSection is both.
//
//   grid.reset(geometry);
//   per frame: grid.beginFrame(); grid.addGround(x, y, z, slope_deg) ...;
//              grid.addObstacle(x, y) ...; grid.endFrame(time_s, fusion);
//   grid.state(ix, iy, fusion)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "travel/Config.hpp"

namespace travel {

enum class CellState : uint8_t {
    Unknown = 0,      ///< never observed, or evidence below both thresholds
    Traversable = 1,  ///< ground, flat enough, no step
    Obstacle = 2,     ///< obstacle points, or ground too steep / with a step
};

const char* toString(CellState state);

/// The grid's cells, one array per field (index = iy * sizeX + ix).
class TraversabilityGrid {
  public:
    void reset(const GridGeometry& geometry);
    /// Forgets the contents, keeps the geometry.
    void clear();

    const GridGeometry& geometry() const { return geometry_; }
    int sizeX() const { return size_x_; }
    int sizeY() const { return size_y_; }
    std::size_t cellCount() const { return logodds_.size(); }
    /// Cell index of world (x, y), or -1 outside the grid.
    long cellIndex(double x, double y) const;
    long cellIndex(int ix, int iy) const { return long(iy) * size_x_ + ix; }
    double cellCenterX(int ix) const { return geometry_.min_x + (ix + 0.5) * geometry_.resolution; }
    double cellCenterY(int iy) const { return geometry_.min_y + (iy + 0.5) * geometry_.resolution; }

    // ---- One frame ----
    void beginFrame();
    /// A ground point (world frame) with the slope of its terrain-model node [deg].
    void addGround(double x, double y, float z, float slope_deg);
    /// An obstacle point (world frame) between the obstacle height limits.
    void addObstacle(double x, double y);
    /// Fuses the frame's cells. Returns the number of cells updated. With max_neighbour_step > 0
    /// the frame's ground heights are corrected first by a plane (offset and tilt) fitted, with
    /// shrinking inlier gates, to their differences from the fused ground over the cells both
    /// hold (>= 50 cells with >= 2 points each): an attitude or height error of the frame.
    std::size_t endFrame(double time_s, const GridFusionParams& fusion);

    // ---- Reading ----
    CellState state(long cell, const GridFusionParams& fusion) const;
    bool observed(long cell) const { return frames_seen_[static_cast<std::size_t>(cell)] > 0; }
    bool empty() const { return observed_cells_ == 0; }
    std::size_t observedCells() const { return observed_cells_; }
    float logodds(long cell) const { return logodds_[static_cast<std::size_t>(cell)]; }
    /// Mean ground height [m] (NaN when no ground point fell in the cell).
    float groundHeight(long cell) const;
    /// Mean ground height of the cells holding ground [m] (NaN when none does).
    double meanGroundHeight() const;
    /// Number of cells in each state, indexed by CellState.
    std::array<std::size_t, 3> stateCounts(const GridFusionParams& fusion) const;
    /// During a frame (before endFrame): the fused ground height, else this frame's mean ground
    /// height in the cell so far, else NaN.
    float groundHeightThisFrame(long cell) const;
    /// Standard deviation of the ground heights [m] (0 with fewer than 2 points).
    float groundSpread(long cell) const;
    /// Mean terrain-model slope of the cell's ground points [deg] (NaN if none).
    float slopeDeg(long cell) const;
    /// Largest step seen inside the cell in one frame [m] (0 if never measured).
    float stepHeight(long cell) const { return step_height_[static_cast<std::size_t>(cell)]; }
    /// Largest step [m] on the cell's edges from the ground heights fused over all frames,
    /// against the "reference" cells within 2 cells (>= 2 ground points, log-odds below
    /// free_threshold): |height difference| between this cell (if a reference) and a
    /// 4-neighbour reference; and between two references on opposite sides of this cell (along
    /// an axis or a diagonal, at most 4 cells apart) when this cell has no ground or its height
    /// lies in the middle half between theirs (it holds both levels). Each minus the rise the
    /// terrain explains over the pair's distance: the steepest height gradient measured just
    /// outside the pair (1 and 2 cells beyond each end, along the pair), capped at
    /// max_traversable_slope_deg,
    /// else the pair's mean terrain-model slope; so a ramp, its foot and its top are not steps,
    /// while beside a kerb the outer cells are flat (the terrain-model slope is not used there:
    /// TRAVEL nodes straddling a kerb fit planes tilted ~10 degrees). With max_neighbour_step > 0
    /// each frame's ground is first levelled against the fused ground (see endFrame()).
    float neighbourStep(long cell, const GridFusionParams& fusion) const;
    /// Time of the last frame that updated the cell [s, MRPT clock] (0 = never).
    double lastSeen(long cell) const { return last_seen_[static_cast<std::size_t>(cell)]; }

    // ---- Storage (for serialization): every per-cell array, in a fixed order ----
    struct Arrays {
        std::vector<float>* floats[6];
        std::vector<uint32_t>* counts[2];
        std::vector<double>* doubles[1];
    };
    Arrays arrays();
    /// Recomputes derived counters after the arrays were filled; throws std::runtime_error if
    /// their sizes do not match the geometry.
    void arraysLoaded();

  private:
    GridGeometry geometry_;
    int size_x_ = 0, size_y_ = 0;
    std::size_t observed_cells_ = 0;

    // Fused state per cell.
    std::vector<float> logodds_;
    std::vector<uint32_t> ground_count_;          ///< ground points ever added
    std::vector<float> ground_mean_, ground_m2_;  ///< Welford running mean / sum of squares
    std::vector<float> slope_sum_;
    std::vector<float> step_height_;
    std::vector<uint32_t> frames_seen_;
    std::vector<double> last_seen_;
    std::vector<float> obstacle_frames_;  ///< frames in which the cell had obstacle points

    // Per-frame scratch, reused: touched cells and their summaries.
    struct FrameCell {
        uint32_t ground = 0, obstacle = 0;
        float z_mean = 0, z_m2 = 0, slope_sum = 0;  ///< the frame's ground (Welford)
        float z_low[2], z_high[2];                  ///< two lowest / highest ground z (robust step)
    };
    std::vector<int32_t> frame_slot_;  ///< per cell: index into frame_cells_, or -1
    std::vector<long> frame_touched_;
    std::vector<FrameCell> frame_cells_;
    FrameCell& frameCell(long cell);
    /// Plane c0 + c1 (x - xm) + c2 (y - ym) fitted to this frame's ground heights minus the fused
    /// ones (see endFrame); false with too few common ground cells.
    bool frameHeightCorrection(float c[3], double& xm, double& ym) const;
    /// The cell's fused ground height can serve as a step reference (see neighbourStep()).
    bool stepReference(long cell, const GridFusionParams& fusion) const;
};

}  // namespace travel
