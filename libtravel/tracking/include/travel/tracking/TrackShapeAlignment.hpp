// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// How far an object moved between two frames, from its shape rather than its centroid. A LiDAR
// sees the faces of a car that point at it, so the centroid of the visible part slides over the
// car as it passes (an oncoming car seems to brake by ~2 m/s; docs/tracking.md, "Limits"). The
// points of two consecutive views still overlap on the faces seen in both, so a 2-D alignment of
// the new view onto the previous one (world xy, translation only: over 0.1 s a car turns by a
// degree or two) gives the object's displacement where those faces constrain it; the Tracker
// re-anchors its Kalman state by the part of the centroid's shift the displacement does not
// explain (Tracker.cpp), so the velocity follows the object, not its visible part.
//
// Cheap by construction: only clusters long enough for the visible part to matter (a car, not
// a pedestrian or a pole) get a sample, of at most kMaxSamples points, kept in buffers reused
// from frame to frame; the nearest-neighbour search runs on the previous view sorted by x.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "travel/Clusters.hpp"
#include "travel/PointCloud.hpp"

namespace travel {

/// A few points of each cluster of one frame (aligned frame, the frame of the ClusterSummary).
class ClusterSamples {
  public:
    /// Points per cluster: enough to cover a car's visible faces every ~0.1-0.3 m, few enough
    /// to keep tracking far below 0.5 ms per frame.
    static constexpr uint32_t kMaxSamples = 64;
    /// [m] Clusters shorter than this (pedestrians, poles: their centroid barely moves with the
    /// view) get no sample; a car seen end-on is ~1.8 m wide.
    static constexpr float kMinLength = 1.5f;
    /// [m] ... and longer than this (walls, hedges, rows of parked cars: 64 points spread over
    /// them are too sparse to find faces, and they do not move) neither; a bus is ~12-18 m.
    static constexpr float kMaxLength = 20.f;
    /// Fewer points than this give no sample: too sparse to align.
    static constexpr uint32_t kMinPoints = 20;

    /// Samples every cluster long enough: every k-th of its points in input order, at most
    /// kMaxSamples. cluster_id: one per point of `cloud` (0 = none, else ClusterSummary::id =
    /// index + 1); aligned_rotation: sensor -> aligned.
    void build(const PointCloud& cloud, const std::vector<uint32_t>& cluster_id,
               const Eigen::Matrix3f& aligned_rotation,
               const std::vector<ClusterSummary>& clusters);

    /// Cluster `c`'s sample: points [begin(c), end(c)) of points(); empty when not sampled.
    uint32_t begin(std::size_t c) const { return c + 1 < offsets_.size() ? offsets_[c] : 0; }
    uint32_t end(std::size_t c) const { return c + 1 < offsets_.size() ? offsets_[c + 1] : 0; }
    const std::vector<Eigen::Vector3f>& points() const { return points_; }

  private:
    std::vector<uint32_t> offsets_;  ///< clusters + 1
    std::vector<uint32_t> stride_, countdown_, filled_;
    std::vector<Eigen::Vector3f> points_;
};

/// One track's view of its object in the previous frame, and the 2-D alignment onto it.
class TrackShape {
  public:
    /// Remembers a view: `world` its points in the world frame, `position` the position the
    /// tracker measured for it (the next displacement is applied to it). Each point on a
    /// vertical face gets the face's normal in xy (from its neighbours within kNormalRadius),
    /// when the next displacement() asks for it.
    void remember(const std::vector<Eigen::Vector3d>& world, const Eigen::Vector2d& position);
    void forget() { view_.clear(); }
    bool known() const { return !view_.empty(); }
    /// The position measured with the remembered view.
    const Eigen::Vector2d& position() const { return position_; }

    /// The object's displacement d since the remembered view (new view = remembered view + d),
    /// by a trimmed, robust point-to-line ICP of `world` (the new view, in xy), translation
    /// only. A face constrains the displacement only across itself (along a face the LiDAR's
    /// points stay where the beams hit, whatever the object does), so the faces are fused with
    /// `guess` (the measured position's shift, 1-sigma `guess_sigma` per axis) in information
    /// form: the faces decide across themselves, the guess where no face does (a side seen
    /// alone, along its length). False when fewer than half of the new points find a partner:
    /// the views do not overlap (a split, another object). faces_information (optional): the
    /// information [1/m^2] the faces alone give on d, sum of w n n^T / kPointSigma^2 over the
    /// matched points (w: the robust weight): large across the faces seen, zero along them.
    bool displacement(const std::vector<Eigen::Vector3d>& world, const Eigen::Vector2d& guess,
                      double guess_sigma, Eigen::Vector2d& d,
                      Eigen::Matrix2d* faces_information = nullptr);

    /// [m] radius of the neighbourhood giving a point's face normal.
    static constexpr double kNormalRadius = 0.5;
    /// ... among this many points on either side along the view's axis (cost: a fixed
    /// number of candidates per point, whatever the cluster's shape) ...
    static constexpr std::size_t kNeighbourWindow = 8;
    /// ... with at least this many points (the point itself included).
    static constexpr int kMinNeighbours = 6;
    /// A neighbourhood is a face when it spreads across the face at most this share (in
    /// variance) of its spread along it: 0.05 ~ a 10 cm thick strip over 0.5 m.
    static constexpr double kMaxFlatness = 0.05;
    /// [m] ... and spreads along it by at least this (standard deviation): points stacked at
    /// one spot (a column of scan rings) give no direction, only their noise.
    static constexpr double kMinFaceSpread = 0.05;
    /// [m] A face is vertical when its points span this much height (several scan rings). A
    /// roof or a bonnet also makes thin strips in xy, the scan rings crossing it, but those
    /// strips follow the sensor, not the object: they get no normal.
    static constexpr double kMinFaceHeight = 0.3;
    /// [m] 1-sigma of a point's distance to the face it is matched with: range noise, a car's
    /// curved panels, a face sampled by a few points. Sets the faces' weight against the guess,
    /// and the scale of the robust (Cauchy) weight, 2 sigma.
    static constexpr double kPointSigma = 0.2;
    /// Views with fewer points on faces are not aligned (their displacement is the guess's).
    static constexpr int kMinFacePoints = 4;

  private:
    /// Sorts the remembered view along its axis and finds its faces: on the first
    /// displacement() only (tracks that never ask pay nothing but the copy).
    void prepare();

    std::vector<Eigen::Vector3d> view_;  ///< as remembered
    bool prepared_ = false;
    struct Point {
        Eigen::Vector2d p, normal;  ///< normal zero: not on a vertical face
        double z;
        double s;  ///< position along axis_
    };
    std::vector<Point> reference_;  ///< sorted along axis_
    Eigen::Vector2d axis_{1, 0};    ///< the view's longest axis
    int faces_ = 0;                 ///< points with a normal
    Eigen::Vector2d position_{0, 0};
};

}  // namespace travel
