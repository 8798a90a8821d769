// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One interface for TRAVEL and the baselines it is compared with in the paper, so that an
// evaluation loop runs any of them by name:
//
//   auto seg = travel::eval::makeSegmenter("gpf+slr", params);  // throws ConfigError
//   travel::eval::Segmentation out;
//   seg->segment(cloud, out);  // out.labels[i], out.cluster_id[i] for every input point i
//
// Every method labels every input point (Invalid for the points travel::preprocess rejects),
// clusters only NonGround points, and numbers its clusters 1..K by their first point (input
// index), keeping clusters of min_cluster_size..max_cluster_size points (others get id 0).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Result.hpp"

namespace travel {
class Pipeline;
}

namespace travel::eval {

struct Segmentation {
    std::vector<PointClass> labels;    ///< one per input point
    std::vector<uint32_t> cluster_id;  ///< one per input point, 0 = no cluster
    double ground_ms = 0;              ///< pre-processing + ground segmentation
    double objects_ms = 0;             ///< clustering (0 for ground-only methods)
    /// Per-stage times when the ground stage is TRAVEL's (zeros for the baselines).
    StageTimings stages;
    /// TRAVEL's note on the sensor mount, on the one frame that has one (Result::mount).
    MountNote mount;
    /// h_s the segmenter used (TRAVEL: its estimate under `auto`, Result::sensor_height): the
    /// height protocol A's vegetation rule must use.
    double sensor_height = 0;
    /// TRAVEL's cluster summaries (aligned frame; empty for methods without TRAVEL's object
    /// stage), and the rotation sensor -> aligned frame they are in (every method).
    std::vector<ClusterSummary> clusters;
    Eigen::Matrix3f aligned_rotation = Eigen::Matrix3f::Identity();
};

class Segmenter {
  public:
    virtual ~Segmenter() = default;
    virtual const char* name() const = 0;
    /// Segments one frame (sensor frame, as acquired). Buffers are reused across frames.
    virtual void segment(const PointCloud& cloud, Segmentation& out) = 0;
    /// False while segment() still carries state from one frame into the next (TRAVEL's
    /// Pipeline estimates or checks the mount on its first frames, Pipeline::mountSettled()).
    /// Once true, frames are independent: clones may segment them in any order, on other
    /// threads, with the labels of one segmenter processing them in order (travel-kitti -j N).
    virtual bool independentFrames() const = 0;
    /// An independent copy in the same state (same settled mount), for another thread. Once
    /// independentFrames(), a thread may clone while another segments with this one.
    virtual std::unique_ptr<Segmenter> clone() const = 0;
    /// Takes `settled`'s state (as clone() gives it) into this segmenter, made by makeSegmenter()
    /// with the same method and Params and not yet used, keeping its buffers (apps build the
    /// workers' segmenters before the first frame, Pipeline::adoptSettledState()).
    virtual void adoptSettledState(const Segmenter& settled) = 0;
    /// The Pipeline whose object stage made the last frame's cluster ids (TRAVEL's methods,
    /// "travel" and "travel-no-ttmf"), for diagnostics that read its range image and rows
    /// (mergedParts()); nullptr for the methods with another or no clustering.
    virtual const Pipeline* objectPipeline() const = 0;
};

/// Methods by name: "travel", "travel-no-ttmf", "tgs", "ransac", "gpf", "gpf+slr", "tgs+slr",
/// "tgs+euclidean", "gpf+euclidean". Throws ConfigError (listing the valid names) for any
/// other name, and for invalid params. The baselines ("ransac", "gpf*") do not estimate the
/// mount: `auto` sensor_height / mount_roll_deg / mount_pitch_deg is a ConfigError for them.
std::unique_ptr<Segmenter> makeSegmenter(const std::string& method, const Params& params);

/// The valid method names, in the order above.
std::vector<std::string> methodNames();

/// Shared by the clusterers: turns raw component labels (0 = none, otherwise any value in
/// [1, max_label]) into ids 1..K ordered by each component's first point; components with
/// fewer than min_size or more than max_size points get 0. `count` and `new_id` are scratch.
void renumberClusters(std::vector<uint32_t>& ids, uint32_t max_label, int min_size, int max_size,
                      std::vector<uint32_t>& count, std::vector<uint32_t>& new_id);

}  // namespace travel::eval
