// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/Pipeline.hpp"

#include <stdexcept>
#include <string>

#include <algorithm>

#include "Prefault.hpp"
#include "travel/GroundLabelling.hpp"
#include "travel/NodeFitting.hpp"
#include "travel/ThreadCpuClock.hpp"

namespace travel {
namespace {

// The stages are timed with the calling thread's CPU clock (StageTimings, ThreadCpuClock.hpp).
struct Clock {
    using time_point = double;  // ms
    static time_point now() { return threadCpuMs(); }
};
double msSince(Clock::time_point& t) {
    const Clock::time_point now = Clock::now();
    const double ms = now - t;
    t = now;
    return ms;
}

// Frames on which `auto` mount values are tried before the fallbacks are kept for good.
constexpr std::size_t kMaxMountFrames = 10;
// A check of configured mount values fits the ground plane on every 4th point: its tolerances
// are 0.3 m and 5 deg (kMountHeightTolerance, kMountTiltToleranceDeg), and a quarter of a
// 64-beam scan (~10k ground points) gives the plane of the fit on all points within 5 mm and
// 0.11 deg (SemanticKITTI 00 frames 0-5 and the 22 kitti_raw_pcd frames), at a quarter of the
// cost on the first frame. `auto` values are estimated on every point.
constexpr std::size_t kMountCheckStride = 4;

bool hasAutoMount(const Params& p) {
    return p.sensor_height.isAuto() || p.mount_roll_deg.isAuto() || p.mount_pitch_deg.isAuto();
}

std::size_t mountStride(const Params& configured) {
    return hasAutoMount(configured) ? 1 : kMountCheckStride;
}

// The face rule's scopes (VerticalFaces): under every ground point, in the ground stage; or
// under wall-like clusters only, after the object segmentation. The walls scope needs the
// object segmentation's runs whatever cluster_objects says: without clusters it still runs
// them (and reports no cluster), so that the ground labels do not depend on cluster_objects.
bool everyGroundPointFaces(const Params& p) {
    return p.vertical_face_min_rise > 0.0 && p.vertical_face_min_length == 0.0;
}
bool wallFaces(const Params& p) {
    return p.vertical_face_min_rise > 0.0 && p.vertical_face_min_length > 0.0;
}
// The object segmentation runs: for the clusters, or for the walls scope.
bool runsObjects(const Params& p) {
    return p.cluster_objects || wallFaces(p);
}

}  // namespace

Pipeline::Pipeline(const Params& params) : configured_(params), params_(params) {
    params_.validate();
    applyFirstGroundRing();
    field_.configure(params_);
    // Buffers sized for a full frame now: their pages are mapped here, not on the first frame.
    const std::size_t points = expectedPoints();
    detail::prefault(aligned_.x, points), detail::prefault(aligned_.y, points);
    detail::prefault(aligned_.z, points), detail::prefault(aligned_.valid, points);
    detail::prefault(aligned_.node, points);
    if (hasSelfBox(params_)) detail::prefault(self_returns_, points);
    const std::size_t stride = mountStride(configured_);
    mount_estimator_.reserve((points + stride - 1) / stride);
    field_.reserve(points);
    graph_search_.reserve(field_), terrain_fitting_.reserve(field_);
    if (runsObjects(params_) || everyGroundPointFaces(params_)) range_image_.reserve(points);
    if (runsObjects(params_))
        clustering_.reserve(points, points);  // the range image has beams x columns cells too
}

Pipeline Pipeline::settledCopy() const {
    Pipeline copy(configured_);
    copy.adoptSettledState(*this);
    return copy;
}

void Pipeline::adoptSettledState(const Pipeline& settled) {
    params_ = settled.params_;  // the `auto` estimates, the raised seed search radius
    angles_source_ = settled.angles_source_;
    mount_done_ =
        settled.mount_done_;  // (frame_index_, which process() counts, only numbers notes)
}

std::size_t Pipeline::expectedPoints() const {
    if (params_.scan_points > 0) return static_cast<std::size_t>(params_.scan_points);
    const std::size_t beams = std::max<std::size_t>(elevationTableDeg(params_).size(),
                                                    static_cast<std::size_t>(params_.num_rings));
    return beams * static_cast<std::size_t>(params_.num_columns);
}

void Pipeline::reserve(Result& result) const {
    const std::size_t points = expectedPoints();
    detail::prefault(result.labels, points);
    detail::prefault(result.cluster_id, points);
    detail::prefault(result.terrain.nodes, static_cast<std::size_t>(field_.numNodes()));
}

void Pipeline::applyFirstGroundRing() {
    const std::vector<double> table = elevationTableDeg(params_);
    if (table.empty()) return;
    const double lowest = *std::min_element(table.begin(), table.end());
    params_.seed_search_radius =
        std::max(configured_.seed_search_radius,
                 firstGroundRingRadius(params_.sensor_height, lowest, params_.tgf_resolution));
}

void Pipeline::updateMount(const PointCloud& cloud, const FrameInput& input, MountNote& note) {
    const std::size_t frame = frame_index_++;
    if (mount_done_) return;
    // Up in the sensor frame under the configured mount (auto angles at their fallbacks).
    const Eigen::Vector3d prior_up = mountRotation(params_).transpose() * Eigen::Vector3d::UnitZ();
    // The own vehicle's returns stay out of the fit, as they stay out of the segmentation.
    markSelfReturns(cloud, params_, self_returns_);
    const GroundPlaneEstimate ground = mount_estimator_.estimate(
        cloud, prior_up, params_.min_range, params_.max_range,
        self_returns_.empty() ? nullptr : self_returns_.data(), mountStride(configured_));
    if (!ground.found) {
        if (frame + 1 < kMaxMountFrames) return;
        mount_done_ = true;
        if (!hasAutoMount(configured_)) return;
        note = notFoundMountNote(configured_, frame);
        return;
    }
    mount_done_ = true;
    if (hasAutoMount(configured_)) {
        if (params_.sensor_height.isAuto()) params_.sensor_height = autoSensorHeight(ground);
        if (params_.mount_roll_deg.isAuto()) params_.mount_roll_deg = ground.roll_deg;
        if (params_.mount_pitch_deg.isAuto()) params_.mount_pitch_deg = ground.pitch_deg;
        applyFirstGroundRing();
        note = estimatedMountNote(configured_, ground, frame);
    }
    const MountNote check = checkedMountNote(configured_, ground, alignmentRotation(params_, input),
                                             frame, angles_source_);
    if (!check) return;
    if (note) {  // the estimate, then what it asks the user to correct
        note.message += "; " + check.message;
        note.kind = check.kind;
    } else {
        note = check;
    }
}

void Pipeline::process(const PointCloud& cloud, const FrameInput& input, Result& result) {
    if (cloud.y.size() != cloud.x.size() || cloud.z.size() != cloud.x.size())
        throw std::invalid_argument("travel::Pipeline::process: x, y and z differ in size (" +
                                    std::to_string(cloud.x.size()) + ", " +
                                    std::to_string(cloud.y.size()) + ", " +
                                    std::to_string(cloud.z.size()) + ")");
    StageTimings& t = result.timings;
    Clock::time_point clock = Clock::now();
    result.mount.kind = MountNote::Kind::None;
    result.mount.message.clear();
    updateMount(cloud, input, result.mount);
    result.sensor_height = params_.sensor_height;
    preprocess(cloud, params_, input, aligned_, &field_.geometry());
    t.preprocess = msSince(clock);
    field_.embed(aligned_, result.terrain);
    t.embedding = msSince(clock);
    fitNodes(field_, params_, result.terrain);
    t.node_fitting = msSince(clock);
    graph_search_.run(field_, params_, result.terrain);
    t.graph_search = msSince(clock);
    terrain_fitting_.run(field_, params_, result.terrain);
    t.ttmf = msSince(clock);
    const bool faces = everyGroundPointFaces(params_);
    const bool foot_heights = faces && params_.vertical_face_min_foot_height > 0.0;
    result.class_counts = labelPoints(field_, aligned_, params_, result.terrain, result.labels,
                                      foot_heights ? &foot_heights_ : nullptr);
    if (faces) {
        range_image_.build(cloud, aligned_.valid, params_);
        vertical_faces_.unlabelFaceFeet(aligned_, range_image_, params_, result.labels,
                                        result.class_counts,
                                        foot_heights ? &foot_heights_ : nullptr);
    } else {
        vertical_faces_.clear();
    }
    t.labelling = msSince(clock);
    t.ground_total =
        t.preprocess + t.embedding + t.node_fitting + t.graph_search + t.ttmf + t.labelling;

    result.cluster_id.assign(cloud.size(), 0u);
    result.clusters.clear();
    t.range_image = t.horizontal = t.vertical = t.clusters = t.objects_total = 0;
    if (!runsObjects(params_)) return;
    if (!faces) range_image_.build(cloud, aligned_.valid, params_);  // else built above
    t.range_image = msSince(clock);
    vertical_faces_.setFaceFeet(result.labels, PointClass::Ground);
    clustering_.horizontal(aligned_, range_image_, result.labels, params_);
    vertical_faces_.setFaceFeet(result.labels, PointClass::NonGround);
    t.horizontal = msSince(clock);
    clustering_.vertical(params_);
    if (wallFaces(params_)) {
        clustering_.wallBottoms(params_, range_image_.cols(), wall_bottoms_, wall_bottom_ranges_);
        vertical_faces_.unlabelWallFeet(aligned_, range_image_, params_, wall_bottoms_,
                                        wall_bottom_ranges_, result.labels, result.class_counts);
    }
    if (!params_.cluster_objects) {  // the walls scope only: its feet are labelled, no cluster
        t.vertical = msSince(clock);
        t.objects_total = t.range_image + t.horizontal + t.vertical;
        return;
    }
    if (params_.cluster_face_feet || wallFaces(params_))
        clustering_.attachFeet(aligned_, range_image_, vertical_faces_.feet(),
                               vertical_faces_.footFaces());
    t.vertical = msSince(clock);
    clustering_.assignIds(params_, result.cluster_id);
    clustering_.summarize(field_, result.terrain, result.clusters);
    t.clusters = msSince(clock);
    t.objects_total = t.range_image + t.horizontal + t.vertical + t.clusters;
}

}  // namespace travel
