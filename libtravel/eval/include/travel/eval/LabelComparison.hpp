// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Regression comparison of two labellings of the same frames (travel-regress,
// docs/regression.md): a golden run (labelled frames stored earlier, e.g. the
// CObservationTravelLabels of a rawlog travel-rawlog wrote) against a replay.
//
// Per frame (compareFrames):
//  - classes: the 4 x 4 confusion counts golden class -> run class, and the agreement (points
//    whose class is unchanged over all points; 100 % for an empty frame). Frames whose point
//    counts differ cannot be compared point by point: agreement 0, size_mismatch set.
//  - clusters, whatever their id numbers: the overlap counts of every (golden id, run id) pair,
//    matched one-to-one greedily by decreasing overlap (ties: smaller golden, then run id). The
//    cluster agreement is the share of the points clustered in either run that lie in a matched
//    pair (100 % when nothing is clustered), so renumbering the clusters changes nothing. A golden
//    cluster is split when no run cluster holds a strict majority of its points (lost clusters
//    included) and merged when it is no strict majority of its best run cluster: the rules of
//    the instance scores of ObjectMetrics.hpp (GroupInClusters), with golden clusters for
//    instances.
//  - terrain: the tri-grid nodes traversable in one run and not in the other (every
//    traversable node when the grid geometries differ).
//  - timing: the total TRAVEL milliseconds of each (ground + objects).
// Over a run (RegressionReport): the compared frames, the golden frames the run lacks (missing)
// and the frames of the run without a golden one (extra), the verdict against the tolerances of
// the configuration's regress section, a per-frame CSV and a Markdown report.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "travel/Config.hpp"
#include "travel/LabelledFrame.hpp"

namespace travel {

/// What identifies a frame: its timestamp (exact, in the source's ticks) and its sensor label.
struct FrameKey {
    int64_t ticks = 0;
    double seconds = 0;  ///< the same time, for people
    std::string label;
    bool operator<(const FrameKey& o) const {
        return ticks != o.ticks ? ticks < o.ticks : label < o.label;
    }
};

struct FrameComparison {
    std::size_t golden_points = 0, run_points = 0;
    bool size_mismatch = false;  ///< point counts differ: classes and clusters not compared
    /// confusion[g][r]: points of golden class g that the run labels r (PointClass values).
    std::array<std::array<uint64_t, 4>, 4> confusion{};
    std::size_t class_changed = 0;  ///< points whose class differs
    double class_agreement = 100;   ///< % of the points whose class is unchanged

    std::size_t golden_clusters = 0, run_clusters = 0, matched_clusters = 0;
    std::size_t split = 0, merged = 0;  ///< golden clusters split / merged (see above)
    std::size_t clustered_points = 0;   ///< points in a cluster in either run
    std::size_t matched_points = 0;     ///< points in a matched pair of clusters in both
    double cluster_agreement = 100;     ///< % matched_points / clustered_points

    std::size_t golden_traversable = 0, run_traversable = 0;
    std::size_t changed_nodes = 0;  ///< nodes traversable in exactly one of the two

    double golden_ms = 0, run_ms = 0;  ///< TRAVEL time (ground + objects)

    /// How different the frame is, for "the worst frames": changed points first.
    double badness() const;
};

/// Compares one frame of the run with its golden frame (see the file comment).
FrameComparison compareFrames(const LabelledFrame& golden, const LabelledFrame& run);

/// changed[i] = 1 where the class of point i differs (empty when the sizes differ).
std::vector<uint8_t> classChanges(const LabelledFrame& golden, const LabelledFrame& run);

struct RegressionVerdict {
    bool passed = true;
    std::vector<std::string> failures;  ///< one per tolerance exceeded, e.g. "class agreement ..."
    std::string line;                   ///< "PASS: ..." or "FAIL: ..." (one line)
};

class RegressionReport {
  public:
    struct Frame {
        FrameKey key;
        FrameComparison comparison;
    };

    void addCompared(const FrameKey& key, const FrameComparison& comparison) {
        compared_.push_back({key, comparison});
    }
    void addMissing(const FrameKey& key) { missing_.push_back(key); }
    void addExtra(const FrameKey& key) { extra_.push_back(key); }

    const std::vector<Frame>& compared() const { return compared_; }
    const std::vector<FrameKey>& missing() const { return missing_; }
    const std::vector<FrameKey>& extra() const { return extra_; }

    /// Sums over the compared frames (confusion, points, clusters, nodes).
    FrameComparison total() const;
    /// Median run / golden time ratio per frame (0 without timings).
    double timeRatio() const;
    /// Indices (into compared()) of up to n frames that differ, the most different first.
    std::vector<std::size_t> worstFrames(std::size_t n) const;

    RegressionVerdict verdict(const RegressSection& tolerances) const;
    /// One line per compared frame, then one per missing / extra frame (status column).
    void writeCsv(std::ostream& out) const;
    /// `title`: the first heading; `pictures`: (frame index into compared(), file name) pairs.
    void writeMarkdown(std::ostream& out, const std::string& title,
                       const RegressSection& tolerances,
                       const std::vector<std::pair<std::size_t, std::string>>& pictures) const;

  private:
    std::vector<Frame> compared_;
    std::vector<FrameKey> missing_, extra_;
};

/// Pairs the frames of two streams by key, whatever their order: a frame waits until its twin
/// arrives; what is left at the end is missing (golden only) or extra (run only). In the usual
/// case (both streams in the same order) at most a few frames wait.
template <class Frame>
class FramePairing {
  public:
    /// The waiting run frame with this key, moved into `out`, when there is one.
    bool takeRun(const FrameKey& key, Frame& out) { return take(run_, key, out); }
    bool takeGolden(const FrameKey& key, Frame& out) { return take(golden_, key, out); }
    void waitRun(const FrameKey& key, Frame frame) { run_.emplace(key, std::move(frame)); }
    void waitGolden(const FrameKey& key, Frame frame) { golden_.emplace(key, std::move(frame)); }
    const std::multimap<FrameKey, Frame>& waitingRun() const { return run_; }
    const std::multimap<FrameKey, Frame>& waitingGolden() const { return golden_; }

  private:
    static bool take(std::multimap<FrameKey, Frame>& from, const FrameKey& key, Frame& out) {
        const auto it = from.find(key);
        if (it == from.end()) return false;
        out = std::move(it->second);
        from.erase(it);
        return true;
    }
    std::multimap<FrameKey, Frame> run_, golden_;
};

}  // namespace travel
