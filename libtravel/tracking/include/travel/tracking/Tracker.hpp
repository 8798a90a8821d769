// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Objects that keep their identity across frames (docs/tracking.md). Each frame's clusters are
// moved into a fixed world frame, associated with the tracks (TrackAssociation.hpp), and each
// track's constant-velocity Kalman filter (ConstantVelocityModel.hpp) gives its velocity and
// uncertainty. Rules, with the keys of the `tracking` configuration section:
//  - birth: a cluster no track takes starts a tentative track (clusters longer than
//    max_object_extent are not tracked);
//  - confirmation: after confirm_hits associated frames; only then the track gets its id,
//    1, 2, ... in the order of confirmation (within one frame, in the order of birth);
//  - end: a tentative track at its first miss, a confirmed one after max_misses consecutive
//    misses (meanwhile it coasts on its prediction and can be picked up again, same id);
//  - position: the centre of the largest box the track has seen, placed on the visible faces
//    (ObjectExtent.hpp); the centroid for tracks longer than full_box_max_length;
//  - displacement: with the clusters' points (ClusterSamples), a track measures how far its
//    object moved by aligning the new view onto the last one (TrackShapeAlignment.hpp) and
//    re-anchors its state by the rest of the measured position's shift (the view sliding over
//    the object), so the velocity is that of the object, not of its visible part;
//  - two filters: Track::motion (the velocity) takes that displacement as an anisotropic
//    measurement, precise across the faces seen, loose along them (correctWithFaces);
//    Track::centroid, fed with centroids alone, predicts where the next centroid lands for the
//    gates, so a face's centimetre precision never shrinks them;
//  - found again: a track born near where a moving track that lost its object (coasting, or
//    ended up to max_misses frames ago) is predicted starts with that track's velocity instead
//    of at rest (an occluded car found again as a new track);
//  - moving: set once the speed exceeds moving_speed_on for moving_frames_on frames in a row,
//    cleared when it falls below moving_speed_off.
// Deterministic: tracks are kept in birth order and every choice has a fixed tie order, so the
// same frames give the same ids. No MRPT, Eigen only.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "travel/Clusters.hpp"
#include "travel/Config.hpp"
#include "travel/tracking/ConstantVelocityModel.hpp"
#include "travel/tracking/TrackAssociation.hpp"
#include "travel/tracking/TrackShapeAlignment.hpp"

namespace travel {

struct Track {
    uint32_t id = 0;     ///< 0 while tentative, then 1, 2, ... (never reused)
    uint64_t birth = 0;  ///< serial number of its birth (the tie order)
    bool confirmed = false;
    bool moving = false;
    int hits = 0;                 ///< associated frames
    int misses = 0;               ///< consecutive frames without a cluster
    int fast_frames = 0;          ///< consecutive frames above moving_speed_on
    bool velocity_given = false;  ///< a new track took its velocity (Tracker::velocityDonor)
    double last_time = 0;         ///< [s] time of the last update
    /// Where the visible part's centroid is and goes (world xy, measured by centroids alone):
    /// the gates, the predicted box and the found-again rule compare clusters' centroids with
    /// it.
    ConstantVelocityModel centroid;
    /// The object's position and velocity (world xy): measured by the faces where they see
    /// it move, by the centroid (loosely, along the faces) elsewhere (Tracker::correctWithFaces).
    /// Its velocity is the track's.
    ConstantVelocityModel motion;
    /// Measured position minus motion's position after the last update [m]: the part of the
    /// last measurement the filter did not take.
    Eigen::Vector2d residual{0, 0};
    WorldBox box;  ///< last associated cluster's box, world frame (centre: filtered position)
    ObjectExtent extent;  ///< the largest box seen: locates partial views
    TrackShape shape;     ///< the last view's points: the displacement to the next view
    double z = 0;         ///< last measured centroid height, world frame [m]
    int cluster = -1;     ///< index of this frame's cluster in the last update() (-1: missed)

    Eigen::Vector2d position() const { return centroid.position(); }
    Eigen::Vector2d velocity() const { return motion.velocity(); }
};

class Tracker {
  public:
    explicit Tracker(const TrackingParams& params = {});
    /// Forgets every track; ids start again at 1.
    void reset();

    /// world_T_aligned: this scan's aligned frame (travel::Result's frame) in a fixed world
    /// frame; t [s], non-decreasing. Fills track_id / velocity / velocity_sigma / moving of each
    /// cluster (velocity in the aligned frame's axes, ego-motion removed; zero for clusters of
    /// no confirmed track).
    /// samples: a few points of each cluster (same frame and order as `clusters`); null: the
    /// displacement is that of the measured position alone.
    void update(double t, const Eigen::Isometry3d& world_T_aligned,
                std::vector<ClusterSummary>& clusters, const ClusterSamples* samples = nullptr);

    /// The live tracks (tentative and confirmed), in birth order.
    const std::vector<Track>& tracks() const { return tracks_; }
    const TrackingParams& params() const { return params_; }
    /// Track ids given so far (the highest id).
    uint32_t idsGiven() const { return next_id_ - 1; }

  private:
    void predictTracks(double t);
    /// Ends the lost tracks; cluster_to_track_ follows the shifted indices.
    void endLostTracks();
    /// Gives the unassigned clusters inside a confirmed, associated track's gate box to it.
    void attachFragments(const std::vector<ClusterSummary>& clusters);
    void updateMovingFlag(Track& track) const;
    /// motion's update with the faces' displacement (information [1/m^2] across the faces,
    /// TrackShape::displacement) and the centroid `position`.
    void correctWithFaces(Track& track, const Eigen::Vector2d& position,
                          const Eigen::Matrix2d& faces_information) const;
    /// The velocity a track born at `position` inherits: that of the moving track predicted
    /// nearest to it (within the gate distance plus 2 sigma) among those coasting or ended in
    /// the last max_misses frames, each given once; null if none.
    const Track* velocityDonor(const Eigen::Vector2d& position);
    /// Where `track` locates `cluster`: the centre of its full box on the visible faces, or the
    /// centroid for long tracks (full_box_max_length).
    Eigen::Vector2d positionOf(const Track& track, const WorldBox& cluster) const;
    void fillCluster(const Track& track, const Eigen::Matrix3d& aligned_R_world,
                     ClusterSummary& cluster) const;

    TrackingParams params_;
    std::vector<Track> tracks_;
    std::vector<Track> lost_;  ///< moving tracks ended lately: a new track may take their velocity
    uint32_t next_id_ = 1;
    uint64_t next_birth_ = 0;
    Eigen::Vector2d sensor_{0, 0};  ///< this frame's sensor position, world xy
    // Scratch reused across frames.
    std::vector<WorldBox> track_boxes_, cluster_boxes_;
    std::vector<AssociationPair> pairs_;
    std::vector<int> track_to_cluster_, cluster_to_track_;
    std::vector<Eigen::Vector3d> view_;  ///< one cluster's sample in the world frame
};

}  // namespace travel
