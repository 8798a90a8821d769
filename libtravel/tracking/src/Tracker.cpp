// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/Tracker.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace travel {
namespace {

/// The cluster's box moved into the world frame (the axis-aligned box of its rotated box);
/// the centre is NaN for clusters too long to track, so that no gate passes.
WorldBox worldBox(const ClusterSummary& c, const Eigen::Isometry3d& world_T_aligned,
                  double max_extent) {
    WorldBox box;
    const Eigen::Matrix3d R = world_T_aligned.linear();
    const Eigen::Vector3d lo = c.aabb_min.cast<double>(), hi = c.aabb_max.cast<double>();
    const Eigen::Vector3d mid = world_T_aligned * (0.5 * (lo + hi));
    const Eigen::Vector3d half = R.cwiseAbs() * (0.5 * (hi - lo));
    box.min = mid - half;
    box.max = mid + half;
    box.centre = (world_T_aligned * c.centroid.cast<double>()).head<2>();
    box.size = c.obb_extent.cast<double>().norm();
    box.flat.centre = (world_T_aligned * c.obb_center.cast<double>()).head<2>();
    box.flat.yaw = c.obb_yaw + std::atan2(R(1, 0), R(0, 0));
    box.flat.size = c.obb_extent.head<2>().cast<double>();
    if (!(c.obb_extent.x() <= max_extent))
        box.centre.setConstant(std::numeric_limits<double>::quiet_NaN());
    return box;
}

/// Whether `point` lies in the xy footprint of `box` grown by `grow` on every side.
bool insideGrown(const WorldBox& box, const Eigen::Vector2d& point, double grow) {
    return (point.array() >= box.min.head<2>().array() - grow).all() &&
           (point.array() <= box.max.head<2>().array() + grow).all();
}

/// Whether the whole xy footprint of `part` lies in that of `box` grown by `grow`.
bool footprintInsideGrown(const WorldBox& box, const WorldBox& part, double grow) {
    return insideGrown(box, part.min.head<2>(), grow) && insideGrown(box, part.max.head<2>(), grow);
}

/// Cluster c's sample moved into the world frame (into `view`); false when it has none.
bool worldView(const ClusterSamples* samples, std::size_t c,
               const Eigen::Isometry3d& world_T_aligned, std::vector<Eigen::Vector3d>& view) {
    view.clear();
    if (!samples) return false;
    for (uint32_t i = samples->begin(c); i < samples->end(c); ++i)
        view.push_back(world_T_aligned * samples->points()[i].cast<double>());
    return !view.empty();
}

}  // namespace

Tracker::Tracker(const TrackingParams& params) : params_(params) {
    params_.validate();
}

void Tracker::reset() {
    tracks_.clear();
    lost_.clear();
    next_id_ = 1;
    next_birth_ = 0;
}

void Tracker::predictTracks(double t) {
    track_boxes_.clear();
    for (Track& track : tracks_) {
        const Eigen::Vector2d before = track.position();
        track.centroid.predict(t - track.last_time, params_.acceleration_sigma);
        track.motion.predict(t - track.last_time, params_.acceleration_sigma);
        track.last_time = std::max(track.last_time, t);
        const Eigen::Vector2d shift = track.position() - before;
        track.box.min.head<2>() += shift;
        track.box.max.head<2>() += shift;
        track.box.centre = track.position();
        // The predicted box is only as sure as the predicted position: grown by 2 sigma, so a
        // young track (velocity still unknown) of a thin, fast object (a car's front face) is
        // not lost on its second frame.
        WorldBox gate_box = track.box;
        const double grow = 2.0 * std::sqrt(std::max(track.centroid.covariance()(0, 0),
                                                     track.centroid.covariance()(1, 1)));
        gate_box.min.head<2>().array() -= grow;
        gate_box.max.head<2>().array() += grow;
        track_boxes_.push_back(gate_box);
    }
    std::size_t kept = 0;
    for (Track& track : lost_) {
        const Eigen::Vector2d before = track.position();
        track.centroid.predict(t - track.last_time, params_.acceleration_sigma);
        track.motion.predict(t - track.last_time, params_.acceleration_sigma);
        track.box.min.head<2>() += track.position() - before;
        track.box.max.head<2>() += track.position() - before;
        track.last_time = std::max(track.last_time, t);
        if (++track.misses > 2 * params_.max_misses) continue;
        lost_[kept++] = std::move(track);
    }
    lost_.resize(kept);
}

const Track* Tracker::velocityDonor(const Eigen::Vector2d& position) {
    Track* best = nullptr;
    double best_distance = 0;
    const auto consider = [&](Track& track) {
        if (!track.confirmed || !track.moving || track.misses == 0 || track.velocity_given) return;
        // Inside the predicted box grown by the margin, 2 sigma and the object's length: the
        // part seen again (a car's front) need not be the part last seen (its rear).
        const double grow = params_.gate_box_margin + track.extent.box().size.x() +
                            2.0 * std::sqrt(std::max(track.centroid.covariance()(0, 0),
                                                     track.centroid.covariance()(1, 1)));
        if (!insideGrown(track.box, position, grow)) return;
        const double distance = (track.position() - position).norm();
        if (!best || distance < best_distance) best = &track, best_distance = distance;
    };
    for (Track& track : tracks_) consider(track);
    for (Track& track : lost_) consider(track);
    if (!best) return nullptr;
    best->velocity_given = true;
    return best;
}

Eigen::Vector2d Tracker::positionOf(const Track& track, const WorldBox& cluster) const {
    if (track.extent.box().size.x() > params_.full_box_max_length) return cluster.centre;
    return track.extent.centreOf(cluster.flat, sensor_);
}

void Tracker::correctWithFaces(Track& track, const Eigen::Vector2d& position,
                               const Eigen::Matrix2d& faces_information) const {
    // The measurement's information: the faces' across themselves, plus the centroid's
    // everywhere. The centroid of the visible part lies anywhere along the object as faces come
    // into and out of view: uniform over the longest length seen, L, it has the variance
    // L^2 / 12 (never less than that of a centroid, position_sigma^2).
    const double length = track.extent.box().size.x();
    const double centroid_variance =
        std::max(params_.position_sigma * params_.position_sigma, length * length / 12.0);
    const Eigen::Matrix2d noise =
        (faces_information + Eigen::Matrix2d::Identity() / centroid_variance).inverse();
    // The faces measure the displacement since the last view, whose position the filter
    // took only in part (`residual`): across the faces the measured position is the filter's
    // last position moved by the faces, i.e. the centroid less that residual; along them it is
    // the centroid.
    track.motion.correct(position - noise * faces_information * track.residual, noise);
}

void Tracker::updateMovingFlag(Track& track) const {
    const double speed = track.velocity().norm();
    track.fast_frames = speed > params_.moving_speed_on ? track.fast_frames + 1 : 0;
    if (!track.moving && track.fast_frames >= params_.moving_frames_on) track.moving = true;
    if (track.moving && speed < params_.moving_speed_off) track.moving = false;
}

void Tracker::endLostTracks() {
    // Tracks with a cluster this frame never end here: only their indices shift.
    std::vector<int>& new_index = track_to_cluster_;  // no longer needed: reused
    new_index.assign(tracks_.size(), -1);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < tracks_.size(); ++k) {
        const Track& track = tracks_[k];
        if (track.misses >= (track.confirmed ? params_.max_misses : 1)) {
            if (track.confirmed && track.moving) lost_.push_back(std::move(tracks_[k]));
            continue;
        }
        new_index[k] = static_cast<int>(kept);
        if (kept != k) tracks_[kept] = std::move(tracks_[k]);
        ++kept;
    }
    tracks_.resize(kept);
    for (int& k : cluster_to_track_)
        if (k >= 0) k = new_index[k];
}

void Tracker::attachFragments(const std::vector<ClusterSummary>& clusters) {
    // A cluster no track took, lying wholly inside the predicted (gate) box of a confirmed
    // track that did take one, is a fragment of that object (a split): it continues the track
    // instead of founding a new one. The track's measurement is its largest part. Wholly, not
    // only its centre: a split leaves its pieces within the object's extent, while an object
    // that comes into view beside a tracked one reaches out of that object's box; and a piece
    // is no longer than the whole (the largest view of the object seen so far).
    for (std::size_t c = 0; c < clusters.size(); ++c) {
        if (cluster_to_track_[c] >= 0 || std::isnan(cluster_boxes_[c].centre.x())) continue;
        for (std::size_t k = 0; k < tracks_.size(); ++k) {
            const int main = track_to_cluster_[k];
            if (main < 0 || !tracks_[k].confirmed) continue;
            if (!footprintInsideGrown(track_boxes_[k], cluster_boxes_[c],
                                      params_.gate_box_margin) ||
                cluster_boxes_[c].flat.size.x() >
                    tracks_[k].extent.box().size.x() + params_.gate_box_margin)
                continue;
            cluster_to_track_[c] = static_cast<int>(k);
            if (clusters[c].num_points > clusters[main].num_points)
                track_to_cluster_[k] = static_cast<int>(c);
            break;
        }
    }
}

void Tracker::fillCluster(const Track& track, const Eigen::Matrix3d& aligned_R_world,
                          ClusterSummary& cluster) const {
    const Eigen::Vector3d v(track.velocity().x(), track.velocity().y(), 0.0);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    cov.topLeftCorner<2, 2>() = track.motion.velocityCovariance();
    const Eigen::Matrix3d aligned_cov = aligned_R_world * cov * aligned_R_world.transpose();
    cluster.track_id = track.id;
    cluster.velocity = (aligned_R_world * v).cast<float>();
    cluster.velocity_sigma = aligned_cov.diagonal().cwiseMax(0.0).cwiseSqrt().cast<float>();
    cluster.moving = track.moving;
}

void Tracker::update(double t, const Eigen::Isometry3d& world_T_aligned,
                     std::vector<ClusterSummary>& clusters, const ClusterSamples* samples) {
    cluster_boxes_.clear();
    for (const ClusterSummary& c : clusters)
        cluster_boxes_.push_back(worldBox(c, world_T_aligned, params_.max_object_extent));
    predictTracks(t);
    sensor_ = world_T_aligned.translation().head<2>();
    const AssociationGates gates{params_.gate_distance, params_.gate_box_margin,
                                 params_.gate_size_ratio};
    associateNearest(
        tracks_.size(), clusters.size(),
        [&](uint32_t t, uint32_t c) {
            return gatedDistance(track_boxes_[t], cluster_boxes_[c],
                                 positionOf(tracks_[t], cluster_boxes_[c]), gates);
        },
        pairs_, track_to_cluster_, cluster_to_track_);

    const Eigen::Matrix3d aligned_R_world = world_T_aligned.linear().transpose();
    for (ClusterSummary& c : clusters) {
        c.track_id = 0;
        c.velocity.setZero();
        c.velocity_sigma.setZero();
        c.moving = false;
    }
    attachFragments(clusters);

    for (std::size_t k = 0; k < tracks_.size(); ++k) {
        Track& track = tracks_[k];
        track.cluster = track_to_cluster_[k];
        if (track.cluster < 0) {
            ++track.misses;
            continue;
        }
        const WorldBox& measured = cluster_boxes_[track.cluster];
        // A larger view moves our idea of the object's centre, not the object: the state is
        // re-anchored by that shift, so the velocity does not see it.
        const Eigen::Vector2d before = positionOf(track, measured);
        track.extent.update(measured.flat);
        const Eigen::Vector2d position = positionOf(track, measured);
        const bool viewed = worldView(samples, track.cluster, world_T_aligned, view_);
        Eigen::Vector2d moved;
        Eigen::Matrix2d faces_information;
        // Only for objects the track says move: at rest, a slide of the centroid over the
        // object reads as motion and brings the alignment in; most clusters of a drive are at
        // rest, and the alignment costs (~10 us a track).
        const bool worth_it = track.velocity().norm() >= params_.moving_speed_off;
        if (viewed && worth_it && track.shape.known() &&
            track.shape.displacement(view_, position - track.shape.position(),
                                     params_.position_sigma, moved, &faces_information)) {
            // The object moved by `moved` since the last view: the rest of the measured
            // position's shift is the view sliding over the object (faces coming into or out
            // of sight), a new reference point like the larger box above.
            const Eigen::Vector2d slide = position - (track.shape.position() + moved);
            track.centroid.shift(slide);
            track.motion.shift(slide);
            track.centroid.correct(position, params_.position_sigma);
            correctWithFaces(track, position, faces_information);
        } else {
            track.centroid.shift(position - before);
            track.motion.shift(position - before);
            track.centroid.correct(position, params_.position_sigma);
            track.motion.correct(position, params_.position_sigma);
        }
        track.residual = position - track.motion.position();
        if (viewed)
            track.shape.remember(view_, position);
        else
            track.shape.forget();
        track.box = measured;
        for (std::size_t c = 0; c < clusters.size(); ++c)  // a split: the union box
            if (cluster_to_track_[c] == static_cast<int>(k)) {
                track.box.min = track.box.min.cwiseMin(cluster_boxes_[c].min);
                track.box.max = track.box.max.cwiseMax(cluster_boxes_[c].max);
            }
        track.box.centre = track.position();
        track.z = (world_T_aligned * clusters[track.cluster].centroid.cast<double>()).z();
        ++track.hits;
        track.misses = 0;
        updateMovingFlag(track);
    }
    endLostTracks();
    // Confirmation in birth order, so ids follow the order of birth within a frame.
    for (Track& track : tracks_) {
        if (track.confirmed || track.hits < params_.confirm_hits) continue;
        track.confirmed = true;
        track.id = next_id_++;
    }
    for (std::size_t c = 0; c < clusters.size(); ++c) {
        if (cluster_to_track_[c] >= 0 || std::isnan(cluster_boxes_[c].centre.x())) continue;
        Track track;
        track.birth = next_birth_++;
        track.last_time = t;
        track.extent.update(cluster_boxes_[c].flat);
        const Eigen::Vector2d position = positionOf(track, cluster_boxes_[c]);
        if (const Track* donor = velocityDonor(position)) {
            track.centroid.startWithVelocityOf(position, params_.position_sigma, donor->centroid);
            track.motion.startWithVelocityOf(position, params_.position_sigma, donor->motion);
        } else {
            track.centroid.start(position, params_.position_sigma, params_.initial_velocity_sigma);
            track.motion.start(position, params_.position_sigma, params_.initial_velocity_sigma);
        }
        track.box = cluster_boxes_[c];
        if (worldView(samples, c, world_T_aligned, view_)) track.shape.remember(view_, position);
        track.z = (world_T_aligned * clusters[c].centroid.cast<double>()).z();
        track.hits = 1;
        track.cluster = static_cast<int>(c);
        cluster_to_track_[c] = static_cast<int>(tracks_.size());
        if (params_.confirm_hits <= 1) {
            track.confirmed = true;
            track.id = next_id_++;
        }
        tracks_.push_back(std::move(track));
    }

    // Every cluster of a track (its fragments too) carries the track's id and velocity.
    for (std::size_t c = 0; c < clusters.size(); ++c) {
        const int k = cluster_to_track_[c];
        if (k >= 0 && tracks_[k].confirmed) fillCluster(tracks_[k], aligned_R_world, clusters[c]);
    }
}

}  // namespace travel
