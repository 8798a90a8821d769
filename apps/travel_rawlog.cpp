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
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
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
#include "LabelReference.hpp"
#include "MemoryLimit.hpp"
#include "travel/ConfigFields.hpp"
#include "travel/Errors.hpp"
#include "travel/Metrics.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel_mrpt/Attitude.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/Registration.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace fs = std::filesystem;
using mrpt::obs::CObservation;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CSensoryFrame;
using travel::PointClass;
using Clock = std::chrono::steady_clock;

namespace {

// ------------------------------------------------------------------------------------------
// Errors: every failure becomes one line "travel-rawlog: error: <file>[: record N]: <what>".

using travel::apps::oneLine;

/// A failure with the file (and record) it concerns; main() prints it on one line.
struct AppError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string where(const std::string& file, long record = -1) {
    return record < 0 ? file : file + ": record " + std::to_string(record);
}

// ------------------------------------------------------------------------------------------
// Command line.

struct Options {
    std::optional<int> exit_code;  // set when the command line says stop (--help, error)
    bool print_config = false;
    std::string input, output, config, preset, sensor_label_regex, png_prefix, csv, label_reference;
    bool plain_clouds = true;
    std::vector<std::string> overrides;
    bool quiet = false;
    bool ignore_sensor_pose = false;
    int png_size = 800;
    double png_metres_per_pixel = 0.075;
    std::size_t max_memory_mib = travel::apps::kDefaultMemoryLimitMiB;
};

std::string presetList() {
    try {
        std::string list;
        for (const auto& name : travel::availablePresets())
            list += (list.empty() ? "" : ", ") + name;
        return list.empty() ? "none found" : list;
    } catch (const std::exception&) {
        return "none found";
    }
}

Options parseCommandLine(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "TRAVEL traversable-ground segmentation and object clustering of the 3-D LiDAR "
        "observations of an MRPT rawlog (CObservationVelodyneScan, CObservationRotatingScan, "
        "CObservationPointCloud, CObservation3DRangeScan).\n"
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
        " (3) --png: PREFIX_<frame>.png, a bird's-eye view centred on the sensor (up = forward; "
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
        ' ', "0.1");
    TCLAP::ValueArg<std::string> input("i", "input", "Input rawlog (.rawlog, gzip or plain)", true,
                                       "", "IN.rawlog", cmd);
    TCLAP::ValueArg<std::string> output("o", "output",
                                        "Output rawlog (gzip-compressed); written to OUT.part "
                                        "and renamed when complete",
                                        true, "", "OUT.rawlog", cmd);
    TCLAP::ValueArg<std::string> config(
        "", "config",
        "YAML (.yaml/.yml) or ini (.ini/.cfg, section [travel]) file of libtravel parameters "
        "and filter keys (see share/presets/*.yaml, share/configs/*), applied after --preset",
        false, "", "FILE", cmd);
    TCLAP::ValueArg<std::string> preset(
        "", "preset",
        "Start from this sensor preset instead of the HDL-64E defaults (" + presetList() + ")",
        false, "", "NAME", cmd);
    TCLAP::MultiArg<std::string> set("", "set",
                                     "Override one parameter or filter key (repeatable), "
                                     "applied last, e.g. --set sensor_height=2.24",
                                     false, "KEY=VALUE", cmd);
    TCLAP::ValueArg<std::string> label(
        "", "sensor-label",
        "Only process LiDAR observations whose whole sensorLabel matches this ECMAScript regex "
        "(the filter key sensor_label; default: the config's, else .*). Our own outputs "
        "(<label>_travel, _ground, _nonground, _outlier) are never re-processed; when the "
        "input already has them (an earlier output) they are replaced.",
        false, "", "REGEX", cmd);
    TCLAP::ValueArg<std::string> png("", "png",
                                     "Write PREFIX_<frame>.png and PREFIX_<frame>.ply per frame "
                                     "(directories are created)",
                                     false, "", "PREFIX", cmd);
    TCLAP::ValueArg<double> png_mpp("", "png-mpp",
                                    "Bird's-eye scale: metres per pixel (default 0.075: +/-30 m "
                                    "in 800 px)",
                                    false, 0.075, "M", cmd);
    TCLAP::ValueArg<int> png_size("", "png-size", "Bird's-eye image side in pixels", false, 800,
                                  "PIXELS", cmd);
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
    TCLAP::ValueArg<long> max_memory(
        "", "max-memory",
        "Address-space ceiling of this process in MiB (0 = none). A corrupt rawlog can announce "
        "gigabyte-sized objects that MRPT's reader would allocate; above the ceiling the record "
        "is reported as corrupt instead. Default " +
            std::to_string(travel::apps::kDefaultMemoryLimitMiB),
        false, static_cast<long>(travel::apps::kDefaultMemoryLimitMiB), "MIB", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "No progress line and no summary (errors only)", cmd);
    const travel::apps::PrintConfigFlag print_config(cmd);
    Options o;
    o.exit_code = travel::apps::parseCommandLine(cmd, argc, argv);
    if (o.exit_code) return o;
    o.print_config = print_config.arg.getValue();

    o.input = input.getValue();
    o.output = output.getValue();
    o.config = config.getValue();
    o.preset = preset.getValue();
    o.overrides = set.getValue();
    o.sensor_label_regex = label.getValue();
    o.png_prefix = png.getValue();
    o.png_metres_per_pixel = png_mpp.getValue();
    o.png_size = png_size.getValue();
    o.csv = csv.getValue();
    o.quiet = quiet.getValue();
    o.ignore_sensor_pose = ignore_pose.getValue();
    o.label_reference = reference.getValue();
    o.plain_clouds = !no_plain.getValue();
    if (max_memory.getValue() < 0 || (max_memory.getValue() > 0 && max_memory.getValue() < 256))
        throw AppError("--max-memory must be 0 (no limit) or at least 256 MiB");
    o.max_memory_mib = static_cast<std::size_t>(max_memory.getValue());
    if (!(o.png_metres_per_pixel > 0) || !std::isfinite(o.png_metres_per_pixel))
        throw AppError("--png-mpp must be > 0");
    if (o.png_size < 64 || o.png_size > 8192) throw AppError("--png-size must be in [64, 8192]");
    return o;
}

travel::Config loadConfiguration(const Options& o) {
    travel::Config config = travel::apps::loadAppConfig(o.preset, o.config, o.overrides);
    if (!o.sensor_label_regex.empty()) config.filter.sensor_label = o.sensor_label_regex;
    if (o.ignore_sensor_pose) config.filter.use_sensor_pose = false;
    config.validate();
    return config;
}

travel_mrpt::TravelFilterOptions loadFilterOptions(const travel::Config& config) {
    travel_mrpt::TravelFilterOptions options;
    options.params = config.travel;
    static_cast<travel::FilterSection&>(options) = config.filter;
    return options;
}

void createParentDirectory(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    if (ec) throw AppError(parent.string() + ": cannot create directory: " + ec.message());
}

// ------------------------------------------------------------------------------------------
// Input: one serialized object per record; clean end of file vs truncated record.

class RawlogReader {
  public:
    explicit RawlogReader(const std::string& path) : path_(path) {
        std::error_code ec;
        if (!fs::exists(path, ec)) throw AppError(path + ": no such file");
        if (fs::is_directory(path, ec)) throw AppError(path + ": is a directory, not a rawlog");
        if (!file_.open(path)) throw AppError(path + ": cannot open for reading");
    }

    /// The next record, or null at the end of the file. Throws AppError naming the record when
    /// it cannot be read (truncated, not a rawlog, class not registered ...).
    mrpt::serialization::CSerializable::Ptr next() {
        const uint64_t start = file_.getPosition();
        try {
            auto obj = archive_.ReadObject();
            if (!obj) throw std::runtime_error("null object");
            ++index_;
            return obj;
        } catch (const mrpt::serialization::CExceptionEOF&) {
            // End of file exactly at a record boundary is the normal end; anywhere else the
            // record was cut.
            if (file_.getPosition() == start) return nullptr;
            throw AppError(where(path_, index_) + ": truncated (end of file inside the record)");
        } catch (const std::bad_alloc&) {
            throw AppError(where(path_, index_) +
                           ": corrupt record (it announces more data than --max-memory allows); "
                           "is it a rawlog?");
        } catch (const std::exception& e) {
            const std::string what = oneLine(e.what());
            // MRPT reports a short read inside an object as a generic error, not CExceptionEOF.
            if (what.find("EOF") != std::string::npos ||
                what.find("Cannot read object class name") != std::string::npos)
                throw AppError(where(path_, index_) +
                               ": truncated (end of file inside the record)");
            throw AppError(
                where(path_, index_) +
                (index_ == 0 ? ": cannot read (is it an MRPT rawlog?): " : ": cannot read: ") +
                what);
        }
    }

    long index() const { return index_; }

  private:
    std::string path_;
    mrpt::io::CFileGZInputStream file_;
    mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream> archive_{file_};
    long index_ = 0;
};

// ------------------------------------------------------------------------------------------
// Per-class output observations.

constexpr std::array<PointClass, 3> kOutputClasses = {PointClass::Ground, PointClass::NonGround,
                                                      PointClass::Outlier};
constexpr std::array<const char*, 3> kOutputSuffixes = {"_ground", "_nonground", "_outlier"};
constexpr const char* kLabelsSuffix = "_travel";

bool endsWith(const std::string& label, const char* suffix) {
    const std::size_t n = std::char_traits<char>::length(suffix);
    return label.size() > n && label.compare(label.size() - n, n, suffix) == 0;
}

/// An observation this program writes: the labels object, or a per-class cloud.
bool isOurOutput(const CObservation& obs) {
    if (dynamic_cast<const travel_mrpt::CObservationTravelLabels*>(&obs)) return true;
    if (!dynamic_cast<const CObservationPointCloud*>(&obs)) return false;
    for (const char* suffix : kOutputSuffixes)
        if (endsWith(obs.sensorLabel, suffix)) return true;
    return false;
}

/// Three CObservationPointCloud per processed observation. They are serialized as soon as
/// their record is written, so the objects (and their point buffers) are reused for the next
/// records; a second LiDAR in the same SensoryFrame gets its own set.
class ClassCloudPool {
  public:
    using Set = std::array<CObservationPointCloud::Ptr, 3>;

    void startRecord() { used_ = 0; }

    const Set& fill(const CObservation& source, const mrpt::poses::CPose3D& sensor_pose,
                    const travel::PointCloud& cloud, const travel::Result& result) {
        if (used_ == sets_.size()) {
            Set set;
            for (auto& obs : set) {
                obs = CObservationPointCloud::Create();
                obs->pointcloud = mrpt::maps::CPointsMapXYZI::Create();
            }
            sets_.push_back(std::move(set));
        }
        const Set& set = sets_[used_++];

        // Counted here rather than taken from result.class_counts: the buffers are written
        // without bounds checks below, so their sizes must come from the labels themselves
        // (& 3 keeps any label value inside the arrays).
        std::array<std::size_t, 4> count_of_class{};
        for (PointClass c : result.labels) ++count_of_class[static_cast<int>(c) & 3];
        std::array<mrpt::maps::CPointsMapXYZI*, 4> map_of_class{};  // indexed by PointClass
        std::array<std::size_t, 4> next_index{};
        for (std::size_t k = 0; k < set.size(); ++k) {
            CObservationPointCloud& obs = *set[k];
            obs.timestamp = source.timestamp;
            obs.sensorLabel = source.sensorLabel + kOutputSuffixes[k];
            obs.sensorPose = sensor_pose;
            auto* map = static_cast<mrpt::maps::CPointsMapXYZI*>(obs.pointcloud.get());
            map->setSize(count_of_class[static_cast<int>(kOutputClasses[k])]);
            map_of_class[static_cast<int>(kOutputClasses[k])] = map;
        }
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            const int c = static_cast<int>(result.labels[i]) & 3;
            mrpt::maps::CPointsMapXYZI* map = map_of_class[c];
            if (!map) continue;  // invalid
            const std::size_t j = next_index[c]++;
            map->setPointFast(j, cloud.x[i], cloud.y[i], cloud.z[i]);
            map->setPointColor_fast(j, cloud.intensity[i], 0.f, 0.f);  // = intensity
        }
        return set;
    }

  private:
    std::vector<Set> sets_;
    std::size_t used_ = 0;
};

// ------------------------------------------------------------------------------------------
// Pictures: bird's-eye PNG (travel_mrpt::renderBirdsEye) and coloured PLY, both from the
// aligned (levelled) coordinates.

/// The colour of point i (0xRRGGBB) as in the bird's-eye pictures and RawLogViewer, or
/// nothing for invalid points.
std::optional<uint32_t> pointColour(PointClass c, uint32_t cluster_id, bool any_cluster) {
    switch (c) {
        case PointClass::Ground:
            return travel_mrpt::kGroundColour;
        case PointClass::Outlier:
            return travel_mrpt::kOutlierColour;
        case PointClass::NonGround:
            if (cluster_id != 0) return travel_mrpt::clusterColour(cluster_id);
            return any_cluster ? travel_mrpt::kUnclusteredColour : travel_mrpt::kNonGroundColour;
        case PointClass::Invalid:
            break;
    }
    return std::nullopt;
}

void writePly(const std::string& path, const travel::AlignedCloud& aligned,
              const travel::Result& result) {
    const auto& labels = result.labels;
    const bool any_cluster = !result.clusters.empty();
    const auto id = [&](std::size_t i) {
        return result.cluster_id.size() == labels.size() ? result.cluster_id[i] : 0u;
    };
    std::size_t n = 0;
    for (std::size_t i = 0; i < labels.size(); ++i)
        n += pointColour(labels[i], id(i), any_cluster).has_value();
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw AppError(path + ": cannot open for writing");
    std::fprintf(f,
                 "ply\nformat ascii 1.0\ncomment TRAVEL labels: green ground, blue outlier, one "
                 "colour per cluster, grey unclustered non-ground; sensor-centred levelled "
                 "frame\nelement vertex %zu\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n",
                 n);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const auto c = pointColour(labels[i], id(i), any_cluster);
        if (!c) continue;
        std::fprintf(f, "%.3f %.3f %.3f %u %u %u\n", aligned.x[i], aligned.y[i], aligned.z[i],
                     (*c >> 16) & 0xFFu, (*c >> 8) & 0xFFu, *c & 0xFFu);
    }
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok) throw AppError(path + ": write error");
}

// ------------------------------------------------------------------------------------------
// Statistics and CSV.

struct Totals {
    std::size_t frames = 0, points = 0, skipped = 0, clusters = 0, levelled = 0, deskewed = 0;
    std::array<std::size_t, 4> per_class{};
    std::vector<double> process_ms, convert_ms;
};

class CsvLog {
  public:
    explicit CsvLog(const std::string& path) : path_(path) {
        if (path.empty()) return;
        createParentDirectory(path);
        file_.open(path);
        if (!file_) throw AppError(path + ": cannot open for writing");
        file_ << "frame,timestamp,sensor_label,points,invalid,ground,nonground,outlier,clusters,"
                 "levelled,deskewed,convert_ms,preprocess_ms,embedding_ms,node_fitting_ms,"
                 "graph_search_ms,ttmf_ms,labelling_ms,range_image_ms,horizontal_ms,vertical_ms,"
                 "clusters_ms,total_ms\n";
    }

    void add(std::size_t frame, const CObservation& obs, const travel_mrpt::TravelFrame& f) {
        if (!file_.is_open()) return;
        const travel::Result& r = f.result;
        const auto& t = r.timings;
        char line[640];
        std::snprintf(
            line, sizeof line,
            "%zu,%.6f,%s,%zu,%zu,%zu,%zu,%zu,%zu,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,"
            "%.3f,%.3f,%.3f,%.3f,%.3f\n",
            frame, mrpt::Clock::toDouble(obs.timestamp), obs.sensorLabel.c_str(), f.cloud.size(),
            r.count(PointClass::Invalid), r.count(PointClass::Ground),
            r.count(PointClass::NonGround), r.count(PointClass::Outlier), r.clusters.size(),
            f.levelled ? 1 : 0, f.deskewed ? 1 : 0, f.convert_ms, t.preprocess, t.embedding,
            t.node_fitting, t.graph_search, t.ttmf, t.labelling, t.range_image, t.horizontal,
            t.vertical, t.clusters, f.process_ms);
        file_ << line;
        if (!file_) throw AppError(path_ + ": write error");
    }

  private:
    std::string path_;
    std::ofstream file_;
};

// ------------------------------------------------------------------------------------------
// The job.

/// The label reference file (--label-reference), written frame by frame.
class ReferenceLog {
  public:
    explicit ReferenceLog(const std::string& path) : path_(path) {
        if (path.empty()) return;
        createParentDirectory(path);
        file_.open(path);
        if (!file_) throw AppError(path + ": cannot open for writing");
        travel::label_reference::writeHeader(file_);
    }
    void add(const travel::Result& r) {
        if (!file_.is_open()) return;
        travel::label_reference::writeFrame(file_, frames_++, r.labels, r.cluster_id);
        if (!file_) throw AppError(path_ + ": write error");
    }
    void finish() {
        if (!file_.is_open()) return;
        travel::label_reference::writeFooter(file_, frames_);
        file_.close();
        if (!file_) throw AppError(path_ + ": write error");
    }

  private:
    std::string path_;
    std::ofstream file_;
    std::size_t frames_ = 0;
};

class RawlogSegmenter {
  public:
    RawlogSegmenter(const Options& options, const travel_mrpt::TravelFilterOptions& filter_options)
        : options_(options),
          label_filter_(filter_options.sensor_label),
          filter_(filter_options),
          csv_(options.csv),
          reference_(options.label_reference) {
        // Notes from the filter (no motion data, ...) once each, in our own format.
        filter_.setMinLoggingLevel(options.quiet ? mrpt::system::LVL_ERROR
                                                 : mrpt::system::LVL_INFO);
        filter_.logging_enable_console_output = false;
        filter_.logRegisterCallback(
            [this](std::string_view msg, mrpt::system::VerbosityLevel, std::string_view,
                   const mrpt::Clock::time_point&) { noteOnce(std::string(msg)); });
        if (!options.png_prefix.empty()) {
            createParentDirectory(options.png_prefix + "_x");
            birds_eye_.size_px = options.png_size;
            birds_eye_.metres_per_pixel = options.png_metres_per_pixel;
        }
    }

    /// Motion records (IMU, odometry, odometry actions) go to the filter's motion estimate.
    void processMotion(const mrpt::serialization::CSerializable& record) {
        if (auto* imu = dynamic_cast<const mrpt::obs::CObservationIMU*>(&record)) {
            filter_.processImu(*imu);
        } else if (auto* odo = dynamic_cast<const mrpt::obs::CObservationOdometry*>(&record)) {
            filter_.processOdometry(*odo);
        } else if (auto* actions = dynamic_cast<const mrpt::obs::CActionCollection*>(&record)) {
            if (auto move = actions->getActionByClass<mrpt::obs::CActionRobotMovement2D>())
                filter_.processAction(*move);
        }
    }

    /// Processes one observation of the record, appending the outputs to `added`.
    void processObservation(const CObservation& obs, long record,
                            std::vector<CObservation::Ptr>& added) {
        processMotion(obs);
        if (!travel_mrpt::isLidarObservation(obs) || isOurOutput(obs)) return;
        std::string why_not;
        if (!filter_.filter(obs, frame_, &why_not)) {
            if (!std::regex_match(obs.sensorLabel, label_filter_)) {
                noteOnce("ignored (does not match the sensor label regex): " + obs.sensorLabel);
                return;
            }
            ++totals_.skipped;
            noteOnce("skipped " + obs.sensorLabel + " (" + why_not + ")");
            return;
        }
        const travel::Result& result = frame_.result;
        if (result.labels.size() != frame_.cloud.size())
            throw AppError(where(options_.input, record) + ": pipeline returned " +
                           std::to_string(result.labels.size()) + " labels for " +
                           std::to_string(frame_.cloud.size()) + " points");

        added.push_back(labelsFor(obs));
        if (options_.plain_clouds)
            for (const auto& out : pool_.fill(obs, frame_.sensorPose, frame_.cloud, result))
                added.push_back(out);

        const std::size_t frame = totals_.frames++;
        totals_.points += frame_.cloud.size();
        for (std::size_t c = 0; c < 4; ++c) totals_.per_class[c] += result.class_counts[c];
        totals_.clusters += result.clusters.size();
        totals_.levelled += frame_.levelled;
        totals_.deskewed += frame_.deskewed;
        totals_.process_ms.push_back(frame_.process_ms);
        totals_.convert_ms.push_back(frame_.convert_ms);
        csv_.add(frame, obs, frame_);
        reference_.add(result);
        if (!options_.png_prefix.empty() && frame_.aligned)
            writePictures(frame, obs, *frame_.aligned);
    }

    /// Outputs of an earlier run (<label>_travel, <label>_ground ... of a label we process
    /// now) are dropped: they are regenerated, and keeping them would duplicate the labels.
    bool isStaleOutput(const CObservation& obs) {
        if (!isOurOutput(obs)) return false;
        const std::string base = obs.sensorLabel.substr(0, obs.sensorLabel.rfind('_'));
        if (!std::regex_match(base, label_filter_)) return false;
        noteOnce("replacing the TRAVEL outputs of an earlier run: " + base + "_*");
        return true;
    }

    void startRecord() {
        pool_.startRecord();
        labels_used_ = 0;
    }
    void finish() { reference_.finish(); }
    const Totals& totals() const { return totals_; }

  private:
    /// The CObservationTravelLabels of the current frame. Serialized as soon as its record is
    /// written, so the objects are reused for the next records (one per observation of a record).
    CObservation::Ptr labelsFor(const CObservation& source) {
        if (labels_used_ == labels_pool_.size())
            labels_pool_.push_back(travel_mrpt::CObservationTravelLabels::Create());
        auto& labels = *labels_pool_[labels_used_];
        labels.assign(frame_.cloud, frame_.result, frame_.alignedRotation);
        labels.sensorPose = frame_.sensorPose;
        labels.sourceClass = source.GetRuntimeClass()->className;
        labels.timestamp = source.timestamp;
        labels.sensorLabel = source.sensorLabel + kLabelsSuffix;
        return labels_pool_[labels_used_++];
    }

    void writePictures(std::size_t frame, const CObservation& obs,
                       const travel::AlignedCloud& aligned) {
        const travel::Result& result = frame_.result;
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "_%06zu", frame);
        const std::string stem = options_.png_prefix + suffix;
        const auto total = std::max<std::size_t>(1, frame_.cloud.size());
        char title[256];
        std::snprintf(title, sizeof title,
                      "frame %zu  %s  %zu pts  ground %.0f%%  non-ground %.0f%%  %zu clusters",
                      frame, obs.sensorLabel.c_str(), frame_.cloud.size(),
                      100.0 * result.count(PointClass::Ground) / total,
                      100.0 * result.count(PointClass::NonGround) / total, result.clusters.size());
        birds_eye_.title = title;
        travel_mrpt::renderBirdsEye(aligned, result.labels, result.cluster_id, &result.terrain,
                                    birds_eye_, image_);
        if (!image_.saveToFile(stem + ".png")) throw AppError(stem + ".png: cannot write PNG");
        writePly(stem + ".ply", aligned, result);
    }

    void noteOnce(const std::string& note) {
        if (notes_.insert(note).second && !options_.quiet)
            std::cerr << "travel-rawlog: note: " << note << "\n";
    }

    const Options& options_;
    std::regex label_filter_;
    travel_mrpt::TravelFilter filter_;
    CsvLog csv_;
    ReferenceLog reference_;
    travel_mrpt::BirdsEyeOptions birds_eye_;
    mrpt::img::CImage image_;  // reused across frames
    std::set<std::string> notes_;
    ClassCloudPool pool_;
    std::vector<travel_mrpt::CObservationTravelLabels::Ptr> labels_pool_;
    std::size_t labels_used_ = 0;
    Totals totals_;
    travel_mrpt::TravelFrame frame_;  // reused across frames
};

void printSummary(const Options& o, const Totals& t, long records, double seconds) {
    const auto pct = [&](std::size_t n) { return t.points ? 100.0 * n / t.points : 0.0; };
    const auto count = [&](PointClass c) { return t.per_class[static_cast<int>(c)]; };
    std::printf("travel-rawlog: %s -> %s\n", o.input.c_str(), o.output.c_str());
    std::printf("  records: %ld, LiDAR frames processed: %zu, skipped: %zu, wall time %.2f s\n",
                records, t.frames, t.skipped, seconds);
    std::printf(
        "  points: %zu  ground %zu (%.1f %%)  non-ground %zu (%.1f %%)  outlier %zu "
        "(%.1f %%)  invalid %zu (%.1f %%)\n",
        t.points, count(PointClass::Ground), pct(count(PointClass::Ground)),
        count(PointClass::NonGround), pct(count(PointClass::NonGround)), count(PointClass::Outlier),
        pct(count(PointClass::Outlier)), count(PointClass::Invalid),
        pct(count(PointClass::Invalid)));
    std::printf("  clusters: %zu (%.1f per frame); frames levelled %zu, deskewed %zu\n", t.clusters,
                t.frames ? static_cast<double>(t.clusters) / t.frames : 0.0, t.levelled,
                t.deskewed);
    if (t.frames) {
        std::printf(
            "  ms per frame: TRAVEL median %.2f max %.2f; conversion median %.2f max %.2f\n",
            travel::median(t.process_ms),
            *std::max_element(t.process_ms.begin(), t.process_ms.end()),
            travel::median(t.convert_ms),
            *std::max_element(t.convert_ms.begin(), t.convert_ms.end()));
    }
    if (!o.csv.empty()) std::printf("  per-frame CSV: %s\n", o.csv.c_str());
    if (!o.label_reference.empty())
        std::printf("  label reference: %s\n", o.label_reference.c_str());
    if (!o.png_prefix.empty())
        std::printf("  pictures: %s_NNNNNN.png / .ply\n", o.png_prefix.c_str());
}

int run(int argc, char** argv) {
    const Options options = parseCommandLine(argc, argv);
    if (options.exit_code) return *options.exit_code;
    const std::string limit_note = travel::apps::applyMemoryLimit(options.max_memory_mib);
    if (!limit_note.empty() && !options.quiet)
        std::cerr << "travel-rawlog: note: " << limit_note << "\n";
    // Our own classes (CObservationTravelLabels) must be readable: inputs may be earlier outputs.
    travel_mrpt::registerClasses();
    const travel::Config configuration = loadConfiguration(options);
    if (options.print_config) {
        std::cout << travel::configToYaml(configuration);
        return 0;
    }
    const travel_mrpt::TravelFilterOptions filter_options = loadFilterOptions(configuration);
    if (fs::exists(options.output) && fs::exists(options.input) &&
        fs::equivalent(options.input, options.output))
        throw AppError(options.output + ": output would overwrite the input");

    RawlogReader reader(options.input);
    RawlogSegmenter segmenter(options, filter_options);

    createParentDirectory(options.output);
    const std::string partial = options.output + ".part";
    mrpt::io::CFileGZOutputStream out_file;
    if (!out_file.open(partial)) throw AppError(partial + ": cannot open for writing");
    auto out = mrpt::serialization::archiveFrom(out_file);

    const auto start = Clock::now();
    auto last_progress = start;
    bool progress_shown = false;
    std::vector<CObservation::Ptr> added;
    try {
        while (auto record = reader.next()) {
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

            if (!options.quiet && Clock::now() - last_progress > std::chrono::milliseconds(500)) {
                last_progress = Clock::now();
                const double s = std::chrono::duration<double>(last_progress - start).count();
                std::fprintf(stderr, "\rtravel-rawlog: record %ld, %zu frames, %.1f frames/s   ",
                             index + 1, segmenter.totals().frames, segmenter.totals().frames / s);
                progress_shown = true;
            }
        }
        if (reader.index() == 0) {
            std::error_code ec;
            throw AppError(options.input + (fs::file_size(options.input, ec) == 0
                                                ? ": empty file, not a rawlog"
                                                : ": no record could be read (not an MRPT rawlog, "
                                                  "or a corrupt gzip stream)"));
        }
        segmenter.finish();
    } catch (...) {
        if (progress_shown) std::fputc('\n', stderr);
        out_file.close();
        std::error_code ec;
        fs::remove(partial, ec);  // never leave a half-written rawlog behind
        throw;
    }
    out_file.close();
    std::error_code ec;
    fs::rename(partial, options.output, ec);
    if (ec)
        throw AppError(options.output + ": cannot rename from " + partial + ": " + ec.message());

    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (progress_shown) std::fprintf(stderr, "\n");
    if (!options.quiet) printSummary(options, segmenter.totals(), reader.index(), seconds);
    if (segmenter.totals().frames == 0)
        throw AppError(options.input +
                       ": no LiDAR observation processed (check --sensor-label; "
                       "the output rawlog is a plain copy)");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-rawlog", run, argc, argv);
}
