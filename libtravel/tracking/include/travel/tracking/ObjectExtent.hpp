// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Where an object is when only part of it is seen. A LiDAR sees the faces of a car that point
// at it, so the centroid (and the box) of its points moves with the viewpoint: an oncoming car
// passing by seems to brake by ~2 m/s. A track therefore remembers the largest box it has seen
// (its length axis and size), and locates each new cluster by the centre of that full box,
// placed so that its near faces are the visible ones: along each axis the visible box is grown
// away from the sensor to the full size.
#pragma once

#include <Eigen/Core>

namespace travel {

/// An oriented box in the world's xy plane.
struct FlatBox {
    Eigen::Vector2d centre{0, 0};
    double yaw = 0;              ///< [rad] of the length axis
    Eigen::Vector2d size{0, 0};  ///< length (along yaw), width [m]
};

class ObjectExtent {
  public:
    /// Grows the remembered box with a new view: the size along the remembered axes becomes
    /// the larger of the two, and the axes follow views that show at least 90 % of the length.
    void update(const FlatBox& visible);
    /// The centre of the full box whose near faces are those of `visible`, seen from `sensor`.
    /// The visible centre itself before any update().
    Eigen::Vector2d centreOf(const FlatBox& visible, const Eigen::Vector2d& sensor) const;
    const FlatBox& box() const { return full_; }
    bool known() const { return known_; }

  private:
    FlatBox full_;  ///< centre unused
    bool known_ = false;
};

/// Extent of `box` along the axes of yaw (its projection): (along, across).
Eigen::Vector2d extentAlong(const FlatBox& box, double yaw);

}  // namespace travel
