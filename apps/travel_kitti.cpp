// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-kitti: run TRAVEL over scans (one file, a folder, a KITTI sequence), write one .label per
// scan (class in the lower 16 bits, cluster id in the upper 16 bits), and, given SemanticKITTI
// labels, print ground precision / recall / F1 / accuracy per frame and their mean and std under
// both evaluation protocols, plus the CPU milliseconds of every stage (the first frame, then the
// median and max of the others) and the run's scans per second. --track: the clusters keep
// their identity across frames (travel::FrameTracker, docs/tracking.md).
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "CommandLine.hpp"
#include "LargePages.hpp"
#include "OrderedWork.hpp"
#include "Progress.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/ThreadCpuClock.hpp"
#include "travel/eval/FrameEvaluation.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/eval/Segmenter.hpp"
#include "travel/eval/TrackingMetrics.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/tracking/FrameTracker.hpp"
#include "travel/traversability/PoseFiles.hpp"
#include "travel/viz/PngFile.hpp"
#include "travel/viz/TrackPicture.hpp"

namespace fs = std::filesystem;

namespace {

/// --track: the frames' poses (given or estimated), the tracker, and what the summary and the
/// picture need. Frames arrive in input order (also with -j N).
struct Tracking {
    std::optional<travel::PoseTrajectory> given;  ///< the sequence's poses.txt (LiDAR frames)
    std::unique_ptr<travel::FrameTracker> tracker;
    std::ofstream poses;
    std::vector<travel::eval::TrackedFrame> frames;
    std::vector<travel::viz::TrackFrame> picture;
    std::vector<double> ms;
    std::vector<uint32_t> track_of_cluster;

    /// Tracks frame `f` (time 0.1 f: KITTI's 10 Hz) and writes its pose line.
    void add(std::size_t f, const travel::PointCloud& cloud, travel::eval::Segmentation& s) {
        const double start = travel::threadCpuMs();
        const Eigen::Isometry3d* pose = given ? &given->poses[f] : nullptr;
        const Eigen::Isometry3d world_T_sensor = tracker->update(
            0.1 * double(f), cloud, s.labels, s.aligned_rotation, s.clusters, pose, &s.cluster_id);
        ms.push_back(travel::threadCpuMs() - start);
        poses << travel::kittiPoseLine(world_T_sensor);
        frames.push_back({s.clusters, tracker->worldTAligned()});
        travel::viz::TrackFrame view;
        view.ego_x = float(world_T_sensor.translation().x());
        view.ego_y = float(world_T_sensor.translation().y());
        track_of_cluster.assign(s.clusters.size() + 1, 0u);
        for (const travel::ClusterSummary& c : s.clusters) {
            track_of_cluster[c.id] = c.track_id;
            if (!c.track_id) continue;
            const Eigen::Vector3d p = frames.back().world_T_aligned * c.centroid.cast<double>();
            const Eigen::Vector3d v =
                frames.back().world_T_aligned.linear() * c.velocity.cast<double>();
            view.tracks.push_back(
                {c.track_id, float(p.x()), float(p.y()), float(v.x()), float(v.y()), c.moving});
        }
        picture.push_back(std::move(view));
    }
    /// The upper 16 bits of a point's label: its cluster's track id.
    uint32_t trackId(uint32_t cluster_id) const { return track_of_cluster[cluster_id]; }
};

struct StageSeries {
    const char* name;
    std::vector<double> ms;  ///< one value per frame, in input order
};

/// One line of the time report: the first frame, then the median and max of the others.
void printTimeLine(const char* name, const std::vector<double>& ms, const char* note) {
    std::printf("  %-13s %8.3f", name, ms.front());
    if (ms.size() > 1) {
        const std::vector<double> rest(ms.begin() + 1, ms.end());
        std::printf(" %8.3f %8.3f", travel::median(rest),
                    *std::max_element(rest.begin(), rest.end()));
    }
    std::printf("%s\n", note);
}

/// The time report: per stage, the first frame apart (it checks the sensor mount and first uses
/// the pipeline's buffers), then the median and max of the other frames.
void printTimeReport(const std::vector<StageSeries>& stages,
                     const std::vector<double>& tracking_ms) {
    const std::size_t frames = stages.front().ms.size();
    if (frames == 0) return;
    std::printf(
        "Milliseconds per frame: CPU time of each stage on its worker thread (reading, scoring and "
        "writing not included):\n");
    std::printf("  %-13s %8s", "", "first");
    if (frames > 1) std::printf(" %8s %8s  (frames 2-%zu)", "median", "max", frames);
    std::printf("\n");
    for (const StageSeries& s : stages)
        if (std::any_of(s.ms.begin(), s.ms.end(), [](double ms) { return ms > 0.0; }))
            printTimeLine(s.name, s.ms, "");  // else a stage this method does not have
    if (!tracking_ms.empty()) printTimeLine("tracking", tracking_ms, "  (ego-motion + tracker)");
}

int run(int argc, char** argv) {
    travel::apps::CommandLine line(
        "travel-kitti",
        "Traversable ground segmentation of scans (TRAVEL, Oh et al. RA-L 2022).\n"
        "-i: a scan (.bin KITTI or nuScenes, .pcd, .ply), a folder of scans or a KITTI sequence "
        "folder (its velodyne/ scans; its labels/ enable the metrics). Writes "
        "<output>/<stem>.label "
        "for every scan <stem>: one little-endian uint32 per input point, in input order; lower "
        "16 bits = class (0 invalid, 1 ground, 2 non-ground, 3 outlier), upper 16 bits = cluster "
        "id (0 = none). With labels (found or --labels), prints ground P/R/F1/accuracy under "
        "protocol A (Patchwork benchmark: vegetation below -0.75 h counts as ground, unlabeled "
        "points predicted ground count as TP) and protocol B (Patchwork++: classes 0, 1, 70 not "
        "scored). Then the time report: CPU milliseconds of each TRAVEL stage on its worker "
        "thread (as bench_travel measures: time waiting for a core, reading, scoring and writing "
        "are not in it; --method baselines are timed the same way), for the first frame "
        "(it checks the mount and first uses the buffers) and as median and max of the others, "
        "and the scans per second of the whole run (wall clock, -j N, reading and writing "
        "included).",
        {"travel-kitti -i data/sequences/00 -o out/00",
         "travel-kitti -i scan.pcd -o out -p vlp16 --set sensor_height=1.2",
         "travel-kitti -i hdl32_000000.bin -f nuscenes -o out -p hdl32 -q -j 1",
         "travel-kitti -i data/kitti_raw_pcd -o out --track --track-png out/tracks.png"});
    TCLAP::CmdLine& cmd = line.cmd;
    const travel::apps::CommonFlags flags(line, false, "hdl64");
    TCLAP::ValueArg<std::string> labels(
        "", "labels",
        "SemanticKITTI labels folder: enables the metrics (default: the sequence's labels/)", false,
        "", "DIR", cmd);
    TCLAP::ValueArg<std::string> csv(
        "", "csv",
        "Write per-frame metrics and timings to this CSV (ms_*: the stages' CPU ms, as in the "
        "time report)",
        false, "", "FILE", cmd);
    const travel::apps::MaxFramesFlag max_frames(line, "scans");
    const travel::apps::JobsFlag jobs(line, "scans");
    TCLAP::ValueArg<std::string> method(
        "", "method",
        "Segmentation method: travel (default), travel-no-ttmf, tgs (ground only), ransac, gpf, "
        "gpf+slr, tgs+slr, tgs+euclidean, gpf+euclidean (baselines written from their papers; "
        "see README)",
        false, "travel", "NAME", cmd);
    TCLAP::SwitchArg track(
        "", "track",
        "Track the clusters across frames (method travel): the upper 16 bits of each label are "
        "the point's track id instead of its cluster id (0 = no confirmed track; ids above 65535 "
        "wrap), and <output>/poses.txt gets one KITTI pose line per scan (LiDAR pose in the first "
        "scan's frame: the sequence's poses.txt with calib.txt when there is one, else point-to-"
        "plane ICP of consecutive scans' non-ground points). Frames are tracked in input order, "
        "so -j N changes nothing. Section tracking: of the configuration (docs/tracking.md)",
        cmd);
    TCLAP::ValueArg<std::string> track_png(
        "", "track-png", "With --track: a bird's-eye picture of the tracks (world frame) to FILE",
        false, "", "FILE", cmd);
    if (const auto exit_code = line.parse(argc, argv)) return *exit_code;
    if (track_png.isSet() && !track.getValue())
        throw travel::apps::usageError("--track-png needs --track");

    const travel::Config configuration = flags.config.load();
    if (flags.config.print(configuration)) return 0;
    const travel::Params& params = configuration.travel;
    const bool quiet = flags.quiet();
    const std::string out = flags.outputPath();
    const travel::ScanFormat format = flags.scanFormat();
    travel::apps::preferLargePages(jobs.count());  // before any pipeline or thread
    // Configuration errors first, before any file is touched.
    std::unique_ptr<travel::eval::Segmenter> segmenter =
        travel::eval::makeSegmenter(method.getValue(), params);
    const travel::ScanList scans = travel::listScans(flags.inputPath(), format);
    std::vector<std::string> files = scans.files;
    const std::string labels_dir = labels.isSet() ? labels.getValue() : scans.labels_dir;
    if (labels.isSet()) travel::requireDirectory(labels_dir, "--labels directory");
    max_frames.keepFirst(files);
    // Label files found up front: the workers only read them.
    std::vector<std::string> label_paths(files.size());
    std::size_t unlabelled_frames = 0;
    for (std::size_t f = 0; f < files.size() && !labels_dir.empty(); ++f) {
        const std::string stem = fs::path(files[f]).stem().string();
        label_paths[f] = (fs::path(labels_dir) / (stem + ".label")).string();
        if (!fs::exists(label_paths[f])) {
            label_paths[f].clear();
            ++unlabelled_frames;
        }
    }
    if (labels.isSet() && unlabelled_frames == files.size())
        throw travel::InputError("--labels " + labels_dir + ": no <stem>.label for any of the " +
                                 std::to_string(files.size()) + " scans");
    Tracking tracking;
    if (track.getValue()) {
        if (method.getValue() != "travel" && method.getValue() != "travel-no-ttmf")
            throw travel::apps::usageError(
                "--track needs TRAVEL's clusters: --method travel or travel-no-ttmf");
        tracking.given = travel::readSequenceLidarPoses(scans.sequence_dir);
        if (tracking.given && tracking.given->size() < files.size())
            throw travel::InputError(scans.sequence_dir +
                                     "/poses.txt: " + std::to_string(tracking.given->size()) +
                                     " poses for " + std::to_string(files.size()) + " scans");
        tracking.tracker = std::make_unique<travel::FrameTracker>(configuration.tracking);
    }
    // A file output given as a folder: refused now, not after the run.
    travel::apps::requireFileName("--csv", csv.getValue());
    travel::apps::requireFileName("--track-png", track_png.getValue());
    // No output may be an input: the scans, the ground truth (-o its folder: the predicted
    // labels would replace it), the sequence's poses (--track writes OUT/poses.txt).
    std::vector<travel::apps::NamedPath> inputs = {{"the labels folder", labels_dir}};
    if (tracking.given) inputs.push_back({"the sequence's", scans.sequence_dir + "/poses.txt"});
    for (const std::string& scan : files) inputs.push_back({"the scan", scan});
    for (const std::string& label : label_paths) inputs.push_back({"the labels", label});
    const std::string poses_out = track.getValue() ? (fs::path(out) / "poses.txt").string() : "";
    travel::apps::checkOutputsApart(inputs, {{"-o", out},
                                             {"-o", poses_out},
                                             {"--csv", csv.getValue()},
                                             {"--track-png", track_png.getValue()}});
    travel::apps::createFolder(out);
    travel::apps::createParentFolder(csv.getValue());
    travel::apps::createParentFolder(track_png.getValue());
    // -j N: the other workers' segmenters, at most one per further scan (one scan builds one
    // pipeline), are built on their own threads while the first frame settles the mount.
    const auto workers =
        static_cast<unsigned>(std::clamp<std::size_t>(files.size(), 1, std::size_t{jobs.count()}));
    travel::apps::BackgroundBuilds<std::unique_ptr<travel::eval::Segmenter>> worker_segmenters(
        workers - 1,
        [&](unsigned) { return travel::eval::makeSegmenter(method.getValue(), params); });
    if (track.getValue()) {
        tracking.poses.open((fs::path(out) / "poses.txt").string());
        if (!tracking.poses)
            throw travel::InputError(
                travel::cannotWriteMessage(out + "/poses.txt", std::strerror(errno)));
    }

    std::ofstream csv_out;
    if (csv.isSet()) {
        csv_out.open(csv.getValue());
        if (!csv_out)
            throw travel::InputError(
                travel::cannotWriteMessage(csv.getValue(), std::strerror(errno)));
        csv_out << "frame,points,invalid,ground,nonground,outlier,"
                   "A_precision,A_recall,A_f1,A_accuracy,B_precision,B_recall,B_f1,B_accuracy,"
                   "clusters,OSE_sum,USE_sum,OSE_mean,USE_mean,instances,mean_coverage,"
                   "mean_purity,"
                   "ms_preprocess,ms_embedding,ms_node_fitting,ms_graph_search,ms_ttmf,"
                   "ms_labelling,ms_ground_total,ms_range_image,ms_horizontal,ms_vertical,"
                   "ms_clusters,ms_objects_total,ms_total"
                << (track.getValue() ? ",tracked_clusters,moving_clusters,ms_tracking\n" : "\n");
    }

    travel::eval::EvaluationAccumulator totals;
    std::vector<uint32_t> encoded;
    std::vector<StageSeries> stages = {
        {"preprocess", {}}, {"embedding", {}}, {"node_fitting", {}}, {"graph_search", {}},
        {"ttmf", {}},       {"labelling", {}}, {"ground_total", {}}, {"range_image", {}},
        {"horizontal", {}}, {"vertical", {}},  {"clusters", {}},     {"objects_total", {}},
        {"total", {}}};
    const int kNumStages = static_cast<int>(stages.size());
    constexpr int kObjectsStage = 11;  // "objects_total"
    const travel::apps::Verbosity verbosity =
        travel::apps::verbosityFrom(flags.quiet(), flags.verbose());
    const bool per_frame_lines = verbosity == travel::apps::Verbosity::Verbose;
    // The per-frame lines replace the progress line.
    travel::apps::ProgressLine progress(
        "travel-kitti", files.size(), per_frame_lines ? travel::apps::Verbosity::Quiet : verbosity,
        "scans");
    if (per_frame_lines)
        std::printf("%-8s %7s %6s %5s %6s | %-23s | %-23s | %s\n", "frame", "points", "ground",
                    "clust", "ms", "ground A: P R F1 Acc", "ground B: P R F1 Acc",
                    "objects: OSE USE (sums) coverage purity");

    // -j N: worker w segments with segmenters[w] (built with the first one, given its state
    // once its mount is settled); frames are consumed here, in input order.
    std::vector<std::unique_ptr<travel::eval::Segmenter>> segmenters;
    segmenters.push_back(std::move(segmenter));
    const auto produce = [&](unsigned w, std::size_t f, travel::eval::FrameEvaluation& frame) {
        if (!segmenters[w]) {
            segmenters[w] = worker_segmenters.take(w - 1);
            segmenters[w]->adoptSettledState(*segmenters[0]);
        }
        travel::eval::evaluateFrame(files[f], label_paths[f], *segmenters[w], frame, format);
    };
    const auto fork = [&](unsigned workers) { segmenters.resize(workers); };
    const auto consume = [&](std::size_t f, travel::eval::FrameEvaluation& frame) {
        travel::apps::throwIfInterrupted();  // the .label files written so far are complete
        const std::string stem = fs::path(files[f]).stem().string();
        totals.add(frame);
        if (const travel::MountNote& note = frame.segmentation.mount; note && !quiet)
            progress.note(travel::apps::mountNoteLine("travel-kitti", "", note));
        const travel::PointCloud& cloud = frame.cloud;
        if (tracking.tracker) tracking.add(f, cloud, frame.segmentation);
        const travel::eval::Segmentation& result = frame.segmentation;

        encoded.resize(cloud.size());
        for (std::size_t i = 0; i < cloud.size(); ++i)
            encoded[i] = travel::encodeLabel(
                result.labels[i],
                tracking.tracker ? tracking.trackId(result.cluster_id[i]) : result.cluster_id[i]);
        travel::writeLabelFile((fs::path(out) / (stem + ".label")).string(), encoded);

        // TRAVEL's stages (result.stages), or a baseline's ground or object stage (result.ground_ms
        // / objects_ms where the pipeline has none): CPU time of this thread, both.
        travel::StageTimings t = result.stages;
        if (t.ground_total == 0.0) t.ground_total = result.ground_ms;
        if (t.objects_total == 0.0) t.objects_total = result.objects_ms;
        const double stage_ms[] = {t.preprocess,
                                   t.embedding,
                                   t.node_fitting,
                                   t.graph_search,
                                   t.ttmf,
                                   t.labelling,
                                   t.ground_total,
                                   t.range_image,
                                   t.horizontal,
                                   t.vertical,
                                   t.clusters,
                                   t.objects_total,
                                   t.ground_total + t.objects_total};
        for (int s = 0; s < kNumStages; ++s) stages[s].ms.push_back(stage_ms[s]);

        const bool scored = frame.scored;
        const travel::GroundScores* scores = frame.ground;
        const travel::ObjectScores& objects = frame.objects;
        if (per_frame_lines) {
            std::printf("%-8s %7zu %6zu %5zu %6.2f", stem.c_str(), cloud.size(),
                        frame.count(travel::PointClass::Ground), std::size_t{frame.clusters},
                        t.ground_total + t.objects_total);
            for (int p = 0; p < 2 && scored; ++p)
                std::printf(" | %5.2f %5.2f %5.2f %5.2f", scores[p].precision, scores[p].recall,
                            scores[p].f1, scores[p].accuracy);
            if (scored)
                std::printf(" | %6.2f %6.2f  %5.3f %5.3f", objects.entropy.ose_sum,
                            objects.entropy.use_sum, objects.mean_coverage, objects.mean_purity);
            std::printf(!labels_dir.empty() && !scored ? " | (no ground truth)\n" : "\n");
        }
        if (csv_out) {
            csv_out << stem << ',' << cloud.size() << ','
                    << frame.count(travel::PointClass::Invalid) << ','
                    << frame.count(travel::PointClass::Ground) << ','
                    << frame.count(travel::PointClass::NonGround) << ','
                    << frame.count(travel::PointClass::Outlier);
            for (int p = 0; p < 2; ++p) {
                if (scored)
                    csv_out << ',' << scores[p].precision << ',' << scores[p].recall << ','
                            << scores[p].f1 << ',' << scores[p].accuracy;
                else
                    csv_out << ",,,,";
            }
            csv_out << ',' << std::size_t{frame.clusters};
            if (scored)
                csv_out << ',' << objects.entropy.ose_sum << ',' << objects.entropy.use_sum << ','
                        << objects.entropy.ose_mean << ',' << objects.entropy.use_mean << ','
                        << objects.instances.size() << ',' << objects.mean_coverage << ','
                        << objects.mean_purity;
            else
                csv_out << ",,,,,,,";
            for (int s = 0; s < kNumStages; ++s) csv_out << ',' << stage_ms[s];
            if (tracking.tracker) {
                const auto& clusters = result.clusters;
                csv_out << ','
                        << std::count_if(clusters.begin(), clusters.end(),
                                         [](const travel::ClusterSummary& c) { return c.track_id; })
                        << ','
                        << std::count_if(clusters.begin(), clusters.end(),
                                         [](const travel::ClusterSummary& c) { return c.moving; })
                        << ',' << tracking.ms.back();
            }
            csv_out << '\n';
        }
        progress.update(f + 1);
    };
    const auto run_start = std::chrono::steady_clock::now();
    travel::apps::forEachInOrder<travel::eval::FrameEvaluation>(
        files.size(), workers, [&] { return !segmenters[0]->independentFrames(); }, fork, produce,
        consume);
    const double run_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
    progress.finish();
    // The CSV and poses.txt streams are written frame by frame: a write that failed (a full
    // disk) shows in the stream's state once it is closed, and is an error, not a lost row.
    const auto close_checked = [](std::ofstream& stream, const std::string& path) {
        if (!stream.is_open()) return;
        stream.close();
        if (stream.fail()) {
            const std::string reason = std::strerror(errno);
            travel::removeCutFile(path);  // rows are missing: no cut file under the name
            throw travel::InputError(travel::cannotWriteMessage(path, reason));
        }
    };
    close_checked(csv_out, csv.getValue());
    close_checked(tracking.poses, (fs::path(out) / "poses.txt").string());
    if (track_png.isSet()) {
        travel::viz::TrackPictureOptions picture;
        travel::viz::writePng(travel::viz::renderTracks(tracking.picture, picture),
                              track_png.getValue());
    }
    if (verbosity == travel::apps::Verbosity::Quiet) return 0;

    std::printf("\n%zu scans processed (method %s, preset %s), labels written to %s\n",
                files.size(), method.getValue().c_str(), flags.config.preset.getValue().c_str(),
                out.c_str());
    if (!labels_dir.empty()) {
        if (unlabelled_frames)
            std::printf("%zu scans had no .label file and are not in the metrics\n",
                        unlabelled_frames);
        const travel::eval::EvaluationSummary sum = totals.summary();
        for (int p = 0; p < 2; ++p)
            if (sum.f1[p].n == 0)  // no value, not a score of 0
                std::printf("Ground, protocol %-26s not scored: no frame holds ground truth\n",
                            travel::protocolName(travel::eval::kGroundProtocols[p]));
            else
                std::printf(
                    "Ground, protocol %-26s over %zu frames: P %.2f +- %.2f  R %.2f +- %.2f  "
                    "F1 %.2f +- %.2f  Acc %.2f +- %.2f\n",
                    travel::protocolName(travel::eval::kGroundProtocols[p]), sum.f1[p].n,
                    sum.precision[p].mean, sum.precision[p].std, sum.recall[p].mean,
                    sum.recall[p].std, sum.f1[p].mean, sum.f1[p].std, sum.accuracy[p].mean,
                    sum.accuracy[p].std);
        const bool clusters_objects =
            std::any_of(stages[kObjectsStage].ms.begin(), stages[kObjectsStage].ms.end(),
                        [](double ms) { return ms > 0.0; });
        if (!clusters_objects) {
            std::printf("Objects: not evaluated (%s segments ground only)\n",
                        method.getValue().c_str());
        } else if (sum.objects.frames == 0) {
            std::printf("Objects: not evaluated (no frame holds ground truth)\n");
        } else {
            const travel::ObjectSummary& o = sum.objects;
            std::printf(
                "Objects over %zu frames: USE %.2f +- %.2f, OSE %.2f +- %.2f (per-frame sums, "
                "paper eqs. 6-7); per object: OSE %.3f, USE %.3f per cluster\n",
                o.frames, sum.use.mean, sum.use.std, sum.ose.mean, sum.ose.std, o.ose_per_object,
                o.use_per_cluster);
            std::printf(
                "Thing instances (>= 50 points): %zu, mean coverage %.3f, mean purity %.3f, "
                "split %zu, merged %zu\n",
                o.instances, o.mean_coverage, o.mean_purity, o.split, o.merged);
        }
    }
    if (tracking.tracker) {
        const travel::eval::IdPersistence kept = travel::eval::idPersistence(tracking.frames);
        std::printf(
            "Tracking: %u tracks confirmed; poses %s, written to %s/poses.txt; clusters >= 300 "
            "points with a cluster within 1 m in the next frame that kept their track id: %zu of "
            "%zu (%.1f %%)\n",
            tracking.tracker->tracker().idsGiven(),
            tracking.given ? "from the sequence's poses.txt" : "estimated (ICP)", out.c_str(),
            kept.kept, kept.counted, 100.0 * kept.share());
    }
    printTimeReport(stages, tracking.ms);
    std::printf(
        "%zu scan%s in %.3f s, %.1f scans/s (wall clock, -j %u; reading, segmentation, "
        "scoring and writing)\n",
        files.size(), files.size() == 1 ? "" : "s", run_seconds,
        double(files.size()) / std::max(run_seconds, 1e-9), workers);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-kitti", run, argc, argv);
}
