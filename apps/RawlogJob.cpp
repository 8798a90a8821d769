// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "RawlogJob.hpp"

#include "travel/eval/Metrics.hpp"

#include <mrpt/obs/CObservation.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>

#include "LabelReference.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace fs = std::filesystem;
using travel::PointClass;

namespace travel::apps {

namespace {

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

}  // namespace

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
    travel::writeThroughPartFile(path, [&](std::ostream& out) {
        out << "ply\nformat ascii 1.0\ncomment TRAVEL labels: green ground, blue outlier, one "
               "colour per cluster, grey unclustered non-ground; sensor-centred levelled "
               "frame\nelement vertex "
            << n
            << "\nproperty float x\nproperty float y\nproperty float z\n"
               "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
        char line[192];  // 3 x 45 characters at most for a float with 3 decimals
        for (std::size_t i = 0; i < labels.size(); ++i) {
            const auto c = pointColour(labels[i], id(i), any_cluster);
            if (!c) continue;
            const int length = std::snprintf(line, sizeof line, "%.3f %.3f %.3f %u %u %u\n",
                                             aligned.x[i], aligned.y[i], aligned.z[i],
                                             (*c >> 16) & 0xFFu, (*c >> 8) & 0xFFu, *c & 0xFFu);
            out.write(line, std::min<std::streamsize>(length, sizeof line - 1));
        }
    });
}

CsvLog::CsvLog(const std::string& path) : path_(path) {
    if (path.empty()) return;
    createParentFolder(path);
    file_.open(path);
    if (!file_) throw AppError(path + ": cannot open for writing");
    file_ << "frame,timestamp,sensor_label,points,invalid,ground,nonground,outlier,clusters,"
             "levelled,deskewed,convert_ms,preprocess_ms,embedding_ms,node_fitting_ms,"
             "graph_search_ms,ttmf_ms,labelling_ms,range_image_ms,horizontal_ms,vertical_ms,"
             "clusters_ms,total_ms\n";
}

void CsvLog::add(std::size_t frame, const mrpt::obs::CObservation& obs,
                 const travel_mrpt::TravelFrame& f) {
    if (!file_.is_open()) return;
    const travel::Result& r = f.result;
    const auto& t = r.timings;
    char line[640];
    std::snprintf(line, sizeof line,
                  "%zu,%.6f,%s,%zu,%zu,%zu,%zu,%zu,%zu,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,"
                  "%.3f,%.3f,%.3f,%.3f,%.3f\n",
                  frame, mrpt::Clock::toDouble(obs.timestamp), obs.sensorLabel.c_str(),
                  f.cloud.size(), r.count(PointClass::Invalid), r.count(PointClass::Ground),
                  r.count(PointClass::NonGround), r.count(PointClass::Outlier), r.clusters.size(),
                  f.levelled ? 1 : 0, f.deskewed ? 1 : 0, f.convert_ms, t.preprocess, t.embedding,
                  t.node_fitting, t.graph_search, t.ttmf, t.labelling, t.range_image, t.horizontal,
                  t.vertical, t.clusters, f.process_ms);
    file_ << line;
    if (!file_) throw AppError(path_ + ": write error");
}

void CsvLog::finish() {
    if (!file_.is_open()) return;
    file_.close();  // the last rows are written here: a full disk shows only now
    if (!file_) throw AppError(path_ + ": write error");
}

ReferenceLog::ReferenceLog(const std::string& path) : path_(path) {
    if (path.empty()) return;
    createParentFolder(path);
    file_.open(path);
    if (!file_) throw AppError(path + ": cannot open for writing");
    travel::label_reference::writeHeader(file_);
}

void ReferenceLog::add(const travel::Result& r) {
    if (!file_.is_open()) return;
    travel::label_reference::writeFrame(file_, frames_++, r.labels, r.cluster_id);
    if (!file_) throw AppError(path_ + ": write error");
}

void ReferenceLog::finish() {
    if (!file_.is_open()) return;
    travel::label_reference::writeFooter(file_, frames_);
    file_.close();
    if (!file_) throw AppError(path_ + ": write error");
}

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
    if (t.tracked)
        std::printf(
            "  tracking: frames tracked %zu (ego-motion from poses %zu, from scan registration "
            "%zu), tracks %u, tracked clusters %zu, moving %zu\n",
            t.tracked, t.tracked_with_poses, t.tracked - t.tracked_with_poses, t.tracks,
            t.tracked_clusters, t.moving_clusters);
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

}  // namespace travel::apps
