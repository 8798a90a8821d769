// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-eval's evaluation: the labelled frames of one or more SemanticKITTI sequences, every
// method run over them (evaluateFrame per frame), the markdown report, frames.csv and the
// parameter-sweep table. The plots are drawn by the app.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "travel/Params.hpp"
#include "travel/eval/FrameEvaluation.hpp"

namespace travel::eval {

struct FrameRef {
    std::string scan, label, name;  ///< name: "<sequence>/<stem>"
    ScanFormat format = ScanFormat::Auto;
};

/// A sequence's name for the report: ".../sequences/00/velodyne" -> "00".
std::string sequenceName(const std::string& scans_dir);

/// The scans that have a label file, over all inputs in order (each as listScans() reads it: a
/// scan, a folder of scans or a KITTI sequence folder), at most max_frames of them (when > 0).
/// `labels` is empty (each input's own labels/ folder) or has one labels folder per input.
/// Throws InputError for a missing labels folder or an input none of whose scans has a label.
std::vector<FrameRef> labelledFrames(const std::vector<std::string>& inputs,
                                     const std::vector<std::string>& labels, std::size_t max_frames,
                                     ScanFormat format = ScanFormat::Auto);

/// "sequence 00, 000000-000002; sequence 01, ..." for the report header.
std::string describeFrames(const std::vector<FrameRef>& frames);

/// One (method, frame) row of frames.csv.
struct FrameRow {
    std::string frame;
    std::size_t points = 0;
    GroundScores ground[2];  ///< per kGroundProtocols
    bool objects = false;    ///< the method clustered this frame
    SegmentationEntropy entropy;
    double coverage = 0, purity = 0;
    std::size_t instances = 0, clustered = 0, split = 0, merged = 0;
    uint32_t clusters = 0;
    double ground_ms = 0, objects_ms = 0;
};

struct MethodRun {
    std::string method;
    std::vector<FrameRow> rows;
    EvaluationSummary summary;
    /// The first note on the sensor mount a frame had (Segmentation::mount), for the caller
    /// to show; empty when none.
    MountNote mount;
};

/// One step of running a method over frames: adds `frame` (the evaluation of `ref`) to `run`
/// (its row, its first mount note) and to `totals`. Call in frame order; afterwards
/// run.summary = totals.summary(). (travel-eval evaluates the frames with evaluateFrame() on
/// -j N workers and adds them here in order.)
void addFrame(const FrameRef& ref, const FrameEvaluation& frame, MethodRun& run,
              EvaluationAccumulator& totals);

/// report.md: ground tables for both protocols and the object table; `setup` describes the
/// parameters (preset, config, overrides), `jobs` the worker threads the frames ran on.
std::string reportMarkdown(const std::vector<MethodRun>& runs, const std::vector<FrameRef>& frames,
                           const std::string& setup, unsigned jobs = 1);

/// frames.csv: one row per method and frame, every per-frame value.
void writeFramesCsv(std::ostream& csv, const std::vector<MethodRun>& runs);

/// A parameter sweep, "KEY=v1,v2,...".
struct SweepSpec {
    std::string key;
    std::vector<std::string> values;
};

/// Parses and checks every value against `base` (key known, value in range, parameters
/// consistent), so a typo in the last value does not waste the whole sweep. Throws ConfigError.
SweepSpec parseSweep(const std::string& spec, const Params& base);

/// x positions: the values themselves when all are numbers, else 0, 1, 2, ... (e.g. booleans).
std::vector<double> sweepPositions(const std::vector<std::string>& values);

/// sweep_KEY.csv: one row per value of the sweep.
void writeSweepCsv(std::ostream& csv, const SweepSpec& spec,
                   const std::vector<EvaluationSummary>& sums, std::size_t frames);

/// What a leave-one-out choice of a swept value maximises, per frame.
enum class SweepScore { GroundF1B, GroundF1A, Coverage, Purity };
/// "f1b", "f1a", "coverage", "purity"; throws ConfigError for any other name.
SweepScore parseSweepScore(const std::string& name);
const char* sweepScoreName(SweepScore score);
double sweepScore(const FrameRow& row, SweepScore score);

/// Leave-one-out over the frames of a sweep: a value chosen on some frames and scored on one it
/// was not chosen on, the honest figure for a default picked from a handful of labelled frames.
struct LeaveOneOut {
    struct Fold {
        std::string frame;       ///< the held-out frame
        std::size_t chosen = 0;  ///< index of the value best on the other frames (ties: first)
        double held_out = 0;     ///< that value's score on the held-out frame
    };
    std::vector<Fold> folds;    ///< one per frame with a score, in frame order
    double held_out_mean = 0;   ///< mean of the folds' held-out scores
    std::size_t in_sample = 0;  ///< index of the value best on all frames (ties: first)
    double in_sample_mean = 0;  ///< its mean score over all frames
};
/// `rows[v]` are the frame rows of value v (MethodRun::rows, same frames in the same order for
/// every value). Folds and means are over the frames with a score at every value: ground truth
/// under the protocol (f1b, f1a), thing instances (coverage, purity; a frame the method did not
/// cluster scores 0). Needs two such frames, and for coverage or purity a clustered frame
/// (FrameRow::objects); throws std::invalid_argument otherwise.
LeaveOneOut leaveOneOut(const std::vector<std::vector<FrameRow>>& rows, SweepScore score);
/// The frames (indices into rows[v]) that have a score at every value, as leaveOneOut() uses.
std::vector<std::size_t> scoredFrames(const std::vector<std::vector<FrameRow>>& rows,
                                      SweepScore score);

/// sweep_KEY_loo.csv: one row per fold, then the in-sample row.
void writeLeaveOneOutCsv(std::ostream& csv, const SweepSpec& spec, SweepScore score,
                         const LeaveOneOut& loo);

}  // namespace travel::eval
