// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-regress: replays a rawlog through TRAVEL (as travel-rawlog does, RawlogSegmenter) and
// compares every labelled frame with the CObservationTravelLabels of a golden labelled rawlog
// (one travel-rawlog wrote), frames paired by timestamp and sensor label. The comparison and the
// verdict are libtravel's (travel/eval/LabelComparison.hpp), the pictures travel::viz's; this
// file parses the flags, streams the two rawlogs and prints. docs/regression.md.
#include <mrpt/img/CImage.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "CommandLine.hpp"
#include "Interrupt.hpp"
#include "MemoryLimit.hpp"
#include "Progress.hpp"
#include "RawlogJob.hpp"
#include "travel/eval/LabelComparison.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/viz/BirdsEye.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/Registration.hpp"
#include "travel_mrpt/TravelLabelsReader.hpp"

namespace fs = std::filesystem;
using travel::FrameKey;
using travel::LabelledFrame;
using travel::apps::AppError;

namespace {

// Exit codes: within the tolerances, outside them, an error (runMain's, usage errors included).
constexpr int kPass = 0, kFail = 1, kError = 2;

struct RegressOptions {
    travel::apps::Options replay;  // -i, the sensor label, -q/-v, --max-memory
    std::string golden, report_dir, command;
    std::size_t pictures = 3;
    travel::viz::BirdsEyeOptions picture;
};

std::optional<int> parseCommandLine(int argc, char** argv, RegressOptions& o,
                                    travel::Config& configuration) {
    travel::apps::CommandLine line(
        "travel-regress",
        "Regression test of TRAVEL's labels on a recorded rawlog: replays -i IN.rawlog with the "
        "given configuration (as travel-rawlog does) and compares, frame by frame, with the "
        "travel_mrpt::CObservationTravelLabels of --golden GOLDEN.rawlog (a rawlog travel-rawlog "
        "wrote with the configuration or library version you trust: travel-rawlog -i IN.rawlog "
        "-o GOLDEN.rawlog ...). Frames are paired by "
        "timestamp and sensor label; golden frames without a replayed twin are 'missing', "
        "replayed frames without a golden one 'extra' (both reported, never skipped).\n"
        "Compared per frame: the class of every point (confusion counts golden -> run, class "
        "agreement), the clusters whatever their id numbers (one-to-one matching by overlap, "
        "cluster agreement, split and merged golden clusters), the traversable terrain-model "
        "nodes that changed, and the TRAVEL time.\n"
        "Tolerances: the regress section of the configuration (min_class_agreement, "
        "min_cluster_agreement, max_split_clusters, max_merged_clusters, max_changed_nodes, "
        "max_missing_frames, max_extra_frames, max_time_ratio; defaults: no difference "
        "allowed, timing not checked), in --config or with --set regress.KEY=VALUE.\n"
        "Outputs: one verdict line on stdout (PASS: ... or FAIL: ... with the tolerances "
        "exceeded; with -q only a FAIL); with -o DIR: DIR/frames.csv (one line per frame: counts, "
        "confusion, "
        "clusters, nodes, times; missing and extra frames with their status), DIR/report.md "
        "(totals, confusion matrix, the frames that differ and what changed, missing and extra "
        "frames, timing) and DIR/diff_<frame>.png for the --pictures most different frames "
        "(golden classes, points whose class changed in black).\n"
        "Exit status: 0 within the tolerances, 1 outside them, 2 on an error (unreadable or "
        "truncated rawlog, golden rawlog without labels, bad flags).",
        {"travel-regress -i drive.rawlog --golden golden.rawlog -p vlp16",
         "travel-regress -i drive.rawlog --golden golden.rawlog -c robot.yaml -o regress/ -q",
         "travel-regress -i drive.rawlog --golden golden.rawlog -p vlp16 --set "
         "sensor_height=1.2 --set regress.min_class_agreement=99.5 --set "
         "regress.max_split_clusters=3"});
    TCLAP::CmdLine& cmd = line.cmd;
    const travel::apps::CommonFlags flags(line, false, "");
    TCLAP::ValueArg<std::string> golden(
        "", "golden", "The golden labelled rawlog (written by travel-rawlog) to compare with",
        false, "", "GOLDEN.rawlog", cmd);
    TCLAP::ValueArg<std::string> label(
        "", "sensor-label",
        "Only replay LiDAR observations whose whole sensorLabel matches this ECMAScript regex "
        "(as travel-rawlog's --sensor-label; give the golden run's)",
        false, "", "REGEX", cmd);
    TCLAP::SwitchArg ignore_pose("", "ignore-sensor-pose",
                                 "Keep the mount_* parameters of the configuration instead of "
                                 "each observation's sensorPose (as travel-rawlog's)",
                                 cmd);
    TCLAP::ValueArg<int> pictures("", "pictures",
                                  "With -o: bird's-eye PNGs of this many most different frames "
                                  "(default 3)",
                                  false, 3, "N", cmd);
    const travel::apps::PictureFlags picture(cmd);
    const travel::apps::MemoryLimitFlag max_memory(cmd);
    std::optional<int> exit_code = line.parse(argc, argv);
    if (exit_code) return *exit_code ? kError : 0;
    configuration = flags.config.load({}, [&](travel::Config& config) {
        if (label.isSet()) config.filter.sensor_label = label.getValue();
        if (ignore_pose.getValue()) config.filter.use_sensor_pose = false;
    });
    if (flags.config.print(configuration)) return 0;

    o.replay.input = flags.inputPath();
    flags.requireAutoFormat("rawlogs");
    if (!golden.isSet()) throw travel::apps::usageError("missing --golden GOLDEN.rawlog");
    if (pictures.getValue() < 0) throw travel::apps::usageError("--pictures must be >= 0");
    if (pictures.isSet() && !flags.output.isSet())
        throw travel::apps::usageError("--pictures needs -o (the pictures are written there)");
    picture.requirePictures(flags.output.isSet() && pictures.getValue() > 0,
                            "-o and --pictures above 0 (the pictures are drawn)");
    o.golden = golden.getValue();
    o.report_dir = flags.output.isSet() ? flags.output.getValue() : "";
    o.pictures = static_cast<std::size_t>(pictures.getValue());
    o.picture.size_px = picture.sidePixels();
    o.picture.metres_per_pixel = picture.metresPerPixel();
    o.replay.app = "travel-regress";
    o.replay.quiet = flags.quiet();
    o.replay.verbose = flags.verbose();
    o.replay.plain_clouds = false;  // only the labels object is compared
    o.replay.max_memory_mib = max_memory.mib();
    o.command =
        "-i " + o.replay.input + " --golden " + o.golden + " (" + flags.config.describe() + ")";
    return std::nullopt;
}

FrameKey keyOf(const mrpt::obs::CObservation& obs) {
    return {obs.timestamp.time_since_epoch().count(), mrpt::Clock::toDouble(obs.timestamp),
            obs.sensorLabel};
}

/// The comparison of the two streams: pairs frames (libtravel's FramePairing), compares them,
/// keeps the pictures of the most different frames.
class Regression {
  public:
    Regression(const RegressOptions& o) : options_(o), golden_(o.golden) {}

    /// A replayed frame: compared with its golden twin (read ahead as far as needed).
    void addRun(const FrameKey& key, const LabelledFrame& run) {
        LabelledFrame golden;
        if (pairing_.takeGolden(key, golden)) return compare(key, golden, run);
        while (auto labels = golden_.next()) {
            const FrameKey golden_key = keyOf(*labels);
            if (!(golden_key < key) && !(key < golden_key)) return compare(key, *labels, run);
            pairing_.waitGolden(golden_key, std::move(static_cast<LabelledFrame&>(*labels)));
            if (golden_key.ticks > key.ticks) break;  // the golden run is past it: wait
        }
        pairing_.waitRun(key, run);
    }

    /// The rest of the golden rawlog, then what found no twin.
    void finish() {
        while (auto labels = golden_.next()) {
            const FrameKey key = keyOf(*labels);
            LabelledFrame run;
            if (pairing_.takeRun(key, run))
                compare(key, *labels, run);
            else
                report_.addMissing(key);
        }
        for (const auto& [key, frame] : pairing_.waitingGolden()) report_.addMissing(key);
        for (const auto& [key, frame] : pairing_.waitingRun()) report_.addExtra(key);
        if (golden_.count() == 0)
            throw AppError(options_.golden +
                           ": no CObservationTravelLabels (not a labelled rawlog written by "
                           "travel-rawlog?)");
    }

    const travel::RegressionReport& report() const { return report_; }
    /// (index into report().compared(), picture) of the most different frames, worst first.
    std::vector<std::pair<std::size_t, travel::viz::Picture>>& pictures() { return pictures_; }

  private:
    void compare(const FrameKey& key, const LabelledFrame& golden, const LabelledFrame& run) {
        const travel::FrameComparison c = travel::compareFrames(golden, run);
        const std::size_t index = report_.compared().size();
        report_.addCompared(key, c);
        if (options_.replay.verbose)
            std::cerr << "travel-regress: frame " << index << " (" << key.label << ", "
                      << std::fixed << key.seconds << " s): class agreement " << c.class_agreement
                      << " %, cluster agreement " << c.cluster_agreement << " %, nodes changed "
                      << c.changed_nodes << "\n";
        keepPicture(index, c, golden, run);
    }

    void keepPicture(std::size_t index, const travel::FrameComparison& c,
                     const LabelledFrame& golden, const LabelledFrame& run) {
        if (options_.report_dir.empty() || options_.pictures == 0 || c.badness() <= 0 ||
            c.size_mismatch)
            return;
        const auto badness = [&](std::size_t k) {
            return report_.compared()[pictures_[k].first].comparison.badness();
        };
        if (pictures_.size() == options_.pictures && badness(pictures_.size() - 1) >= c.badness())
            return;
        travel::viz::BirdsEyeOptions opt = options_.picture;
        char title[200];
        std::snprintf(title, sizeof title, "frame %zu  %s  %zu of %zu points changed class", index,
                      report_.compared()[index].key.label.c_str(), c.class_changed,
                      c.golden_points);
        opt.title = title;
        auto picture =
            travel::viz::renderClassChanges(golden, travel::classChanges(golden, run), opt);
        if (pictures_.size() == options_.pictures) pictures_.pop_back();
        auto at = pictures_.begin();
        while (at != pictures_.end() &&
               report_.compared()[at->first].comparison.badness() >= c.badness())
            ++at;
        pictures_.insert(at, {index, std::move(picture)});
    }

    const RegressOptions& options_;
    travel_mrpt::TravelLabelsReader golden_;
    travel::FramePairing<LabelledFrame> pairing_;
    travel::RegressionReport report_;
    std::vector<std::pair<std::size_t, travel::viz::Picture>> pictures_;
};

void writeOutputs(const RegressOptions& o, travel::Config& configuration, Regression& regression) {
    const fs::path dir(o.report_dir);
    std::vector<std::pair<std::size_t, std::string>> names;
    mrpt::img::CImage image;
    for (const auto& [index, picture] : regression.pictures()) {
        char name[48];
        std::snprintf(name, sizeof name, "diff_%06zu.png", index);
        travel_mrpt::toImage(picture, image);
        travel_mrpt::savePicture(image, (dir / name).string());
        names.emplace_back(index, name);
    }
    const auto write = [&](const std::string& name, const auto& fill) {
        travel::writeThroughPartFile((dir / name).string(), fill);
    };
    write("frames.csv", [&](std::ostream& f) { regression.report().writeCsv(f); });
    write("report.md", [&](std::ostream& f) {
        regression.report().writeMarkdown(f, "travel-regress: " + o.command, configuration.regress,
                                          names);
    });
}

int run(int argc, char** argv) {
    RegressOptions o;
    travel::Config configuration;
    if (const auto code = parseCommandLine(argc, argv, o, configuration)) return *code;
    const std::string limit_note = travel::apps::applyMemoryLimit(o.replay.max_memory_mib);
    if (!limit_note.empty() && !o.replay.quiet)
        std::cerr << "travel-regress: note: " << limit_note << "\n";
    // The report folder first: a wrong -o fails before the replay.
    if (!o.report_dir.empty())
        travel::apps::createParentFolder((fs::path(o.report_dir) / "report.md").string());
    travel_mrpt::registerClasses();  // the golden rawlog's CObservationTravelLabels
    Regression regression(o);        // opens the golden rawlog: errors before the replay
    travel_mrpt::RawlogReader reader(o.replay.input);
    travel::apps::RawlogSegmenter segmenter(o.replay,
                                            travel::apps::filterOptionsFrom(configuration));
    travel::apps::ProgressLine progress(
        "travel-regress", 0, travel::apps::verbosityFrom(o.replay.quiet, o.replay.verbose));
    const auto attached = segmenter.attach(progress);
    std::vector<mrpt::obs::CObservation::Ptr> added;
    const auto compareAdded = [&] {
        for (const auto& obs : added)
            if (auto labels = std::dynamic_pointer_cast<travel_mrpt::CObservationTravelLabels>(obs))
                regression.addRun(keyOf(*labels), *labels);
    };
    while (auto record = reader.next()) {
        travel::apps::throwIfInterrupted();
        const long index = reader.index() - 1;
        segmenter.startRecord();
        added.clear();
        if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(record)) {
            for (const auto& obs : *sf)
                if (obs) segmenter.processObservation(*obs, index, added);
        } else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(record)) {
            segmenter.processObservation(*obs, index, added);
        } else {
            segmenter.processMotion(*record);
        }
        compareAdded();
        progress.update(segmenter.totals().frames, reader.fractionRead());
    }
    regression.finish();
    progress.finish();

    const travel::RegressionVerdict verdict = regression.report().verdict(configuration.regress);
    if (!o.report_dir.empty()) writeOutputs(o, configuration, regression);
    // -q: nothing but errors, and the verdict when it fails (the answer a CI log needs).
    if (!o.replay.quiet || !verdict.passed) std::cout << "travel-regress: " << verdict.line << "\n";
    if (!o.replay.quiet && !o.report_dir.empty())
        std::cout << "  report: " << (fs::path(o.report_dir) / "report.md").string()
                  << ", per-frame CSV: " << (fs::path(o.report_dir) / "frames.csv").string()
                  << "\n";
    return verdict.passed ? kPass : kFail;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-regress", run, argc, argv, kError);
}
