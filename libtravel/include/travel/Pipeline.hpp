// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The TRAVEL pipeline: composes the stages, owns every buffer and reuses it across frames.
//
// Threads: one Pipeline is used by one thread at a time (process() changes it; nothing locks).
// Pipelines share nothing, so several may run at once, one per thread, with identical results.
// A Pipeline may move from thread to thread: the labelling keeps small scratch buffers per
// thread (thread_local), allocated on the first frame a thread runs. Copies (and settledCopy())
// have buffers of their own. Buffers only grow: process() allocates nothing once this pipeline
// and the Result have seen frames as large (points, runs, clusters) on this thread.
//
//   Pipeline travel(params);            // validates params (throws ConfigError)
//   travel.process(cloud, {}, result);  // result.labels[i] for every input point i
//   if (result.mount) std::cerr << result.mount.message << "\n";  // once: estimate or warning
//
// The mount (MountEstimator.hpp): `auto` sensor_height / mount_roll_deg / mount_pitch_deg are
// estimated from the first frame with a ground plane (tried on up to 10 frames; until then
// their fallback values are used) and kept; fixed values are checked once against the first
// frame's ground plane. Either way result.mount reports it on that frame. The seed search
// radius is raised to reach the first ground ring (firstGroundRingRadius) when it cannot.
#pragma once

#include <utility>

#include "travel/MountEstimator.hpp"
#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"
#include "travel/Result.hpp"
#include "travel/RunClustering.hpp"
#include "travel/TerrainModelFitting.hpp"
#include "travel/TraversableGraphSearch.hpp"
#include "travel/TriGridField.hpp"
#include "travel/VerticalFaces.hpp"

namespace travel {

class Pipeline {
  public:
    /// Validates `params` and sizes every buffer for the sensor they describe (rings x columns
    /// points, the tri-grid's extent), so the first frame is not slower than the next ones.
    /// Throws ConfigError (Params::validate()) naming the first parameter out of its range or
    /// inconsistent with another.
    explicit Pipeline(const Params& params);

    /// Sizes a Result's buffers for this pipeline's frames (before its first process(): the
    /// first frame into a fresh Result would otherwise map their memory page by page).
    void reserve(Result& result) const;

    /// The parameters in use: `auto` values replaced by their estimates once known, the seed
    /// search radius as raised by the first-ground-ring rule.
    const Params& params() const { return params_; }
    /// The parameters as given to the constructor.
    const Params& configuredParams() const { return configured_; }

    /// Traversable ground segmentation (TGS) of one frame, then (params.cluster_objects)
    /// above-ground object segmentation (AOS) of its non-ground points. The face rule's walls
    /// scope (vertical_face_min_rise > 0, vertical_face_min_length > 0) runs the AOS runs even
    /// without cluster_objects (its walls are clusters), reporting no cluster then: the labels
    /// are the same either way.
    ///
    /// `cloud`: x, y, z [m] in the sensor frame (PointCloud.hpp), any number of points, any
    /// values (NaN, inf and out-of-range points are labelled Invalid). `input`: what is known of
    /// the platform this frame ({} = nothing). `result` is overwritten: result.labels and
    /// result.cluster_id get one entry per input point; cluster summaries and the terrain model
    /// are in the aligned frame (Preprocessing.hpp). Reuse the same Result frame after frame.
    /// The same frame on the same parameters gives the same labels and cluster ids, whatever
    /// this pipeline processed before (once the mount is settled, see mountSettled()).
    ///
    /// Throws std::invalid_argument when cloud.x, y and z differ in size, and InputError when an
    /// explicit ring_source cannot be used for this cloud (`field`: no ring field, or a valid
    /// point's ring >= num_rings; `scan_order`: rings not found in the storage order; `auto`
    /// falls back instead). `result` holds no usable frame then; the pipeline stays usable.
    void process(const PointCloud& cloud, const FrameInput& input, Result& result);

    /// Names where fixed mount_roll_deg / mount_pitch_deg come from when the caller sets them
    /// (e.g. from a robot description), for the advice of a tilt Mismatch note.
    void setMountAnglesSource(MountAnglesSource source) { angles_source_ = std::move(source); }

    /// True once the mount is settled (`auto` values estimated or given up, fixed ones checked):
    /// from then on each process() depends on its own frame only, and a copy of this Pipeline
    /// labels any later frame exactly as this one would (apps run such copies on several
    /// threads, one Pipeline per thread).
    bool mountSettled() const { return mount_done_; }

    /// A new pipeline in this one's settled state (the parameters in use, the mount settled)
    /// with buffers of its own. Reads only what process() no longer changes once
    /// mountSettled(), so another thread may call it while this pipeline processes a frame.
    Pipeline settledCopy() const;

    /// Takes `settled`'s settled state (as settledCopy() gives it) into this pipeline, built from
    /// the same configured Params and not yet used, keeping this one's buffers: a worker's
    /// pipeline can be built (its pages mapped) before the first frame settles the mount.
    /// Reads only what `settled`.process() no longer changes once it is mountSettled().
    void adoptSettledState(const Pipeline& settled);

    /// The aligned coordinates of the last frame (sensor-centred, gravity-aligned).
    const AlignedCloud& aligned() const { return aligned_; }
    /// Rings and columns of the last frame (valid when params.cluster_objects or the face rule
    /// is on).
    const RangeImage& rangeImage() const { return range_image_; }
    /// The object stage of the last frame (its rows' elevations: RunClustering::rowElevations();
    /// valid when params.cluster_objects or the face rule's walls scope is on).
    const RunClustering& clustering() const { return clustering_; }

  private:
    /// Estimates `auto` values or checks fixed ones (until done); sets `note`.
    void updateMount(const PointCloud& cloud, const FrameInput& input, MountNote& note);
    /// seed_search_radius >= firstGroundRingRadius for the current height and elevation table.
    void applyFirstGroundRing();
    /// Points of a full frame of the configured sensor: scan_points, else beams x num_columns.
    std::size_t expectedPoints() const;

    Params configured_;
    Params params_;
    MountEstimator mount_estimator_;
    std::vector<uint8_t> self_returns_;  // per point of the frame the mount is estimated on
    MountAnglesSource angles_source_;
    std::size_t frame_index_ = 0;
    bool mount_done_ = false;
    AlignedCloud aligned_;
    TriGridField field_;
    TraversableGraphSearch graph_search_;
    TerrainModelFitting terrain_fitting_;
    RangeImage range_image_;
    VerticalFaces vertical_faces_;
    std::vector<float> foot_heights_;  // labelPoints' signed distances, for the face rule
    // Per range-image column, RunClustering::wallBottoms().
    std::vector<int16_t> wall_bottoms_;
    std::vector<float> wall_bottom_ranges_;
    RunClustering clustering_;
};

}  // namespace travel
