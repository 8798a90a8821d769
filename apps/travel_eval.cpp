// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-eval: the paper-style evaluation of TRAVEL and its baselines on SemanticKITTI.
//
//   travel-eval report --scans DIR --labels DIR --out DIR [--methods a,b,...]
//       every method over every labelled frame: report.md (ground tables for protocols A and B,
//       an object table) and frames.csv (one row per method and frame).
//   travel-eval sweep --scans DIR --labels DIR --out DIR --sweep KEY=v1,v2,... [--method NAME]
//       one method, one parameter: sweep_KEY.csv and three PNG plots (ground F1, objects, time).
//
// Metrics and timings are those of travel-kitti (same libtravel APIs), aggregated differently.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/img/CImage.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "travel/Errors.hpp"
#include "travel/KittiIO.hpp"
#include "travel/Metrics.hpp"
#include "travel/ObjectMetrics.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/eval/Segmenter.hpp"

namespace fs = std::filesystem;
using mrpt::img::CImage;
using mrpt::img::TColor;

namespace {

constexpr travel::GroundProtocol kProtocols[2] = {travel::GroundProtocol::A,
                                                  travel::GroundProtocol::B};

// ---------------------------------------------------------------------------------------------
// Small helpers

std::vector<std::string> splitList(const std::string& text, char sep) {
    std::vector<std::string> items;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, sep)) items.push_back(item);
    if (!text.empty() && text.back() == sep) items.emplace_back();  // "a,b," has an empty last
    return items;
}

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), fmt, v);
    return buf;
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const std::size_t colon = line.find(':');
        if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
    return "unknown CPU";
}

std::string nowText() {
    const std::time_t t = std::time(nullptr);
    char buf[64];
    std::strftime(buf, sizeof(buf), "%Y-%m-%d %H:%M %Z", std::localtime(&t));
    return buf;
}

// ---------------------------------------------------------------------------------------------
// Frames

struct FrameRef {
    std::string scan, label, name;  // name: "<sequence>/<stem>"
};

// A sequence's name for the report: ".../sequences/00/velodyne" -> "00".
std::string sequenceName(const std::string& scans_dir) {
    fs::path p = fs::path(scans_dir).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    if (p.filename() == "velodyne" && p.has_parent_path()) p = p.parent_path();
    return p.filename().string();
}

// The scans that have a label file, over all (scans, labels) pairs, in order.
std::vector<FrameRef> labelledFrames(const std::vector<std::string>& scans,
                                     const std::vector<std::string>& labels, int max_frames) {
    if (scans.empty() || labels.empty())
        throw TCLAP::CmdLineParseException("--scans DIR and --labels DIR are required", "--scans");
    if (scans.size() != labels.size())
        throw TCLAP::CmdLineParseException(
            "give one --labels DIR per --scans DIR (paired by order): " +
                std::to_string(scans.size()) + " --scans, " + std::to_string(labels.size()) +
                " --labels",
            "--labels");
    std::vector<FrameRef> frames;
    for (std::size_t s = 0; s < scans.size(); ++s) {
        if (!fs::is_directory(labels[s]))
            throw travel::InputError("labels directory " + labels[s] + " does not exist");
        const std::string seq = sequenceName(scans[s]);
        for (const std::string& bin : travel::listFiles(scans[s], ".bin")) {
            const std::string stem = fs::path(bin).stem().string();
            const fs::path label = fs::path(labels[s]) / (stem + ".label");
            if (fs::exists(label)) frames.push_back({bin, label.string(), seq + "/" + stem});
        }
    }
    if (frames.empty()) {
        std::string dirs;
        for (std::size_t s = 0; s < scans.size(); ++s)
            dirs += (s ? ", " : "") + scans[s] + " with " + labels[s];
        throw travel::InputError("no labelled frames: no scan has a <stem>.label (" + dirs + ")");
    }
    if (max_frames > 0 && frames.size() > static_cast<std::size_t>(max_frames))
        frames.resize(max_frames);
    return frames;
}

// "sequence 00, 000000-000002; sequence 01, ..." for the report header.
std::string describeFrames(const std::vector<FrameRef>& frames) {
    std::string text;
    std::size_t i = 0;
    while (i < frames.size()) {
        const std::string seq = frames[i].name.substr(0, frames[i].name.find('/'));
        std::size_t j = i;
        // A run ends where the sequence changes or restarts (the same one given twice).
        while (j + 1 < frames.size() && frames[j + 1].name.rfind(seq + "/", 0) == 0 &&
               frames[j + 1].name > frames[j].name)
            ++j;
        const auto stem = [&](std::size_t k) { return frames[k].name.substr(seq.size() + 1); };
        text += (text.empty() ? "" : "; ") + std::string("sequence ") + seq + ", " + stem(i) +
                (j > i ? "-" + stem(j) : "");
        i = j + 1;
    }
    return text;
}

// ---------------------------------------------------------------------------------------------
// Running one method over the frames

struct FrameRow {
    std::string frame;
    std::size_t points = 0;
    travel::GroundScores ground[2];  // protocols A, B
    bool objects = false;            // the method clustered this frame
    travel::SegmentationEntropy entropy;
    double coverage = 0, purity = 0;
    std::size_t instances = 0, clustered = 0, split = 0, merged = 0;
    uint32_t clusters = 0;
    double ground_ms = 0, objects_ms = 0;
};

struct MethodRun {
    std::string method;
    std::vector<FrameRow> rows;
    travel::ObjectScoreAccumulator objects;
    bool clusters = false;  // any frame clustered: the method has an object stage
};

MethodRun runMethod(const std::string& method, const travel::Params& params,
                    const std::vector<FrameRef>& frames, const std::string& progress_label) {
    MethodRun run;
    run.method = method;
    const std::unique_ptr<travel::eval::Segmenter> seg =
        travel::eval::makeSegmenter(method, params);
    travel::PointCloud cloud;
    travel::eval::Segmentation out;
    const bool tty = isatty(fileno(stderr));
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const FrameRef& ref = frames[f];
        // A terminal gets one updating line; a log every 100th frame (and the first and last).
        if (tty)
            std::fprintf(stderr, "\r%s: frame %zu/%zu %s   ", progress_label.c_str(), f + 1,
                         frames.size(), ref.name.c_str());
        else if (f == 0 || (f + 1) % 100 == 0 || f + 1 == frames.size())
            std::fprintf(stderr, "%s: frame %zu/%zu %s\n", progress_label.c_str(), f + 1,
                         frames.size(), ref.name.c_str());
        FrameRow row;
        row.frame = ref.name;
        try {
            travel::readKittiBin(ref.scan, cloud);
            const std::vector<uint32_t> gt = travel::readLabelFile(ref.label, cloud.size());
            seg->segment(cloud, out);
            for (int p = 0; p < 2; ++p)
                row.ground[p] = travel::scoresFrom(travel::countGround(
                    out.labels, gt, cloud.z, params.sensor_height, kProtocols[p]));
            row.points = cloud.size();
            row.ground_ms = out.ground_ms;
            row.objects_ms = out.objects_ms;
            row.clusters = out.cluster_id.empty()
                               ? 0
                               : *std::max_element(out.cluster_id.begin(), out.cluster_id.end());
            // Ground-only methods have no object stage: their object scores would be all zero.
            row.objects = out.objects_ms > 0 || row.clusters > 0;
            if (row.objects) {
                const travel::ObjectScores o =
                    travel::evaluateObjects(out.cluster_id, out.labels, gt, cloud);
                run.objects.add(o);
                row.entropy = o.entropy;
                row.coverage = o.mean_coverage;
                row.purity = o.mean_purity;
                row.instances = o.instances.size();
                row.clustered = o.clustered;
                row.split = o.split;
                row.merged = o.merged;
                run.clusters = true;
            }
        } catch (const std::exception& e) {
            // Name the scan in every error (the pipeline's own messages do not know it).
            const std::string what = e.what();
            throw std::runtime_error(what.find(ref.scan) == std::string::npos &&
                                             what.find(ref.label) == std::string::npos
                                         ? ref.scan + ": " + what
                                         : what);
        }
        run.rows.push_back(std::move(row));
    }
    if (tty) std::fprintf(stderr, "\n");
    return run;
}

struct Summary {
    travel::MeanStd precision[2], recall[2], f1[2], accuracy[2];
    travel::MeanStd use, ose;  // per-frame sums (the paper's values)
    travel::ObjectSummary objects;
    double ground_ms = 0, objects_ms = 0;  // medians
    bool clusters = false;
};

Summary summarize(const MethodRun& run) {
    Summary s;
    std::vector<double> v[2][4], use, ose, gms, oms;
    for (const FrameRow& r : run.rows) {
        for (int p = 0; p < 2; ++p) {
            v[p][0].push_back(r.ground[p].precision);
            v[p][1].push_back(r.ground[p].recall);
            v[p][2].push_back(r.ground[p].f1);
            v[p][3].push_back(r.ground[p].accuracy);
        }
        gms.push_back(r.ground_ms);
        if (!r.objects) continue;
        use.push_back(r.entropy.use_sum);
        ose.push_back(r.entropy.ose_sum);
        oms.push_back(r.objects_ms);
    }
    for (int p = 0; p < 2; ++p) {
        s.precision[p] = travel::meanStd(v[p][0]);
        s.recall[p] = travel::meanStd(v[p][1]);
        s.f1[p] = travel::meanStd(v[p][2]);
        s.accuracy[p] = travel::meanStd(v[p][3]);
    }
    s.use = travel::meanStd(use);
    s.ose = travel::meanStd(ose);
    s.objects = run.objects.summary();
    s.ground_ms = travel::median(gms);
    s.objects_ms = travel::median(oms);
    s.clusters = run.clusters;
    return s;
}

void createDir(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw travel::InputError("cannot create output directory " + dir + ": " + ec.message());
}

std::ofstream openOut(const fs::path& path) {
    std::ofstream out(path);
    if (!out) throw travel::InputError("cannot write " + path.string());
    return out;
}

// ---------------------------------------------------------------------------------------------
// report

std::string reportMarkdown(const std::vector<MethodRun>& runs, const std::vector<Summary>& sums,
                           const std::vector<FrameRef>& frames, const std::string& setup) {
    std::ostringstream md;
    md << "# TRAVEL evaluation report\n\n"
       << frames.size() << " labelled SemanticKITTI frames (" << describeFrames(frames) << "); "
       << setup << "; machine: " << cpuModel() << ", " << sysconf(_SC_NPROCESSORS_ONLN)
       << " logical CPUs, single thread; " << nowText() << ".\n\n"
       << "Mean (mu) and population standard deviation (sigma) over frames; ms = median "
          "milliseconds per frame (each frame run once, cold caches).\n";
    for (int p = 0; p < 2; ++p) {
        md << "\n## Ground, protocol " << travel::protocolName(kProtocols[p]) << "\n\n"
           << "| method | P | R | F1 μ | F1 σ | accuracy μ | accuracy σ | ms |\n"
           << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
        for (std::size_t m = 0; m < runs.size(); ++m) {
            const Summary& s = sums[m];
            md << "| " << runs[m].method << " | " << format("%.2f", s.precision[p].mean) << " | "
               << format("%.2f", s.recall[p].mean) << " | " << format("%.2f", s.f1[p].mean) << " | "
               << format("%.2f", s.f1[p].std) << " | " << format("%.2f", s.accuracy[p].mean)
               << " | " << format("%.2f", s.accuracy[p].std) << " | " << format("%.1f", s.ground_ms)
               << " |\n";
        }
    }
    md << "\n## Objects\n\n"
       << "| method | USE μ | USE σ | OSE μ | OSE σ | coverage | purity | split | merged | ms |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::size_t instances = 0;
    for (std::size_t m = 0; m < runs.size(); ++m) {
        const Summary& s = sums[m];
        if (!s.clusters) continue;
        instances = s.objects.instances;
        md << "| " << runs[m].method << " | " << format("%.2f", s.use.mean) << " | "
           << format("%.2f", s.use.std) << " | " << format("%.2f", s.ose.mean) << " | "
           << format("%.2f", s.ose.std) << " | " << format("%.3f", s.objects.mean_coverage) << " | "
           << format("%.3f", s.objects.mean_purity) << " | " << s.objects.split << " | "
           << s.objects.merged << " | " << format("%.1f", s.objects_ms) << " |\n";
    }
    md << "\nUSE / OSE: per-frame sums over clusters / ground-truth objects (paper eqs. 6-7, "
          "natural log). Coverage, purity, split, merged: pooled over the "
       << instances
       << " thing instances with >= 50 points. Ground-only methods are not in this table.\n";
    return md.str();
}

void writeFramesCsv(const fs::path& path, const std::vector<MethodRun>& runs) {
    std::ofstream csv = openOut(path);
    csv << "method,frame,points,A_precision,A_recall,A_f1,A_accuracy,B_precision,B_recall,B_f1,"
           "B_accuracy,USE_sum,OSE_sum,USE_mean,OSE_mean,gt_objects,mean_coverage,mean_purity,"
           "instances,clustered,split,merged,clusters,ground_ms,objects_ms\n";
    for (const MethodRun& run : runs) {
        for (const FrameRow& r : run.rows) {
            csv << run.method << ',' << r.frame << ',' << r.points;
            for (int p = 0; p < 2; ++p)
                csv << ',' << r.ground[p].precision << ',' << r.ground[p].recall << ','
                    << r.ground[p].f1 << ',' << r.ground[p].accuracy;
            if (r.objects)  // empty cells, not zeros, for methods without an object stage
                csv << ',' << r.entropy.use_sum << ',' << r.entropy.ose_sum << ','
                    << r.entropy.use_mean << ',' << r.entropy.ose_mean << ','
                    << r.entropy.num_gt_objects << ',' << r.coverage << ',' << r.purity << ','
                    << r.instances << ',' << r.clustered << ',' << r.split << ',' << r.merged;
            else
                csv << ",,,,,,,,,,,";
            csv << ',' << r.clusters << ',' << r.ground_ms << ',' << r.objects_ms << '\n';
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Plots drawn into an mrpt::img::CImage (no display needed)

struct Series {
    std::string name;
    std::vector<double> y;
    TColor color;
};

const TColor kBlue(31, 119, 180), kOrange(230, 120, 20), kGreen(44, 160, 44), kRed(214, 39, 40),
    kPurple(148, 103, 189), kBlack(0, 0, 0), kGrid(225, 225, 225), kGrey(90, 90, 90);

// 1, 2 or 5 times a power of ten, giving about `target` intervals over `range`.
double niceStep(double range, int target) {
    const double raw = range / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / mag;
    return (f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10) * mag;
}

std::string tickText(double v, double step) {
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
    return buf;
}

// Text in the 9x15 / 10x20 bitmap fonts: width in pixels.
int textWidth(const std::string& s, int char_w) {
    return static_cast<int>(s.size()) * char_w;
}

/// One line chart in the rectangle (x0, y0, w, h) of `img`: title, legend row, y label above
/// the axis, ticks on both axes (an x tick at every swept value, labelled with its text).
void drawChart(CImage& img, int x0, int y0, int w, int h, const std::string& title,
               const std::string& x_label, const std::string& y_label,
               const std::vector<double>& xs, const std::vector<std::string>& x_text,
               const std::vector<Series>& series, bool from_zero = false) {
    const int left = x0 + 80, right = x0 + w - 25, top = y0 + 70, bottom = y0 + h - 55;

    img.selectTextFont("10x20");
    img.textOut(x0 + (w - textWidth(title, 10)) / 2, y0 + 10, title, kBlack);

    // Value ranges; NaN marks "no value" (e.g. objects of a ground-only method).
    double ylo = INFINITY, yhi = -INFINITY;
    for (const Series& s : series)
        for (double v : s.y)
            if (std::isfinite(v)) ylo = std::min(ylo, v), yhi = std::max(yhi, v);
    const bool has_data = std::isfinite(ylo);
    if (!has_data) ylo = 0, yhi = 1;
    if (from_zero) ylo = std::min(ylo, 0.0);  // times: show the scale of a change honestly
    if (yhi - ylo < 1e-9 * std::max(1.0, std::abs(yhi))) {  // flat: give it some height
        const double pad = std::max(std::abs(yhi) * 0.05, 1e-3);
        ylo -= pad, yhi += pad;
    }
    const double span = yhi - ylo, ystep = niceStep(span * 1.2, 5);
    ylo = from_zero && ylo >= 0 ? 0 : std::floor((ylo - 0.1 * span) / ystep) * ystep;
    yhi = std::ceil((yhi + 0.1 * span) / ystep) * ystep;
    double xlo = *std::min_element(xs.begin(), xs.end());
    double xhi = *std::max_element(xs.begin(), xs.end());
    const double xpad = xhi > xlo ? 0.06 * (xhi - xlo) : 1.0;
    xlo -= xpad, xhi += xpad;
    const auto px = [&](double x) {
        return left + static_cast<int>(std::lround((x - xlo) / (xhi - xlo) * (right - left)));
    };
    const auto py = [&](double y) {
        return bottom - static_cast<int>(std::lround((y - ylo) / (yhi - ylo) * (bottom - top)));
    };

    // Grid and tick labels.
    img.selectTextFont("9x15");
    for (int k = 0;; ++k) {
        const double y = ylo + k * ystep;
        if (y > yhi + ystep * 1e-6) break;
        const int yy = py(y);
        img.line(left, yy, right, yy, kGrid);
        img.line(left - 5, yy, left, yy, kBlack);
        const std::string t = tickText(y, ystep);
        img.textOut(left - 9 - textWidth(t, 9), yy - 7, t, kBlack);
    }
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const int xx = px(xs[i]);
        img.line(xx, top, xx, bottom, kGrid);
        img.line(xx, bottom, xx, bottom + 5, kBlack);
        img.textOut(xx - textWidth(x_text[i], 9) / 2, bottom + 9, x_text[i], kBlack);
    }
    img.rectangle(left, top, right, bottom, kBlack);
    img.textOut(left + (right - left - textWidth(x_label, 9)) / 2, bottom + 30, x_label, kGrey);
    img.textOut(x0 + 8, top - 24, y_label, kGrey);

    // Legend, right-aligned in the row between the title and the plot (never over the data).
    int lx = right;
    for (auto it = series.rbegin(); it != series.rend(); ++it) lx -= 56 + textWidth(it->name, 9);
    for (const Series& s : series) {
        img.line(lx, top - 17, lx + 26, top - 17, s.color, 3);
        img.filledRectangle(lx + 10, top - 20, lx + 16, top - 14, s.color);
        img.textOut(lx + 32, top - 24, s.name, kBlack);
        lx += 56 + textWidth(s.name, 9);
    }

    if (!has_data) {
        const std::string note = "no values: this method has no object stage";
        img.textOut((left + right - textWidth(note, 9)) / 2, (top + bottom) / 2 - 7, note, kGrey);
    }

    // Lines and markers.
    for (const Series& s : series) {
        int prev_x = 0, prev_y = 0;
        bool has_prev = false;
        for (std::size_t i = 0; i < xs.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.y[i])) {
                has_prev = false;
                continue;
            }
            const int xx = px(xs[i]), yy = py(s.y[i]);
            if (has_prev) img.line(prev_x, prev_y, xx, yy, s.color, 2);
            img.filledRectangle(xx - 4, yy - 4, xx + 4, yy + 4, s.color);
            prev_x = xx, prev_y = yy, has_prev = true;
        }
    }
}

CImage whiteImage(int w, int h) {
    CImage img(w, h, mrpt::img::CH_RGB);
    img.filledRectangle(0, 0, w - 1, h - 1, TColor(255, 255, 255));
    return img;
}

void savePng(const CImage& img, const fs::path& path) {
    if (!img.saveToFile(path.string())) throw travel::InputError("cannot write " + path.string());
}

// ---------------------------------------------------------------------------------------------
// sweep

struct SweepSpec {
    std::string key;
    std::vector<std::string> values;
};

SweepSpec parseSweep(const std::string& spec, const travel::Params& base) {
    const std::string help =
        "--sweep '" + spec + "': expected KEY=v1,v2,... (e.g. " + "tgf_resolution=2,4,6,8,10)";
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0) throw travel::ConfigError(help);
    SweepSpec s{spec.substr(0, eq), splitList(spec.substr(eq + 1), ',')};
    if (s.values.empty()) throw travel::ConfigError(help + ": no values");
    for (const std::string& v : s.values) {
        if (v.empty()) throw travel::ConfigError(help + ": empty value");
        // Every value is checked (key known, value in range, params consistent) before the
        // first run, so a typo in the last value does not waste the whole sweep.
        travel::Params p = base;
        travel::applyOverride(s.key + "=" + v, p);
        p.validate();
    }
    return s;
}

// x positions: the values themselves when all are numbers, else 0, 1, 2, ... (e.g. booleans).
std::vector<double> sweepPositions(const std::vector<std::string>& values) {
    std::vector<double> xs;
    for (const std::string& v : values) {
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        if (end == v.c_str() || *end != '\0' || !std::isfinite(x)) {
            xs.clear();
            for (std::size_t i = 0; i < values.size(); ++i) xs.push_back(static_cast<double>(i));
            return xs;
        }
        xs.push_back(x);
    }
    return xs;
}

void writeSweep(const fs::path& dir, const std::string& method, const SweepSpec& spec,
                const std::vector<Summary>& sums, std::size_t frames) {
    const std::string stem = "sweep_" + spec.key;
    std::ofstream csv = openOut(dir / (stem + ".csv"));
    csv << spec.key
        << ",frames,B_precision,B_recall,B_f1,B_f1_std,A_f1,A_f1_std,coverage,purity,USE,OSE,"
           "ground_ms_median,objects_ms_median\n";
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const Summary& s = sums[i];
        csv << spec.values[i] << ',' << frames << ',' << s.precision[1].mean << ','
            << s.recall[1].mean << ',' << s.f1[1].mean << ',' << s.f1[1].std << ',' << s.f1[0].mean
            << ',' << s.f1[0].std;
        if (s.clusters)
            csv << ',' << s.objects.mean_coverage << ',' << s.objects.mean_purity << ','
                << s.use.mean << ',' << s.ose.mean;
        else
            csv << ",,,,";
        csv << ',' << s.ground_ms << ',' << s.objects_ms << '\n';
    }

    const std::vector<double> xs = sweepPositions(spec.values);
    const std::string what = method + ", " + std::to_string(frames) + " frames";
    const auto col = [&](auto get) {
        std::vector<double> y;
        for (const Summary& s : sums) y.push_back(get(s));
        return y;
    };
    const auto obj = [&](auto get) {  // NaN (not drawn) when the method does not cluster
        return col([&](const Summary& s) { return s.clusters ? get(s) : NAN; });
    };

    CImage ground = whiteImage(800, 500);
    drawChart(ground, 0, 0, 800, 500, "Ground F1 vs " + spec.key + " (" + what + ")", spec.key,
              "F1 [%]", xs, spec.values,
              {{"F1 protocol B", col([](const Summary& s) { return s.f1[1].mean; }), kBlue},
               {"F1 protocol A", col([](const Summary& s) { return s.f1[0].mean; }), kOrange}});
    savePng(ground, dir / (stem + "_ground.png"));

    CImage objects = whiteImage(800, 900);
    drawChart(objects, 0, 0, 800, 450, "Thing instances vs " + spec.key + " (" + what + ")",
              spec.key, "share of instance / cluster", xs, spec.values,
              {{"coverage", obj([](const Summary& s) { return s.objects.mean_coverage; }), kGreen},
               {"purity", obj([](const Summary& s) { return s.objects.mean_purity; }), kPurple}});
    drawChart(objects, 0, 450, 800, 450, "Segmentation entropy vs " + spec.key, spec.key,
              "per-frame sum (lower is better)", xs, spec.values,
              {{"USE", obj([](const Summary& s) { return s.use.mean; }), kRed},
               {"OSE", obj([](const Summary& s) { return s.ose.mean; }), kBlue}});
    objects.line(20, 450, 780, 450, kGrid);
    savePng(objects, dir / (stem + "_objects.png"));

    CImage time = whiteImage(800, 500);
    drawChart(time, 0, 0, 800, 500, "Median ms per frame vs " + spec.key + " (" + what + ")",
              spec.key, "milliseconds (single thread)", xs, spec.values,
              {{"ground", col([](const Summary& s) { return s.ground_ms; }), kBlue},
               {"objects", obj([](const Summary& s) { return s.objects_ms; }), kGreen},
               {"ground + objects",
                col([](const Summary& s) { return s.ground_ms + s.objects_ms; }), kBlack}},
              true);
    savePng(time, dir / (stem + "_time.png"));
}

// ---------------------------------------------------------------------------------------------

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Evaluation of TRAVEL and its baselines on SemanticKITTI (labelled frames only).\n"
        "  report: runs every --methods method (default: all) over the frames and writes "
        "<out>/report.md (ground P, R, F1 and accuracy mu/sigma and median ms per method, one "
        "table per protocol A and B; objects USE/OSE mu/sigma, coverage, purity, split, merged "
        "and median ms for the methods that cluster), printed to stdout as well, and "
        "<out>/frames.csv (one row per method and frame, every per-frame value).\n"
        "  sweep: runs one --method (default travel) once per value of one parameter "
        "(--sweep KEY=v1,v2,..., any key of travel-kitti --print-params) and writes "
        "<out>/sweep_KEY.csv "
        "(per value: B P/R/F1, A F1, coverage, purity, USE, OSE, median ground / objects ms) and "
        "the plots sweep_KEY_ground.png (F1, protocols A and B), sweep_KEY_objects.png (coverage, "
        "purity; USE, OSE) and sweep_KEY_time.png. Paper studies: tgf_resolution=2,4,6,8,10, "
        "vertical_ring_span=1,2,3,4,5, vertical_column_extension=1,3,5,10,20.\n"
        "Several sequences: repeat --scans and --labels (paired by order).",
        ' ', "0.1");
    std::vector<std::string> commands{"report", "sweep"};
    TCLAP::ValuesConstraint<std::string> command_values(commands);
    TCLAP::UnlabeledValueArg<std::string> command("command", "report or sweep", true, "",
                                                  &command_values, cmd);
    TCLAP::MultiArg<std::string> scans("", "scans", "Directory of KITTI .bin scans (repeatable)",
                                       false, "DIR", cmd);
    TCLAP::MultiArg<std::string> labels(
        "", "labels", "SemanticKITTI .label directory for the --scans of the same position", false,
        "DIR", cmd);
    TCLAP::ValueArg<std::string> out("", "out", "Output directory (created); required", false, "",
                                     "DIR", cmd);
    TCLAP::ValueArg<std::string> methods("", "methods",
                                         "report: comma-separated methods (default: all of them)",
                                         false, "", "A,B,...", cmd);
    TCLAP::ValueArg<std::string> method("", "method", "sweep: the method (default travel)", false,
                                        "travel", "NAME", cmd);
    TCLAP::ValueArg<std::string> sweep("", "sweep",
                                       "sweep: KEY=v1,v2,... e.g. tgf_resolution=2,4,6,8,10", false,
                                       "", "KEY=VALUES", cmd);
    TCLAP::ValueArg<std::string> preset("", "preset", "Sensor preset from share/presets", false,
                                        "hdl64", "NAME", cmd);
    TCLAP::ValueArg<std::string> config("", "config",
                                        "YAML or ini parameter file applied after the preset",
                                        false, "", "FILE", cmd);
    TCLAP::MultiArg<std::string> set(
        "", "set", "Override one parameter, e.g. --set tgf_resolution=4", false, "KEY=VALUE", cmd);
    TCLAP::ValueArg<int> max_frames("", "max-frames", "Use at most the first N labelled frames",
                                    false, -1, "N", cmd);
    const travel::apps::PrintConfigFlag print_config(cmd);
    if (const auto exit_code = travel::apps::parseCommandLine(cmd, argc, argv)) return *exit_code;
    const travel::Config configuration =
        travel::apps::loadAppConfig(preset.getValue(), config.getValue(), set.getValue());
    if (print_config.print(configuration)) return 0;

    const bool is_sweep = command.getValue() == "sweep";
    // Configuration errors first, before any file is read.
    if (!out.isSet()) throw TCLAP::CmdLineParseException("--out DIR is required", "--out");
    if (max_frames.isSet() && max_frames.getValue() < 1)
        throw TCLAP::CmdLineParseException("--max-frames must be at least 1", "--max-frames");
    if (is_sweep && methods.isSet())
        throw TCLAP::CmdLineParseException("sweep runs one --method, not --methods", "--methods");
    if (!is_sweep && (sweep.isSet() || method.isSet()))
        throw TCLAP::CmdLineParseException("report takes --methods; --sweep/--method are for sweep",
                                           sweep.isSet() ? "--sweep" : "--method");
    if (is_sweep && !sweep.isSet())
        throw TCLAP::CmdLineParseException("sweep needs --sweep KEY=v1,v2,...", "--sweep");
    const travel::Params& params = configuration.travel;
    std::string setup = "preset " + preset.getValue();
    if (config.isSet()) setup += ", config " + config.getValue();
    for (const std::string& kv : set.getValue()) setup += ", " + kv;

    std::vector<std::string> names =
        methods.isSet() ? splitList(methods.getValue(), ',') : travel::eval::methodNames();
    if (is_sweep) names = {method.getValue()};
    for (const std::string& name : names)
        travel::eval::makeSegmenter(name, params);  // throws, listing the valid names
    const SweepSpec spec = is_sweep ? parseSweep(sweep.getValue(), params) : SweepSpec{};

    const std::vector<FrameRef> frames =
        labelledFrames(scans.getValue(), labels.getValue(), max_frames.getValue());
    createDir(out.getValue());
    const fs::path dir(out.getValue());

    if (!is_sweep) {
        std::vector<MethodRun> runs;
        std::vector<Summary> sums;
        for (const std::string& name : names) {
            runs.push_back(runMethod(name, params, frames, name));
            sums.push_back(summarize(runs.back()));
        }
        const std::string md = reportMarkdown(runs, sums, frames, setup);
        openOut(dir / "report.md") << md;
        writeFramesCsv(dir / "frames.csv", runs);
        std::cout << md << "\nWritten: " << (dir / "report.md").string() << ", "
                  << (dir / "frames.csv").string() << "\n";
        return 0;
    }

    std::vector<Summary> sums;
    for (const std::string& value : spec.values) {
        travel::Params p = params;
        travel::applyOverride(spec.key + "=" + value, p);
        p.validate();
        const MethodRun run = runMethod(names[0], p, frames, spec.key + "=" + value);
        sums.push_back(summarize(run));
        const Summary& s = sums.back();
        std::printf("%s=%-8s B F1 %6.2f  A F1 %6.2f", spec.key.c_str(), value.c_str(), s.f1[1].mean,
                    s.f1[0].mean);
        if (s.clusters)
            std::printf("  coverage %.3f purity %.3f  USE %6.2f OSE %6.2f", s.objects.mean_coverage,
                        s.objects.mean_purity, s.use.mean, s.ose.mean);
        std::printf("  ms %.2f + %.2f\n", s.ground_ms, s.objects_ms);
    }
    writeSweep(dir, names[0], spec, sums, frames.size());
    const std::string stem = (dir / ("sweep_" + spec.key)).string();
    std::printf("Written: %s.csv, %s_ground.png, %s_objects.png, %s_time.png\n", stem.c_str(),
                stem.c_str(), stem.c_str(), stem.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-eval", run, argc, argv);
}
