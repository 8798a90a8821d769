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
// (the steepness is tested across the gap), so porous faces keep their feet too. Off by default on
// roads (docs/parameters.md, "Off-road driving": unclustered feet, purity, speed). The object
// segmentation (Sec. IV) builds its runs without the feet, so that feet of neighbouring objects
// never link at ground level. With cluster_face_feet each foot then joins the cluster of its own
// face (RunClustering::attachFeet); without it (the default) the feet stay unclustered: on the
// SemanticKITTI dev frames about 9 % of the feet are road, parking or sidewalk points of the ground
// truth, mostly at car sills and tyres, and joined to the cars they lower the purity 0.991 -> 0.985
// (docs/parameters.md, "Off-road driving").
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"

namespace travel {

class VerticalFaces {
  public:
    /// Relabels Ground points at the foot of vertical faces NonGround and updates `counts`
    /// (indexed by PointClass). Does nothing when params.vertical_face_min_rise is 0.
    /// `heights` (labelPoints' signed distances, needed when
    /// params.vertical_face_min_foot_height > 0): a point lower than that is never a foot.
    void unlabelFaceFeet(const AlignedCloud& cloud, const RangeImage& image, const Params& params,
                         std::vector<PointClass>& labels, std::array<std::size_t, 4>& counts,
                         const std::vector<float>* heights = nullptr);

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
        int32_t point;  // the nearest (xy) point of the cell, or -1
    };
    std::vector<Cell> cells_;           // rows x cols
    std::vector<uint32_t> face_feet_;   // points relabelled by the last unlabelFaceFeet()
    std::vector<uint32_t> foot_faces_;  // the face point of each
};

}  // namespace travel
