// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Above-ground object segmentation (AOS, paper Sec. IV): the non-ground points of each ring form
// runs (nodes); runs are linked along the ring (horizontal update, circular and skipped linkage)
// and across rings (vertical update); linked runs are one object. Merges go through a
// union-find, so no label is ever stale (the reference relabels only the two runs in hand).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "travel/Clusters.hpp"
#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"

namespace travel {

class TriGridField;
struct TerrainModel;

class RunClustering {
  public:
    /// Seam linkage: runs ending / starting within this many columns of the sweep start.
    static constexpr int kSeamColumns = 4;

    /// Stage 1 (Sec. IV-B): sort the non-ground points by (ring, column) and build the runs of
    /// every ring, with skipped linkage (a point joins the most recent of the last T_skip + 1
    /// open runs whose end lies within T_horz, or, across an occlusion, within
    /// occlusion_max_gap), circular linkage across the 0/360-degree seam, and seam linkage
    /// (seam_max_shift) across the column where the sweep started (image.sweepStartColumn()),
    /// where a moving object is seen 0.1 s apart.
    void horizontal(const AlignedCloud& cloud, const RangeImage& image,
                    const std::vector<PointClass>& labels, const Params& params);

    /// Stage 2 (Sec. IV-C): each run is compared with the runs of the T_ring rings below it
    /// whose column span, widened by T_ext, overlaps its own; they merge when two of their
    /// points in nearby columns are closer than T_vert beyond one ring's spacing at their range
    /// (sqrt(T_vert^2 + (R dtheta)^2)). Then see-through linkage (a
    /// cluster seen only through the gaps of another, within see_through_depth behind it,
    /// joins it: a car's seats and far side seen through its windows), and set-back linkage (a
    /// cluster standing on a nearer one, within its columns, at least half as wide and within
    /// set_back_depth behind it, joins it: a car's cabin seen end on over its boot or bonnet).
    void vertical(const Params& params);

    /// After vertical(), before assignIds(): each point feet[k] (left out of horizontal(), see
    /// VerticalFaces) joins the run of its face point faces[k], a clustered point, so it gets
    /// the face's cluster id and counts in its summary. Feet take no part in the run merging:
    /// two objects never link through their feet.
    void attachFeet(const AlignedCloud& cloud, const RangeImage& image,
                    const std::vector<uint32_t>& feet, const std::vector<uint32_t>& faces);

    /// After vertical(), for the face rule's walls scope (VerticalFaces::unlabelWallFeet()):
    /// per range-image column, the row of its lowest clustered point when that point's cluster
    /// is wall-like (its xy box has a side of at least params.vertical_face_min_length: a wall,
    /// fence, hedge or building, longer than any car seen from any side), else -1; and that
    /// point's xy range.
    void wallBottoms(const Params& params, int cols, std::vector<int16_t>& bottom_row,
                     std::vector<float>& bottom_range);

    /// Stage 3: cluster ids. Clusters with min_cluster_size..max_cluster_size points get ids
    /// 1, 2, ... in the order of their first point (smallest input index): the same input
    /// gives the same ids. Other points keep id 0.
    void assignIds(const Params& params, std::vector<uint32_t>& cluster_id);

    /// Stage 4: per-cluster summaries (count, centroid, boxes, height above the terrain
    /// model) of the clusters of the last assignIds().
    void summarize(const TriGridField& field, const TerrainModel& terrain,
                   std::vector<ClusterSummary>& clusters);

    /// Sizes (and maps) the buffers for frames of up to `points` non-ground points on a range
    /// image of `cells` = rows x columns cells.
    void reserve(std::size_t points, std::size_t cells);

    std::size_t numRuns() const { return run_first_.size(); }

    /// After horizontal(): the mean elevation [rad] of each range-image row, the range-weighted
    /// mean sine of the elevations of the row's clustered (non-ground) points in the aligned
    /// frame; 0 for a row without any.
    const std::vector<float>& rowElevations() const { return row_elevation_; }
    /// After horizontal(): dtheta of the range-scaled vertical rule between rows r and rr: one
    /// ring's spacing [rad], the rows' mean elevations apart / rows apart. Two points of these
    /// rows merge when closer than sqrt(T_vert^2 + (R dtheta)^2), R the upper point's range.
    /// 0 when r == rr or either row has no run (the vertical update compares no point there).
    float ringSpacing(int r, int rr) const {
        const auto a = static_cast<std::size_t>(r), b = static_cast<std::size_t>(rr);
        if (r == rr || row_runs_begin_[a] == row_runs_begin_[a + 1] ||
            row_runs_begin_[b] == row_runs_begin_[b + 1])
            return 0.f;
        return std::fabs(row_elevation_[a] - row_elevation_[b]) / float(std::abs(r - rr));
    }

  private:
    int find(int run);
    void linkAcrossSeam(int begin, int end, int seam_col, int cols, float max_dist2);
    void linkSeenThrough(const Params& params);
    void linkSetBackTops(const Params& params);
    static constexpr int kNoRoot = -1, kConflictRoot = -2;
    // The cluster (root) of the points in front of run's points in the row below it (by more
    // than t_horz, at most depth), kNoRoot if none, kConflictRoot if two or one deeper.
    int rootInFrontBelow(uint32_t run, float t_horz, float depth) const;
    std::vector<int16_t> root_low_row_;  // per root: its lowest row, see linkSetBackTops()
    // The cluster (root) of the nearest pair of points nearer than `nearer_than` before and
    // after the run [first, last] on its row [row_lo, row_hi), within a few points, -1 if
    // none; the pair in enclosure_left_ / enclosure_right_.
    int enclosingRoot(uint32_t first, uint32_t last, uint32_t row_lo, uint32_t row_hi,
                      float nearer_than, int own_root);
    uint32_t enclosure_left_ = 0, enclosure_right_ = 0;
    // How far the run's deepest point lies behind the frame of the gap it is seen through in
    // cluster `enclosing` (the line through that cluster's nearest points left and right of the
    // run within max_lateral), measured in xy along the line's normal.
    float depthBehindFrame(uint32_t run, int enclosing, float max_lateral) const;
    // Passenger cars (SUVs, pick-ups) are at most 2.0 m tall; taller vehicles may be 2.55 m wide.
    static constexpr float kCarMaxHeight = 2.0f;
    // Row r's run b has a point of cluster `root` nearer than `nearer_than` in its columns on
    // one of the two rows above or below.
    bool closedAboveOrBelow(int r, int rows, uint32_t b, int root, float nearer_than);
    struct RootBox {
        int row_lo = 1 << 30, row_hi = -1, col_lo = 1 << 30, col_hi = -1;
        float nearest = std::numeric_limits<float>::infinity();
        uint32_t points = 0;
        void add(int row, int col_begin, int col_end, float range, uint32_t size) {
            row_lo = std::min(row_lo, row), row_hi = std::max(row_hi, row);
            col_lo = std::min(col_lo, col_begin), col_hi = std::max(col_hi, col_end);
            nearest = std::min(nearest, range), points += size;
        }
    };
    std::vector<RootBox> root_box_;  // of the roots involved_ only
    std::vector<uint8_t> involved_;  // per root: to join another, or to be joined
    // root_box_ of the roots with enclosure_[root] >= 0 (and closed_[root] when closed_only)
    // and of the roots they would join.
    void boxInvolvedRoots(bool closed_only);
    std::vector<uint8_t> closed_;  // per root, see linkSeenThrough()
    void unite(int a, int b);
    // Two of the runs' points in columns at most column_window apart are closer than
    // sqrt(t_vert2 + ring_step2 R^2), R the range of a's point.
    bool runsTouch(int a, int b, int column_window, float t_vert2, float ring_step2) const;
    float dist2(uint32_t a, uint32_t b) const;  // between sorted points a and b

    // Non-ground points sorted by (row, column, input index): input indices, their coordinates
    // and columns (one 16-byte record: the sort writes two places per point, not five, and the
    // later walks read a point's coordinates and column together), and the offsets of each row
    // in this order.
    struct SortedPoint {
        float x, y, z;
        int32_t col;
    };
    std::vector<uint32_t> sorted_;
    std::vector<SortedPoint> pts_;
    std::vector<uint32_t> row_begin_;
    std::vector<uint32_t> key_count_;
    int cols_ = 0;  // of the range image of the last horizontal()
    // The first sorted point of `row` in column `col` or after, the row's end if none: one
    // lookup in the counting sort's cell offsets (no search).
    uint32_t firstPointFrom(int row, int col) const;
    std::vector<uint32_t> input_, key_;  // the points to sort and their keys, in input order
    std::vector<float> range_;           // of each sorted point

    // Runs: first and last point (sorted positions), column span, row; runs of a row are
    // consecutive and ordered by first column.
    std::vector<uint32_t> run_first_, run_last_;
    std::vector<float> run_far_range_, run_near_range_;  // max, min
    std::vector<float> row_elevation_;                   // mean elevation of each row [rad]
    std::vector<int32_t> run_col_begin_, run_col_end_;
    std::vector<int16_t> run_row_;
    std::vector<uint32_t> run_size_, run_first_input_;  // points, smallest input index
    std::vector<uint32_t> row_runs_begin_;  // runs of row r: [row_runs_begin_[r], [r + 1])
    // Bounding box of each run: x, y, z (and an unused 0), so that the vertical update's box
    // test is a few 4-lane operations.
    struct RunBox {
        Eigen::Array4f lo, hi;
    };
    std::vector<RunBox> run_box_;
    // vertical(): the run boxes as arrays (lo x, y, z, hi x, y, z, each num_runs + padding
    // floats) for its box test 4 runs at a time, and for the last rows the first run starting
    // at or after each column.
    std::vector<float> box_arrays_;
    std::vector<uint32_t> first_run_;
    // Per root: the union of its runs' boxes (unionRootBoxes(), from run_root_): the cluster's
    // height in linkSeenThrough(), its length in wallBottoms().
    std::vector<RunBox> root_box3_;
    void unionRootBoxes();
    std::vector<uint8_t> wall_root_;  // per root: wall-like, see wallBottoms()
    // Per run of the upper row, while a pair of rows is compared in vertical(): the squared
    // distance below which its points merge with the lower row's.
    std::vector<float> merge_dist2_;
    struct NearPair {
        uint32_t a, b;  // runs of the upper and the lower row whose boxes are near
    };
    std::vector<NearPair> near_;  // see vertical()
    // vertical(): blocks of up to 4 candidate runs (the box test's lanes) of one run `fixed`:
    // candidates first .. min(first + 4, end) - 1.
    struct CandidateBlock {
        uint32_t fixed, first, end;
    };
    std::vector<CandidateBlock> blocks_;
    std::vector<int32_t> point_run_;  // run of each sorted point
    // The points of a run, in column order: from run_first_, each point's successor, up to
    // kEndOfRun.
    static constexpr uint32_t kEndOfRun = 0xffffffffu;
    std::vector<uint32_t> next_in_run_;
    std::vector<int32_t> parent_;
    std::vector<int32_t> open_runs_;                 // of the ring being swept, most recent last
    std::vector<int32_t> seam_before_, seam_after_;  // runs ending / starting at the seam
    std::vector<int32_t> enclosure_;  // per root: the cluster it is seen through, see .cpp

    // Id assignment scratch.
    std::vector<uint32_t> root_size_, root_first_;
    std::vector<int32_t> root_order_;
    std::vector<uint32_t> root_id_;
    std::vector<int32_t> run_root_;
    std::vector<uint32_t> run_id_;    // cluster id of each run
    std::vector<uint32_t> point_id_;  // cluster id of each sorted point
    struct Sums {
        double sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, syy = 0;
        float cos_yaw = 1, sin_yaw = 0;
        Eigen::Vector4f extent{0.f, 0.f, 0.f, 0.f};
    };
    std::vector<Sums> sums_;
};

}  // namespace travel
