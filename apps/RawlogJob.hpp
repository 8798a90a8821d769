// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-rawlog's job, apart from its command line: the options, the per-record work
// (RawlogSegmenter: the filter, the added observations, the notes), the output files besides the
// rawlog (per-frame CSV, label reference, bird's-eye PNG and PLY) and the summary. Errors:
// every failure becomes one line "travel-rawlog: error: <file>[: record N]: <what>".
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CSerializable.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "MemoryLimit.hpp"
#include "OutputFolder.hpp"
#include "Progress.hpp"
#include "travel/Pipeline.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/LabelledOutputs.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace travel::apps {

using mrpt::obs::CObservation;
using travel::PointClass;

inline std::string where(const std::string& file, long record = -1) {
    return record < 0 ? file : travel_mrpt::RawlogReader::where(file, record);
}

/// The valid points of a frame as an ASCII PLY (x y z red green blue), in the aligned frame, in
/// the bird's-eye colours.
void writePly(const std::string& path, const travel::AlignedCloud& aligned,
              const travel::Result& result);

/// Segments frame.cloud into frame.result with `pipeline`; the milliseconds it took.
inline double segmentFrame(travel::Pipeline& pipeline, travel_mrpt::TravelFrame& frame,
                           const travel::FrameInput& input) {
    const auto start = std::chrono::steady_clock::now();
    pipeline.process(frame.cloud, input, frame.result);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

struct Totals {
    std::size_t frames = 0, points = 0, skipped = 0, clusters = 0, levelled = 0, deskewed = 0;
    /// --track: frames tracked (ego-motion from poses), tracked / moving clusters, tracks.
    std::size_t tracked = 0, tracked_with_poses = 0, tracked_clusters = 0, moving_clusters = 0;
    uint32_t tracks = 0;  ///< the largest track id (ids are 1, 2, ... in confirmation order)
    std::array<std::size_t, 4> per_class{};
    std::vector<double> process_ms, convert_ms;
};

/// The per-frame CSV (--csv); nothing when the path is empty.
class CsvLog {
  public:
    explicit CsvLog(const std::string& path);
    void add(std::size_t frame, const mrpt::obs::CObservation& obs,
             const travel_mrpt::TravelFrame& f);
    void finish();

  private:
    std::string path_;
    std::ofstream file_;
};

/// The label reference file (--label-reference), written frame by frame; nothing when the path
/// is empty.
class ReferenceLog {
  public:
    explicit ReferenceLog(const std::string& path);
    void add(const travel::Result& r);
    void finish();

  private:
    std::string path_;
    std::ofstream file_;
    std::size_t frames_ = 0;
};

struct Options {
    std::optional<int> exit_code;       // set when the command line says stop (--help, error)
    std::string app = "travel-rawlog";  // the notes' prefix (travel-regress replays too)
    std::string input, output, sensor_label_regex, png_prefix, csv, label_reference;
    std::string pcap_model, pcap_calibration;  // .pcap inputs
    bool plain_clouds = true;
    bool quiet = false, verbose = false;
    bool ignore_sensor_pose = false;
    int png_size = 800;
    double png_metres_per_pixel = 0.075;
    std::size_t max_memory_mib = travel::apps::kDefaultMemoryLimitMiB;
    unsigned jobs = 1;  ///< -j: segmentation threads (records are read and written in order)
};

/// The filter's options from a loaded configuration: its travel, filter and tracking sections.
inline travel_mrpt::TravelFilterOptions filterOptionsFrom(const travel::Config& config) {
    travel_mrpt::TravelFilterOptions options;
    options.fromConfig(config);
    return options;
}

class RawlogSegmenter {
  public:
    RawlogSegmenter(const Options& options, const travel_mrpt::TravelFilterOptions& filter_options)
        : options_(options),
          label_filter_(filter_options.sensor_label),
          notes_(options.app, travel::apps::verbosityFrom(options.quiet, options.verbose)),
          filter_(filter_options),
          csv_(options.csv),
          reference_(options.label_reference) {
        // Notes from the filter (no motion data, ...) once each, in our own format.
        notes_.listen(filter_);
        if (!options.png_prefix.empty()) {
            createParentFolder(options.png_prefix + "_x");
            birds_eye_.size_px = options.png_size;
            birds_eye_.metres_per_pixel = options.png_metres_per_pixel;
        }
    }

    /// Notes and warnings go through `progress` while the returned object lives (declare it
    /// after `progress`, so that it goes first).
    [[nodiscard]] Notes::Attached attach(ProgressLine& progress) {
        return Notes::Attached(notes_, progress);
    }

    /// Motion records (IMU, odometry, odometry actions) go to the filter's motion estimate.
    bool processMotion(const mrpt::serialization::CSerializable& record) {
        return motion_.process(record);
    }

    /// Processes one observation of the record, appending the outputs to `added`.
    void processObservation(const CObservation& obs, long record,
                            std::vector<CObservation::Ptr>& added) {
        if (!prepare(obs, record, frame_, job_)) return;
        const double segment_ms = segmentFrame(*job_.pipeline, frame_, job_.input);
        complete(obs, record, frame_, job_, job_.pipeline->aligned(), segment_ms, added);
    }

    /// processObservation() in three steps (-j N): prepare() in record order (motion records,
    /// the checks and notes, the conversion; true when `frame` is to be segmented with
    /// job.pipeline or a settled copy of it), the segmentation on any thread, then complete()
    /// in record order with the aligned cloud of that segmentation (kept alive by the caller).
    bool prepare(const CObservation& obs, long record, travel_mrpt::TravelFrame& frame,
                 travel_mrpt::TravelFilter::FrameJob& job) {
        if (processMotion(obs) || !travel_mrpt::isLidarObservation(obs)) return false;
        std::string why_not;
        if (filter_.prepare(obs, frame, job, &why_not)) return true;
        if (!std::regex_match(obs.sensorLabel, label_filter_)) {
            noteOnce("ignored (does not match the sensor label regex): " + obs.sensorLabel);
            return false;
        }
        ++totals_.skipped;
        notes_.oncePerReason(where(options_.input, record), "skipped: " + why_not);
        return false;
    }
    void complete(const CObservation& obs, long record, travel_mrpt::TravelFrame& frame,
                  const travel_mrpt::TravelFilter::FrameJob& job,
                  const travel::AlignedCloud& aligned, double segment_ms,
                  std::vector<CObservation::Ptr>& added) {
        filter_.complete(frame, job, aligned, segment_ms);
        const travel::Result& result = frame.result;
        if (result.labels.size() != frame.cloud.size())
            throw AppError(where(options_.input, record) + ": pipeline returned " +
                           std::to_string(result.labels.size()) + " labels for " +
                           std::to_string(frame.cloud.size()) + " points");

        outputs_.add(obs, frame, options_.plain_clouds, added);

        const std::size_t index = totals_.frames++;
        totals_.points += frame.cloud.size();
        for (std::size_t c = 0; c < 4; ++c) totals_.per_class[c] += result.class_counts[c];
        totals_.clusters += result.clusters.size();
        totals_.levelled += frame.levelled;
        totals_.deskewed += frame.deskewed;
        if (frame.tracked) addTracking(frame);
        totals_.process_ms.push_back(frame.process_ms);
        totals_.convert_ms.push_back(frame.convert_ms);
        csv_.add(index, obs, frame);
        reference_.add(result);
        if (result.mount && !options_.quiet)
            say(mountNoteLine(options_.app, obs.sensorLabel, result.mount));
        if (!options_.png_prefix.empty() && frame.aligned) writePictures(index, obs, frame);
    }

    /// Outputs of an earlier run (<label>_travel, <label>_ground ... of a label we process
    /// now) are dropped: they are regenerated, and keeping them would duplicate the labels.
    bool isStaleOutput(const CObservation& obs) {
        if (!travel_mrpt::isTravelOutput(obs)) return false;
        const std::string base = travel_mrpt::travelOutputSource(obs);
        if (!std::regex_match(base, label_filter_)) return false;
        noteOnce("replacing the TRAVEL outputs of an earlier run: " + base + "_*");
        return true;
    }

    void startRecord() { outputs_.startRecord(); }
    void finish() {
        csv_.finish();
        reference_.finish();
    }
    const Totals& totals() const { return totals_; }

  private:
    void writePictures(std::size_t index, const CObservation& obs,
                       const travel_mrpt::TravelFrame& frame) {
        const travel::AlignedCloud& aligned = *frame.aligned;
        const travel::Result& result = frame.result;
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "_%06zu", index);
        const std::string stem = options_.png_prefix + suffix;
        const auto total = std::max<std::size_t>(1, frame.cloud.size());
        char title[256];
        std::snprintf(title, sizeof title,
                      "frame %zu  %s  %zu pts  ground %.0f%%  non-ground %.0f%%  %zu clusters",
                      index, obs.sensorLabel.c_str(), frame.cloud.size(),
                      100.0 * result.count(PointClass::Ground) / total,
                      100.0 * result.count(PointClass::NonGround) / total, result.clusters.size());
        birds_eye_.title = title;
        travel_mrpt::renderBirdsEye(aligned, result.labels, result.cluster_id, &result.terrain,
                                    birds_eye_, image_);
        travel_mrpt::savePicture(image_, stem + ".png");
        travel::apps::writePly(stem + ".ply", aligned, result);
    }

    void addTracking(const travel_mrpt::TravelFrame& frame) {
        ++totals_.tracked;
        totals_.tracked_with_poses += frame.egoFromPoses;
        for (const travel::ClusterSummary& c : frame.result.clusters) {
            totals_.tracked_clusters += c.track_id != 0;
            totals_.moving_clusters += c.moving;
            totals_.tracks = std::max(totals_.tracks, c.track_id);
        }
    }
    void noteOnce(const std::string& note) { notes_.once(note); }
    // On a line of its own above the progress line, once one is attached.
    void say(const std::string& line) { notes_.say(line); }

    const Options& options_;
    std::regex label_filter_;
    Notes notes_;  // before filter_, which sends it notes
    travel_mrpt::TravelFilter filter_;
    travel_mrpt::RawlogMotion motion_{filter_};
    CsvLog csv_;
    ReferenceLog reference_;
    travel_mrpt::BirdsEyeOptions birds_eye_;
    mrpt::img::CImage image_;  // reused across frames
    travel_mrpt::LabelledOutputPool outputs_;
    Totals totals_;
    travel_mrpt::TravelFrame frame_;  // reused across frames (processObservation)
    travel_mrpt::TravelFilter::FrameJob job_;
};

/// The summary on stdout.
void printSummary(const Options& o, const Totals& t, long records, double seconds);

}  // namespace travel::apps
