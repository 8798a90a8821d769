// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-rawlog: TRAVEL ground segmentation and object clustering of the LiDAR observations of
// an MRPT rawlog, through travel_mrpt::TravelFilter. Streams the input (observation format or
// SensoryFrame/action format, one record at a time), feeds IMU / odometry / odometry actions to
// the filter's motion estimate (attitude levelling, deskew), copies every record to the output
// rawlog and adds, per processed observation, one travel_mrpt::CObservationTravelLabels (shown
// in colour by RawLogViewer with the plugin) and one plain CObservationPointCloud per class (for
// readers without the plugin). Optionally writes a per-frame CSV, bird's-eye PNGs, coloured
// PLYs and a label reference file. See --help for the details of each output.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "Interrupt.hpp"
#include "MemoryLimit.hpp"
#include "Progress.hpp"
#include "RawlogJob.hpp"
#include "travel/ConfigFields.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/eval/Metrics.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel_mrpt/Attitude.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/GzFileOutput.hpp"
#include "travel_mrpt/LabelledOutputs.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#ifdef TRAVEL_WITH_PCAP
#include "travel_mrpt/RecordReader.hpp"
#endif
#include "travel_mrpt/Registration.hpp"
#include "travel_mrpt/TravelFilter.hpp"

using mrpt::obs::CObservation;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CSensoryFrame;
using travel::PointClass;
using Clock = std::chrono::steady_clock;

namespace {

using travel::apps::AppError;
using travel::apps::Options;
using travel::apps::RawlogSegmenter;

// ------------------------------------------------------------------------------------------
// Command line.

/// The options, and in `configuration` the parameters: -p, -c, each --set, then --sensor-label,
/// --ignore-sensor-pose and --track.
Options parseCommandLine(int argc, char** argv, travel::Config& configuration) {
    travel::apps::CommandLine line(
        "travel-rawlog",
        "TRAVEL traversable-ground segmentation and object clustering of the 3-D LiDAR "
        "observations of an MRPT rawlog (CObservationVelodyneScan, CObservationRotatingScan, "
        "CObservationPointCloud, CObservation3DRangeScan).\n"
        "-i: the input rawlog (.rawlog, gzip or plain) or Velodyne capture (.pcap, or a file "
        "starting with the libpcap magic number; read through MRPT's CVelodyneScanner, one "
        "CObservationVelodyneScan labelled VELODYNE per full rotation). -o: OUT.rawlog, "
        "gzip-compressed, written to OUT.rawlog.part and renamed when complete.\n"
        "Outputs:\n"
        " (1) OUT.rawlog: every input record, unchanged, in the input's format; after each "
        "processed observation (in SensoryFrame rawlogs: inside its SensoryFrame) a "
        "travel_mrpt::CObservationTravelLabels labelled <label>_travel (every point of the "
        "source in the sensor frame with its class and cluster id, the cluster boxes and the "
        "terrain model; RawLogViewer -l libtravel_mrpt_plugin.so shows it in colour, "
        "rawlog-edit -p describes it) and, unless --no-plain-clouds, three "
        "CObservationPointCloud (CPointsMapXYZI, same sensorPose and timestamp, original "
        "intensity) labelled <label>_ground, <label>_nonground and <label>_outlier for readers "
        "without the plugin. Invalid points (no return, out of range) are in none of the "
        "three.\n"
        " (2) --csv: one line per frame: index, timestamp, label, point counts per class, "
        "clusters, whether the frame was levelled / deskewed, and milliseconds per stage.\n"
        " (3) --png: PREFIX_<frame>.png (--mpp, --size), a bird's-eye view centred on the sensor "
        "(up = forward; "
        "ground green, outliers blue, each cluster its own colour, unclustered non-ground grey, "
        "traversable tri-grid nodes shaded), and PREFIX_<frame>.ply, the valid points in the "
        "same colours (ASCII PLY: x y z red green blue, sensor-centred, levelled frame) for "
        "CloudCompare/MeshLab.\n"
        " (4) --label-reference: the class and cluster id of every point of every frame as text "
        "(format in apps/LabelReference.hpp).\n"
        " (5) a summary on stdout.\n"
        "Motion: CObservationIMU (attitude, gyro), CObservationOdometry and "
        "CActionRobotMovement2D (velocities) records are fed to the filter in rawlog order; a "
        "LiDAR frame is levelled with the robot's roll/pitch and deskewed with the sensor's "
        "velocity when recent motion data exists (config keys use_robot_attitude, "
        "velocity_source, max_motion_age, deskew; see share/configs/travel_filter_example.yaml)."
        "\n"
        "Parameters: HDL-64E/KITTI defaults, then --preset, then --config (libtravel parameters "
        "and the filter keys), then each --set. The mount_{roll,pitch,yaw}_deg parameters are "
        "taken from each observation's sensorPose (unless --ignore-sensor-pose). Exit status: 0 "
        "on success, 1 on any error.",
        {"travel-rawlog -i drive.rawlog -o drive_travel.rawlog -p vlp16",
         "travel-rawlog -i capture.pcap -p hdl32 -o capture.rawlog --csv frames.csv",
         "travel-rawlog -i drive.rawlog -o out.rawlog --png views/frame --mpp 0.05 -q"});
    TCLAP::CmdLine& cmd = line.cmd;
    const travel::apps::CommonFlags flags(line, false, "");
    TCLAP::ValueArg<std::string> label(
        "", "sensor-label",
        "Only process LiDAR observations whose whole sensorLabel matches this ECMAScript regex "
        "(the filter key sensor_label; default: the config's, else .*). Our own outputs "
        "(<label>_travel, _ground, _nonground, _outlier) are never re-processed; when the "
        "input already has them (an earlier output) they are replaced.",
        false, "", "REGEX", cmd);
    TCLAP::ValueArg<std::string> pcap_model(
        "", "pcap-model",
        "Velodyne model of a .pcap input: VLP16, HDL32 or HDL64 (default: from --preset "
        "vlp16/hdl32/hdl64)",
        false, "", "MODEL", cmd);
    TCLAP::ValueArg<std::string> pcap_calibration(
        "", "pcap-calibration",
        "The sensor's own calibration XML (Velodyne db.xml) for a .pcap input (default: the "
        "model's built-in table; MRPT 2.5.8 has none for HDL64, so HDL-64E captures need it)",
        false, "", "FILE.xml", cmd);
    TCLAP::ValueArg<std::string> png("", "png",
                                     "Write PREFIX_<frame>.png and PREFIX_<frame>.ply per frame "
                                     "(directories are created)",
                                     false, "", "PREFIX", cmd);
    const travel::apps::PictureFlags picture(cmd);
    TCLAP::ValueArg<std::string> csv("", "csv", "Write per-frame counts and timings to this CSV",
                                     false, "", "FILE", cmd);
    TCLAP::ValueArg<std::string> reference(
        "", "label-reference",
        "Write the class and cluster id of every point of every frame to this text file", false, "",
        "FILE", cmd);
    TCLAP::SwitchArg no_plain("", "no-plain-clouds",
                              "Do not add the three per-class CObservationPointCloud", cmd);
    TCLAP::SwitchArg ignore_pose("", "ignore-sensor-pose",
                                 "Keep the mount_* parameters of the configuration instead of "
                                 "each observation's sensorPose",
                                 cmd);
    TCLAP::SwitchArg track(
        "", "track",
        "Track the clusters across frames (the filter key track_objects; parameters: section "
        "tracking): the labelled observations carry track ids, velocities and moving flags "
        "(RawLogViewer colours each track alike in every frame and draws velocity arrows). "
        "Ego-motion from the rawlog's odometry / robot poses, else from registering "
        "consecutive scans",
        cmd);
    const travel::apps::MemoryLimitFlag max_memory(cmd);
    const travel::apps::JobsFlag jobs(
        line, "LiDAR frames",
        "one pipeline each (records are read, and motion data applied, in order on the main "
        "thread; tracking and the outputs too)");
    Options o;
    o.exit_code = line.parse(argc, argv);
    if (o.exit_code) return o;
    if (!flags.config.print_config.arg.getValue()) {  // --print-config needs no -i / -o
        o.input = flags.inputPath();
        o.output = flags.outputPath();
    }
    flags.requireAutoFormat("rawlogs and Velodyne captures");
    o.sensor_label_regex = label.getValue();
    const std::string preset = flags.config.preset.getValue();
    o.pcap_model = pcap_model.getValue().empty() ? preset : pcap_model.getValue();
    o.pcap_calibration = pcap_calibration.getValue();
    o.png_prefix = png.getValue();
    picture.requirePictures(!o.png_prefix.empty(), "--png");
    o.png_metres_per_pixel = picture.metresPerPixel();
    o.png_size = picture.sidePixels();
    o.csv = csv.getValue();
    o.quiet = flags.quiet();
    o.verbose = flags.verbose();
    o.ignore_sensor_pose = ignore_pose.getValue();
    o.label_reference = reference.getValue();
    o.plain_clouds = !no_plain.getValue();
    o.max_memory_mib = max_memory.mib();
    o.jobs = jobs.count();

    configuration = flags.config.load({}, [&](travel::Config& config) {
        if (!o.sensor_label_regex.empty()) config.filter.sensor_label = o.sensor_label_regex;
        if (o.ignore_sensor_pose) config.filter.use_sensor_pose = false;
        if (track.getValue()) config.filter.track_objects = true;
    });
    if (flags.config.print(configuration)) o.exit_code = 0;
    return o;
}

#ifdef TRAVEL_WITH_PCAP
travel_mrpt::RecordReader openInput(const Options& o) {
    travel_mrpt::PcapSourceOptions pcap;
    pcap.model = o.pcap_model;
    pcap.calibration_file = o.pcap_calibration;
    if (travel_mrpt::isPcapFile(o.input) && travel_mrpt::velodyneModelName(pcap.model).empty())
        throw AppError(o.input + ": a Velodyne capture needs its model: --pcap-model " +
                       "VLP16|HDL32|HDL64 or --preset vlp16|hdl32|hdl64" +
                       (pcap.model.empty() ? "" : " (not '" + pcap.model + "')"));
    if (travel_mrpt::isPcapFile(o.input) && travel_mrpt::velodyneModelName(pcap.model) == "HDL64" &&
        pcap.calibration_file.empty())
        throw AppError(o.input + ": an HDL-64E capture needs the sensor's calibration: " +
                       "--pcap-calibration db.xml (MRPT 2.5.8 has no usable HDL64 default)");
    return travel_mrpt::RecordReader(o.input, pcap);
}
#else
travel_mrpt::RawlogReader openInput(const Options& o) {
    return travel_mrpt::RawlogReader(o.input);  // built without mrpt-hwdrivers: no .pcap
}
#endif

/// -j 1: each record read, segmented and written before the next.
template <class Reader>
void replayInOneThread(Reader& reader, RawlogSegmenter& segmenter,
                       mrpt::serialization::CArchive& out, travel::apps::ProgressLine& progress) {
    std::vector<CObservation::Ptr> added;
    while (auto record = reader.next()) {
        travel::apps::throwIfInterrupted();
        const long index = reader.index() - 1;
        segmenter.startRecord();
        added.clear();
        if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(record)) {
            for (auto it = sf->begin(); it != sf->end();)
                it = *it && segmenter.isStaleOutput(**it) ? sf->erase(it) : std::next(it);
            // The new clouds join the SensoryFrame of their source observation.
            for (const auto& obs : *sf)
                if (obs) segmenter.processObservation(*obs, index, added);
            for (const auto& obs : added) sf->insert(obs);
            out << *sf;
        } else if (auto obs = std::dynamic_pointer_cast<CObservation>(record)) {
            if (segmenter.isStaleOutput(*obs)) continue;
            segmenter.processObservation(*obs, index, added);
            out << *obs;
            for (const auto& extra : added) out << *extra;
        } else {
            segmenter.processMotion(*record);  // odometry actions
            out << *record;                    // copied unchanged
        }
        progress.update(segmenter.totals().frames, reader.fractionRead());
    }
}

/// One record in flight under -j N: its LiDAR observations, each with its frame (reused from
/// record to record) and the aligned cloud of its segmentation.
struct RecordSlot {
    struct Item {
        CObservation* obs = nullptr;  // owned by `record`
        travel_mrpt::TravelFrame frame;
        travel_mrpt::TravelFilter::FrameJob job;
        /// The settled pipeline the workers copy (made on the main thread, read-only after).
        std::shared_ptr<const travel::Pipeline> origin;
        travel::AlignedCloud aligned;
        double segment_ms = 0;
    };
    mrpt::serialization::CSerializable::Ptr record;
    long index = 0;
    double fraction_read = 0;
    std::vector<Item> items;  // grows to the most LiDARs of a record, then reused
    std::size_t used = 0;
    Item& add() {
        if (used == items.size()) items.emplace_back();
        return items[used++];
    }
};

/// -j N: records are read, and their motion data and conversion done, in order on this
/// thread; the frames are segmented on N workers, each with its own copy of every sensor's
/// pipeline (once its mount is settled: until then frames are segmented here, in order);
/// tracking, outputs and writing happen here again, in record order. The output is the same as
/// with -j 1 (apps.travel_rawlog_jobs compares them).
template <class Reader>
void replayOnWorkers(Reader& reader, RawlogSegmenter& segmenter, mrpt::serialization::CArchive& out,
                     travel::apps::ProgressLine& progress, unsigned jobs) {
    // Worker w's pipelines: per sensor label, the copy and the settled pipeline it came from.
    struct WorkerPipeline {
        const travel::Pipeline* origin = nullptr;
        std::unique_ptr<travel::Pipeline> pipeline;
    };
    std::vector<std::map<std::string, WorkerPipeline>> worker_pipelines(jobs);
    const auto segment = [&](unsigned w, RecordSlot& slot) {
        for (std::size_t k = 0; k < slot.used; ++k) {
            RecordSlot::Item& item = slot.items[k];
            WorkerPipeline& mine = worker_pipelines[w][item.frame.sensorLabel];
            if (mine.origin != item.origin.get()) {  // first frame, or a new mount
                mine.pipeline = std::make_unique<travel::Pipeline>(item.origin->settledCopy());
                mine.origin = item.origin.get();
            }
            item.segment_ms =
                travel::apps::segmentFrame(*mine.pipeline, item.frame, item.job.input);
            item.aligned = mine.pipeline->aligned();  // the pipeline moves on to other frames
        }
    };
    std::vector<CObservation::Ptr> added;
    const auto consume = [&](RecordSlot& slot) {
        travel::apps::throwIfInterrupted();
        segmenter.startRecord();
        added.clear();
        std::size_t k = 0;
        const auto completeNext = [&](const CObservation& obs) {
            if (k < slot.used && slot.items[k].obs == &obs) {
                RecordSlot::Item& item = slot.items[k++];
                segmenter.complete(obs, slot.index, item.frame, item.job, item.aligned,
                                   item.segment_ms, added);
            }
        };
        if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(slot.record)) {
            for (const auto& obs : *sf)
                if (obs) completeNext(*obs);
            for (const auto& obs : added) sf->insert(obs);
            out << *sf;
        } else if (auto obs = std::dynamic_pointer_cast<CObservation>(slot.record)) {
            completeNext(*obs);
            out << *obs;
            for (const auto& extra : added) out << *extra;
        } else {
            out << *slot.record;
        }
        slot.record.reset();
        progress.update(segmenter.totals().frames, slot.fraction_read);
    };

    // The settled pipeline of each sensor label that the workers copy, per generation.
    struct Origin {
        unsigned generation = 0;
        std::shared_ptr<const travel::Pipeline> pipeline;
    };
    std::map<std::string, Origin> origins;
    travel::apps::OrderedSlots<RecordSlot> pool(jobs, segment);
    while (auto record = reader.next()) {
        travel::apps::throwIfInterrupted();
        RecordSlot& slot = pool.next(consume);
        slot.record = record;
        slot.index = reader.index() - 1;
        slot.fraction_read = reader.fractionRead();
        slot.used = 0;
        const auto prepare = [&](CObservation& obs) {
            RecordSlot::Item& item = slot.add();
            if (segmenter.prepare(obs, slot.index, item.frame, item.job))
                item.obs = &obs;
            else
                --slot.used;
        };
        if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(record)) {
            for (auto it = sf->begin(); it != sf->end();)
                it = *it && segmenter.isStaleOutput(**it) ? sf->erase(it) : std::next(it);
            for (const auto& obs : *sf)
                if (obs) prepare(*obs);
        } else if (auto obs = std::dynamic_pointer_cast<CObservation>(record)) {
            if (segmenter.isStaleOutput(*obs)) {
                slot.record.reset();
                continue;  // the slot stays free
            }
            prepare(*obs);
        } else {
            segmenter.processMotion(*record);  // odometry actions
        }
        // A mount still being settled: frames of that sensor depend on the ones before, so
        // they are segmented here, in order (the workers hold no copy of that pipeline yet).
        // Records without a LiDAR frame need no worker either.
        bool here = false;
        for (std::size_t k = 0; k < slot.used; ++k)
            here = here || !slot.items[k].job.pipeline->mountSettled();
        if (here || slot.used == 0) {
            for (std::size_t k = 0; k < slot.used; ++k) {
                RecordSlot::Item& item = slot.items[k];
                item.segment_ms =
                    travel::apps::segmentFrame(*item.job.pipeline, item.frame, item.job.input);
                item.aligned = item.job.pipeline->aligned();
            }
            pool.submitDone();
            continue;
        }
        for (std::size_t k = 0; k < slot.used; ++k) {
            RecordSlot::Item& item = slot.items[k];
            Origin& origin = origins[item.frame.sensorLabel];
            if (!origin.pipeline || origin.generation != item.job.generation) {
                origin.pipeline =
                    std::make_shared<const travel::Pipeline>(item.job.pipeline->settledCopy());
                origin.generation = item.job.generation;
            }
            item.origin = origin.pipeline;
        }
        pool.submit();
    }
    pool.drain(consume);
}

int run(int argc, char** argv) {
    travel::Config configuration;
    const Options options = parseCommandLine(argc, argv, configuration);
    if (options.exit_code) return *options.exit_code;
    const std::string limit_note = travel::apps::applyMemoryLimit(options.max_memory_mib);
    if (!limit_note.empty() && !options.quiet)
        std::cerr << "travel-rawlog: note: " << limit_note << "\n";
    // Our own classes (CObservationTravelLabels) must be readable: inputs may be earlier outputs.
    travel_mrpt::registerClasses();
    const travel_mrpt::TravelFilterOptions filter_options =
        travel::apps::filterOptionsFrom(configuration);
    travel::apps::requireFileName("-o", options.output);
    // The rawlog is written as OUT.rawlog.part first (travel::PartFile): that name must not be
    // the input either (it is emptied when opened, and removed when the run fails).
    travel::apps::checkOutputsApart(
        {{"-i", options.input}}, {{"-o", options.output},
                                  {"-o (its part file)", travel::PartFile::partOf(options.output)},
                                  {"--csv", options.csv},
                                  {"--label-reference", options.label_reference}});

    auto reader = openInput(options);
    // The CSV and the label reference are written in place (RawlogSegmenter's constructor
    // creates them): an interrupted or failed run, the constructor's included, removes them, as
    // it removes the partial rawlog (OUT.rawlog.part).
    travel::apps::PartialOutput csv_guard(options.csv), reference_guard(options.label_reference);
    RawlogSegmenter segmenter(options, filter_options);
    travel::apps::createParentFolder(options.output);
    travel::PartFile output(options.output);  // never a half-written rawlog under the name
    travel_mrpt::GzFileOutput out_file(output.part(), output.path());
    auto out = mrpt::serialization::archiveFrom(out_file);

    const auto start = Clock::now();
    travel::apps::ProgressLine progress(
        "travel-rawlog", 0, travel::apps::verbosityFrom(options.quiet, options.verbose));
    const auto attached = segmenter.attach(progress);
    try {
        if (options.jobs <= 1)
            replayInOneThread(reader, segmenter, out, progress);
        else
            replayOnWorkers(reader, segmenter, out, progress, options.jobs);
        segmenter.finish();
        progress.finish();
    } catch (...) {
        progress.finish();
        throw;  // out_file closes, then `output` removes the part file
    }
    out_file.close();
    output.commit();

    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!options.quiet) printSummary(options, segmenter.totals(), reader.index(), seconds);
    if (segmenter.totals().frames == 0)
        throw AppError(options.input +
                       ": no LiDAR observation processed (check --sensor-label; "
                       "the output rawlog is a plain copy)");
    csv_guard.commit();
    reference_guard.commit();
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-rawlog", run, argc, argv);
}
