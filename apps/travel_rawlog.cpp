// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-rawlog: TRAVEL ground segmentation of the LiDAR observations of an MRPT rawlog.
// Streams the input (observation format or SensoryFrame/action format, one record at a time),
// copies every record to the output rawlog and adds, per processed observation, one plain
// CObservationPointCloud per class. Optionally writes a per-frame CSV, bird's-eye PNGs and
// coloured PLYs. See --help for the details of each output.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
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
#include "MemoryLimit.hpp"
#include "travel/Errors.hpp"
#include "travel/Metrics.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel_mrpt/Attitude.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"

namespace fs = std::filesystem;
using mrpt::obs::CObservation;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CSensoryFrame;
using travel::PointClass;
using Clock = std::chrono::steady_clock;

namespace {

// ------------------------------------------------------------------------------------------
// Errors: every failure becomes one line "travel-rawlog: error: <file>[: record N]: <what>".

/// MRPT exception texts span many lines (banner, nested "Message:" lines, locations, call
/// stacks); keep the innermost message, which says what went wrong.
std::string oneLine(const std::string& text) {
    std::istringstream lines(text);
    std::string line, message, first;
    while (std::getline(lines, line)) {
        const auto start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos) continue;
        line = line.substr(start);
        if (first.empty()) first = line;
        if (line.rfind("Message:", 0) == 0) message = line.substr(line.find_first_not_of(' ', 8));
    }
    std::string best = message.empty() ? first : message;
    // MRPT's hint about gzip is wrong here: the reader accepts plain and gzip files alike.
    const auto hint = best.find(" (Perhaps it's a gz");
    if (hint != std::string::npos) best.erase(hint);
    return best.empty() ? text : best;
}

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
    std::string input, output, config, preset, sensor_label_regex, png_prefix, csv;
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
        "TRAVEL traversable-ground segmentation of the 3-D LiDAR observations of an MRPT rawlog "
        "(CObservationVelodyneScan, CObservationRotatingScan, CObservationPointCloud, "
        "CObservation3DRangeScan).\n"
        "Outputs:\n"
        " (1) OUT.rawlog: every input record, unchanged, in the input's format; after each "
        "processed observation, three CObservationPointCloud (CPointsMapXYZI, points in the "
        "sensor frame, same sensorPose and timestamp, original intensity) labelled "
        "<label>_ground, <label>_nonground and <label>_outlier; in SensoryFrame rawlogs they are "
        "added to the observation's SensoryFrame. Invalid points (no return, out of range) are in "
        "none of them.\n"
        " (2) --csv: one line per frame: index, timestamp, label, point counts per class and "
        "milliseconds per stage.\n"
        " (3) --png: PREFIX_<frame>.png, a bird's-eye view centred on the sensor (up = forward; "
        "ground green, non-ground red, outlier blue), and PREFIX_<frame>.ply, the valid points "
        "coloured the same way (ASCII PLY: x y z red green blue, sensor-centred, levelled frame) "
        "for CloudCompare/MeshLab.\n"
        " (4) a summary on stdout.\n"
        "Parameters: HDL-64E/KITTI defaults, then --preset, then --config, then each --set. "
        "The mount_{roll,pitch,yaw}_deg parameters are taken from each observation's sensorPose "
        "(unless --ignore-sensor-pose). Exit status: 0 on success, 1 on any error.",
        ' ', "0.1");
    TCLAP::ValueArg<std::string> input("i", "input", "Input rawlog (.rawlog, gzip or plain)", true,
                                       "", "IN.rawlog", cmd);
    TCLAP::ValueArg<std::string> output("o", "output",
                                        "Output rawlog (gzip-compressed); written to OUT.part "
                                        "and renamed when complete",
                                        true, "", "OUT.rawlog", cmd);
    TCLAP::ValueArg<std::string> config("", "config",
                                        "YAML or ini parameter file (see share/presets/*.yaml), "
                                        "applied after --preset",
                                        false, "", "FILE", cmd);
    TCLAP::ValueArg<std::string> preset(
        "", "preset",
        "Start from this sensor preset instead of the HDL-64E defaults (" + presetList() + ")",
        false, "", "NAME", cmd);
    TCLAP::MultiArg<std::string> set("", "set",
                                     "Override one parameter (repeatable), applied last, e.g. "
                                     "--set sensor_height=2.24",
                                     false, "KEY=VALUE", cmd);
    TCLAP::ValueArg<std::string> label(
        "", "sensor-label",
        "Only process LiDAR observations whose sensorLabel contains a match of this ECMAScript "
        "regex (anchor with ^...$ for an exact match). Our own <label>_ground/_nonground/"
        "_outlier outputs are never re-processed; when the input already has them (an earlier "
        "output) they are replaced.",
        false, ".*", "REGEX", cmd);
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
    Options o;
    o.exit_code = travel::apps::parseCommandLine(cmd, argc, argv);
    if (o.exit_code) return o;

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
    if (max_memory.getValue() < 0 || (max_memory.getValue() > 0 && max_memory.getValue() < 256))
        throw AppError("--max-memory must be 0 (no limit) or at least 256 MiB");
    o.max_memory_mib = static_cast<std::size_t>(max_memory.getValue());
    if (!(o.png_metres_per_pixel > 0) || !std::isfinite(o.png_metres_per_pixel))
        throw AppError("--png-mpp must be > 0");
    if (o.png_size < 64 || o.png_size > 8192) throw AppError("--png-size must be in [64, 8192]");
    return o;
}

travel::Params loadParams(const Options& o) {
    travel::Params params;  // HDL-64E on KITTI
    if (!o.preset.empty()) params = travel::loadPreset(o.preset);
    if (!o.config.empty()) travel::applyParamsFile(o.config, params);
    for (const auto& kv : o.overrides) travel::applyOverride(kv, params);  // errors quote kv
    params.validate();
    return params;
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

bool isOurOutputLabel(const std::string& label) {
    for (const char* suffix : kOutputSuffixes) {
        const std::size_t n = std::char_traits<char>::length(suffix);
        if (label.size() > n && label.compare(label.size() - n, n, suffix) == 0) return true;
    }
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

struct Rgb {
    uint8_t r, g, b;
};
constexpr Rgb kGroundColour{0, 170, 0}, kNonGroundColour{220, 0, 0}, kOutlierColour{0, 60, 255};

const Rgb* colourOf(PointClass c) {
    switch (c) {
        case PointClass::Ground:
            return &kGroundColour;
        case PointClass::NonGround:
            return &kNonGroundColour;
        case PointClass::Outlier:
            return &kOutlierColour;
        case PointClass::Invalid:
            break;
    }
    return nullptr;
}

void writePly(const std::string& path, const travel::AlignedCloud& aligned,
              const std::vector<PointClass>& labels) {
    std::size_t n = 0;
    for (PointClass c : labels) n += colourOf(c) != nullptr;
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw AppError(path + ": cannot open for writing");
    std::fprintf(f,
                 "ply\nformat ascii 1.0\ncomment TRAVEL labels: green ground, red non-ground, "
                 "blue outlier; sensor-centred levelled frame\nelement vertex %zu\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n",
                 n);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const Rgb* c = colourOf(labels[i]);
        if (!c) continue;
        std::fprintf(f, "%.3f %.3f %.3f %u %u %u\n", aligned.x[i], aligned.y[i], aligned.z[i],
                     unsigned{c->r}, unsigned{c->g}, unsigned{c->b});
    }
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok) throw AppError(path + ": write error");
}

// ------------------------------------------------------------------------------------------
// Statistics and CSV.

struct Totals {
    std::size_t frames = 0, points = 0, skipped = 0;
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
        file_ << "frame,timestamp,sensor_label,points,invalid,ground,nonground,outlier,"
                 "convert_ms,preprocess_ms,embedding_ms,node_fitting_ms,graph_search_ms,ttmf_ms,"
                 "labelling_ms,total_ms\n";
    }

    void add(std::size_t frame, const CObservation& obs, const travel::Result& r,
             std::size_t points, double convert_ms, double total_ms) {
        if (!file_.is_open()) return;
        const auto& t = r.timings;
        char line[512];
        std::snprintf(line, sizeof line,
                      "%zu,%.6f,%s,%zu,%zu,%zu,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n",
                      frame, mrpt::Clock::toDouble(obs.timestamp), obs.sensorLabel.c_str(), points,
                      r.count(PointClass::Invalid), r.count(PointClass::Ground),
                      r.count(PointClass::NonGround), r.count(PointClass::Outlier), convert_ms,
                      t.preprocess, t.embedding, t.node_fitting, t.graph_search, t.ttmf,
                      t.labelling, total_ms);
        file_ << line;
        if (!file_) throw AppError(path_ + ": write error");
    }

  private:
    std::string path_;
    std::ofstream file_;
};

// ------------------------------------------------------------------------------------------
// The job.

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

class RawlogSegmenter {
  public:
    RawlogSegmenter(const Options& options, const travel::Params& params)
        : options_(options),
          base_params_(params),
          label_filter_(options.sensor_label_regex),
          csv_(options.csv) {
        if (!options.png_prefix.empty()) {
            createParentDirectory(options.png_prefix + "_x");
            birds_eye_.size_px = options.png_size;
            birds_eye_.metres_per_pixel = options.png_metres_per_pixel;
        }
    }

    /// Processes every selected observation of the record, appending the outputs to `added`.
    void processObservation(const CObservation& obs, long record,
                            std::vector<CObservation::Ptr>& added) {
        if (!travel_mrpt::isLidarObservation(obs)) return;
        if (dynamic_cast<const CObservationPointCloud*>(&obs) && isOurOutputLabel(obs.sensorLabel))
            return;  // an output of ours (kept when its source label is not selected)
        if (!std::regex_search(obs.sensorLabel, label_filter_)) {
            noteOnce("ignored (does not match --sensor-label): " + obs.sensorLabel);
            return;
        }
        const auto t0 = Clock::now();
        std::string why_not;
        if (!travel_mrpt::toTravelCloud(obs, cloud_, sensor_pose_, &why_not)) {
            ++totals_.skipped;
            noteOnce("skipped " + obs.sensorLabel + " (" + why_not + ")");
            return;
        }
        const double convert_ms = msSince(t0);

        travel::Pipeline& pipeline = pipelineFor(obs.sensorLabel, sensor_pose_);
        const auto t1 = Clock::now();
        pipeline.process(cloud_, travel::FrameInput{}, result_);
        const double process_ms = msSince(t1);
        if (result_.labels.size() != cloud_.size())
            throw AppError(where(options_.input, record) + ": pipeline returned " +
                           std::to_string(result_.labels.size()) + " labels for " +
                           std::to_string(cloud_.size()) + " points");

        for (const auto& out : pool_.fill(obs, sensor_pose_, cloud_, result_)) added.push_back(out);

        const std::size_t frame = totals_.frames++;
        totals_.points += cloud_.size();
        for (std::size_t c = 0; c < 4; ++c) totals_.per_class[c] += result_.class_counts[c];
        totals_.process_ms.push_back(process_ms);
        totals_.convert_ms.push_back(convert_ms);
        csv_.add(frame, obs, result_, cloud_.size(), convert_ms, process_ms);
        if (!options_.png_prefix.empty()) writePictures(frame, obs, pipeline.aligned());
    }

    /// Outputs of an earlier run (<label>_ground ... of a label we process now) are dropped:
    /// they are regenerated, and keeping them would duplicate the labels.
    bool isStaleOutput(const CObservation& obs) {
        if (!dynamic_cast<const CObservationPointCloud*>(&obs) ||
            !isOurOutputLabel(obs.sensorLabel))
            return false;
        const std::string base = obs.sensorLabel.substr(0, obs.sensorLabel.rfind('_'));
        if (!std::regex_search(base, label_filter_)) return false;
        noteOnce("replacing the TRAVEL outputs of an earlier run: " + base + "_*");
        return true;
    }

    void startRecord() { pool_.startRecord(); }
    const Totals& totals() const { return totals_; }

  private:
    struct Sensor {
        std::unique_ptr<travel::Pipeline> pipeline;
        mrpt::poses::CPose3D pose;
    };

    /// One pipeline per sensor label: the mount angles come from that sensor's pose, and a
    /// pipeline's buffers are sized for its sensor. Rebuilt only if the pose changes.
    travel::Pipeline& pipelineFor(const std::string& label, const mrpt::poses::CPose3D& pose) {
        Sensor& sensor = sensors_[label];
        if (!sensor.pipeline || !(sensor.pose == pose)) {
            travel::Params params = base_params_;
            if (!options_.ignore_sensor_pose) travel_mrpt::setMountFromSensorPose(pose, params);
            try {
                sensor.pipeline = std::make_unique<travel::Pipeline>(params);
            } catch (const travel::ConfigError& e) {
                throw travel::ConfigError("sensor " + label + ": " + e.what());
            }
            sensor.pose = pose;
        }
        return *sensor.pipeline;
    }

    void writePictures(std::size_t frame, const CObservation& obs,
                       const travel::AlignedCloud& aligned) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "_%06zu", frame);
        const std::string stem = options_.png_prefix + suffix;
        const auto total = std::max<std::size_t>(1, cloud_.size());
        char title[256];
        std::snprintf(title, sizeof title,
                      "frame %zu  %s  %zu pts  ground %.0f%%  non-ground %.0f%%", frame,
                      obs.sensorLabel.c_str(), cloud_.size(),
                      100.0 * result_.count(PointClass::Ground) / total,
                      100.0 * result_.count(PointClass::NonGround) / total);
        // Class colours only (no cluster ids, no terrain): the picture shows what the output
        // rawlog holds.
        birds_eye_.title = title;
        travel_mrpt::renderBirdsEye(aligned, result_.labels, {}, nullptr, birds_eye_, image_);
        if (!image_.saveToFile(stem + ".png")) throw AppError(stem + ".png: cannot write PNG");
        writePly(stem + ".ply", aligned, result_.labels);
    }

    void noteOnce(const std::string& note) {
        if (notes_.insert(note).second && !options_.quiet)
            std::cerr << "travel-rawlog: note: " << note << "\n";
    }

    const Options& options_;
    travel::Params base_params_;
    std::regex label_filter_;
    CsvLog csv_;
    travel_mrpt::BirdsEyeOptions birds_eye_;
    mrpt::img::CImage image_;  // reused across frames
    std::map<std::string, Sensor> sensors_;
    std::set<std::string> notes_;
    ClassCloudPool pool_;
    Totals totals_;
    // Reused across frames.
    travel::PointCloud cloud_;
    travel::Result result_;
    mrpt::poses::CPose3D sensor_pose_;
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
    if (t.frames) {
        std::printf(
            "  ms per frame: TRAVEL median %.2f max %.2f; conversion median %.2f max %.2f\n",
            travel::median(t.process_ms),
            *std::max_element(t.process_ms.begin(), t.process_ms.end()),
            travel::median(t.convert_ms),
            *std::max_element(t.convert_ms.begin(), t.convert_ms.end()));
    }
    if (!o.csv.empty()) std::printf("  per-frame CSV: %s\n", o.csv.c_str());
    if (!o.png_prefix.empty())
        std::printf("  pictures: %s_NNNNNN.png / .ply\n", o.png_prefix.c_str());
}

int run(int argc, char** argv) {
    const Options options = parseCommandLine(argc, argv);
    if (options.exit_code) return *options.exit_code;
    const std::string limit_note = travel::apps::applyMemoryLimit(options.max_memory_mib);
    if (!limit_note.empty() && !options.quiet)
        std::cerr << "travel-rawlog: note: " << limit_note << "\n";
    const travel::Params params = loadParams(options);
    if (fs::exists(options.output) && fs::exists(options.input) &&
        fs::equivalent(options.input, options.output))
        throw AppError(options.output + ": output would overwrite the input");

    RawlogReader reader(options.input);
    RawlogSegmenter segmenter(options, params);

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
                out << *record;  // actions and anything else: copied unchanged
            }

            if (!options.quiet && Clock::now() - last_progress > std::chrono::milliseconds(500)) {
                last_progress = Clock::now();
                const double s = std::chrono::duration<double>(last_progress - start).count();
                std::fprintf(stderr, "\rtravel-rawlog: record %ld, %zu frames, %.1f frames/s   ",
                             index + 1, segmenter.totals().frames, segmenter.totals().frames / s);
                progress_shown = true;
            }
        }
        if (reader.index() == 0) throw AppError(options.input + ": empty file, not a rawlog");
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
    try {
        return run(argc, argv);
    } catch (const travel::ConfigError& e) {
        std::cerr << "travel-rawlog: configuration error: " << oneLine(e.what()) << "\n";
    } catch (const std::regex_error& e) {
        std::cerr << "travel-rawlog: error: --sensor-label: invalid regex: " << e.what() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "travel-rawlog: error: " << oneLine(e.what()) << "\n";
    } catch (...) {
        std::cerr << "travel-rawlog: error: unknown exception\n";
    }
    return 1;
}
