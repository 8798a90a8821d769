// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Vertical structure above a ground point as evidence against ground (extends paper eq. 5,
// Sec. III-D). Eq. 5 labels every point within eps3 of the terrain plane ground, so the lowest
// centimetres of a wall, a fence mesh or a footing are ground: a node plane cannot tell a
// point on the ground from a point on a face that rises from it. The range image can: along
// one column (one azimuth), consecutive rings that hit flat ground land rho^2 dtheta / h apart
// in range, rising little; rings that hit a vertical face land at the same range, rising
// rho dtheta each. A ground-labelled point from which the column climbs steeply (each ring to
// the next steeper than 45 degrees, steeper than any traversable slope) by more than
// vertical_face_min_rise, up to a non-ground point of eq. 5 (the face), is the face's foot:
// NonGround. Kerbs (0.10-0.20 m, ground in SemanticKITTI and in the synthetic truth) rise less
// than the 0.25 m the os64 preset sets, and are kept. Foliage, mesh and dark paint return part
// of the rays only: the climb steps over up to vertical_face_max_gap rings without a return
// (the steepness is tested across the gap), so porous faces keep their feet too. Two scopes
// (vertical_face_min_length; docs/parameters.md, "Off-road driving"):
// * every ground point (0, the os64 preset): unlabelFaceFeet() in the ground stage. The object
//   segmentation (Sec. IV) builds its runs without the feet, so that feet of neighbouring
//   objects never link at ground level. With cluster_face_feet each foot then joins the cluster
//   of its own face (RunClustering::attachFeet); without it the feet stay unclustered: on the
//   SemanticKITTI dev frames about 9 % of them are road, parking or sidewalk points of the
//   ground truth, mostly at car sills and tyres, and joined to the cars they lower the purity
//   0.991 -> 0.985.
// * walls and fences (> 0, the scope for roads, where the rule is off by default: +10 % CPU):
//   unlabelWallFeet() after the object segmentation, only in the range-image columns whose
//   lowest clustered point belongs to a cluster whose xy box has a side at least that long
//   (RunClustering::wallBottoms): longer than any car seen from any side, so car sills and
//   tyres never lose their road. The same climb; each foot joins its face's cluster. A foot is
//   taken only under a thin face (vertical_face_max_thickness): a wall or fence is one vertical
//   plane, a hedge (vegetation in SemanticKITTI, ground below 0.75 h_s in its protocol A)
//   scatters its returns through its depth.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"

namespace travel {

class VerticalFaces {
  public:
    /// Relabels Ground points at the foot of vertical faces NonGround and updates `counts`
    /// (indexed by PointClass). Does nothing when params.vertical_face_min_rise is 0 or
    /// params.vertical_face_min_length is not (the walls' scope, unlabelWallFeet()).
    /// `heights` (labelPoints' signed distances, needed when
    /// params.vertical_face_min_foot_height > 0): a point lower than that is never a foot.
    void unlabelFaceFeet(const AlignedCloud& cloud, const RangeImage& image, const Params& params,
                         std::vector<PointClass>& labels, std::array<std::size_t, 4>& counts,
                         const std::vector<float>* heights = nullptr);

    /// The walls' scope: the same climb, from the ground points of the rows just below
    /// bottom_row[c] (the lowest clustered point of column c, when its cluster is wall-like;
    /// -1 otherwise; bottom_range[c] its xy range) up to a face at or above it. Relabels the feet
    /// NonGround and updates `counts`; feet() / footFaces() list them for
    /// RunClustering::attachFeet().
    void unlabelWallFeet(const AlignedCloud& cloud, const RangeImage& image, const Params& params,
                         const std::vector<int16_t>& bottom_row,
                         const std::vector<float>& bottom_range, std::vector<PointClass>& labels,
                         std::array<std::size_t, 4>& counts);

    void clear() { face_feet_.clear(), foot_faces_.clear(); }

    /// The points relabelled by the last unlabelFaceFeet(), and for each the point of its face
    /// (a non-ground point of eq. 5 in the same range-image column, above it).
    const std::vector<uint32_t>& feet() const { return face_feet_; }
    const std::vector<uint32_t>& footFaces() const { return foot_faces_; }

    /// Gives the points relabelled by the last unlabelFaceFeet() the class `c` (Ground while
    /// the runs are built without them, NonGround again afterwards).
    void setFaceFeet(std::vector<PointClass>& labels, PointClass c) const {
        for (const uint32_t i : face_feet_) labels[i] = c;
    }

  private:
    struct Cell {
        float z;        // height of the cell's point, NaN if empty
        float r2;       // its squared xy range
        int32_t point;  // the nearest (xy) point of the cell, or -1
        // A cell keeps its nearest point in xy: the choice depends neither on the order of the
        // points nor on invalid points between them.
        void keepNearest(int32_t i, float z_i, float r2_i) {
            if (point < 0 || r2_i < r2) point = i, z = z_i, r2 = r2_i;
        }
    };
    static constexpr Cell kEmptyCell{std::numeric_limits<float>::quiet_NaN(), 0.f, -1};
    // The climb from a ground point at height foot_z, xy range foot_range, up the cells
    // cell[0], cell[stride], ... (`steps` of them, the rings above it): the first non-ground
    // point of eq. 5 it meets, if it rises by min_rise through steps steeper than 45 degrees,
    // else -1.
    static int32_t climbToFace(const Cell* cell, std::ptrdiff_t stride, int steps, float foot_z,
                               float foot_range, const std::vector<PointClass>& labels,
                               float min_rise, int max_gap);
    // The thickness of a face: the spread of the xy ranges of the returns in cell[0..rings)
    // (consecutive rings of one column, from the face's point up; see VerticalFaces.cpp),
    // leaving out those 0.5 m or more behind face_range; 0 with fewer than two.
    static float faceThickness(const Cell* cell, int rings, float face_range);
    void finish(std::vector<PointClass>& labels, std::array<std::size_t, 4>& counts) const;
    std::vector<Cell> cells_;  // rows x cols (every ground point's scope)
    // The walls' scope: a window of rows per column, and the candidate feet (ground points of
    // its rows below the wall's lowest point, within reach of it).
    struct Window {
        int16_t lo = 0, rows = 0;  // rows [lo, lo + rows), at cells_[begin...]
        int16_t feet_below = 0;    // window rows below the wall's lowest point
        uint32_t begin = 0;
        float min_r2 = 0.f;  // a foot's squared xy range is at least this
    };
    std::vector<Window> windows_;
    std::vector<uint32_t> spans_;        // per column + 1: its window's lo | rows << 16
    std::vector<uint8_t> window_flags_;  // per point (padded to 8): in a window
    std::vector<uint32_t> in_window_;    // the points in a window
    std::vector<uint32_t> candidates_;
    std::vector<uint32_t> face_feet_;   // points relabelled by the last unlabelFaceFeet()
    std::vector<uint32_t> foot_faces_;  // the face point of each
};

}  // namespace travel
