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
// vertical_face_min_rise is on a face, not on the ground, and is relabelled NonGround.
// Kerbs (0.10-0.20 m, ground in SemanticKITTI and in the synthetic truth) rise less than the
// 0.25 m the os64 preset sets, and are kept. Off by default: the feet are left out of the object
// segmentation (see setFaceFeet), which breaks "every non-ground point is clustered"; joining
// each foot to the cluster of the face above it needs RunClustering's summaries to follow.
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
    void unlabelFaceFeet(const AlignedCloud& cloud, const RangeImage& image, const Params& params,
                         std::vector<PointClass>& labels, std::array<std::size_t, 4>& counts);

    void clear() { face_feet_.clear(); }

    /// Gives the points relabelled by the last unlabelFaceFeet() the class `c`. The object
    /// segmentation sees them as Ground: the face above each is clustered without it, and feet
    /// of neighbouring objects do not join them at ground level (measured: with the feet, the
    /// purity on the SemanticKITTI dev frames drops from 0.990 to 0.986).
    void setFaceFeet(std::vector<PointClass>& labels, PointClass c) const {
        for (const uint32_t i : face_feet_) labels[i] = c;
    }

  private:
    std::vector<int32_t> cell_point_;  // rows x cols: the first point of each cell, or -1
    std::vector<uint32_t> face_feet_;  // points relabelled by the last unlabelFaceFeet()
};

}  // namespace travel
