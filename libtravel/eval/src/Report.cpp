// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/Report.hpp"
#include "travel/Text.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/eval/KittiIO.hpp"

namespace travel::eval {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

std::string sequenceName(const std::string& scans_dir) {
    fs::path p = fs::path(scans_dir).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    if (p.filename() == "velodyne" && p.has_parent_path()) p = p.parent_path();
    return p.filename().string();
}

std::vector<FrameRef> labelledFrames(const std::vector<std::string>& inputs,
                                     const std::vector<std::string>& labels, std::size_t max_frames,
                                     ScanFormat format) {
    if (!labels.empty() && labels.size() != inputs.size())
        throw InputError(
            "give one labels folder per input (paired by order): " + std::to_string(inputs.size()) +
            " inputs, " + std::to_string(labels.size()) + " labels folders");
    std::vector<FrameRef> frames;
    for (std::size_t s = 0; s < inputs.size(); ++s) {
        const ScanList scans = listScans(inputs[s], format);
        const std::string labels_dir = labels.empty() ? scans.labels_dir : labels[s];
        if (labels_dir.empty())
            throw InputError(inputs[s] +
                             ": no labels folder (a KITTI sequence folder has labels/ "
                             "beside velodyne/; else give --labels DIR)");
        requireDirectory(labels_dir, "labels directory");
        const std::string seq = sequenceName(scans.scans_dir);
        const std::size_t before = frames.size();
        for (const std::string& scan : scans.files) {
            const std::string stem = fs::path(scan).stem().string();
            const fs::path label = fs::path(labels_dir) / (stem + ".label");
            if (fs::exists(label))
                frames.push_back({scan, label.string(), seq + "/" + stem, format});
        }
        // An input that adds no frame is a mistake (a wrong --labels, labels not yet
        // downloaded), not a sequence to leave out of the report silently.
        if (frames.size() == before)
            throw InputError("no labelled frames in " + inQuotes(inputs[s]) + ": none of its " +
                             std::to_string(scans.files.size()) + " scans has a <stem>.label in " +
                             inQuotes(labels_dir));
    }
    if (max_frames > 0 && frames.size() > max_frames) frames.resize(max_frames);
    return frames;
}

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

void addFrame(const FrameRef& ref, const FrameEvaluation& frame, MethodRun& run,
              EvaluationAccumulator& totals) {
    if (frame.segmentation.mount && !run.mount) run.mount = frame.segmentation.mount;
    totals.add(frame);
    FrameRow row;
    row.frame = ref.name;
    row.points = frame.cloud.size();
    for (int p = 0; p < 2; ++p) row.ground[p] = frame.ground[p];
    row.ground_ms = frame.segmentation.ground_ms;
    row.objects_ms = frame.segmentation.objects_ms;
    row.clusters = frame.clusters;
    // Ground-only methods have no object stage: their object scores would be all zero.
    row.objects = frame.clustered;
    if (row.objects) {
        const ObjectScores& o = frame.objects;
        row.entropy = o.entropy;
        row.coverage = o.mean_coverage;
        row.purity = o.mean_purity;
        row.instances = o.instances.size();
        row.clustered = o.clustered;
        row.split = o.split;
        row.merged = o.merged;
    }
    run.rows.push_back(std::move(row));
}

std::string reportMarkdown(const std::vector<MethodRun>& runs, const std::vector<FrameRef>& frames,
                           const std::string& setup, unsigned jobs) {
    std::ostringstream md;
    md << "# TRAVEL evaluation report\n\n"
       << frames.size() << " labelled SemanticKITTI frames (" << describeFrames(frames) << "); "
       << setup << "; machine: " << cpuModel() << ", " << sysconf(_SC_NPROCESSORS_ONLN)
       << " logical CPUs, " << jobs << (jobs == 1 ? " worker thread" : " worker threads")
       << " (each frame on one); " << nowText() << ".\n\n"
       << "Mean (mu) and population standard deviation (sigma) over frames; ms = median "
          "CPU milliseconds per frame of the method's thread (each frame run once).\n";
    for (int p = 0; p < 2; ++p) {
        md << "\n## Ground, protocol " << protocolName(kGroundProtocols[p]) << "\n\n"
           << "| method | P | R | F1 μ | F1 σ | accuracy μ | accuracy σ | ms |\n"
           << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
        std::string partly;  // the methods whose means leave frames out
        for (std::size_t m = 0; m < runs.size(); ++m) {
            const EvaluationSummary& s = runs[m].summary;
            // No frame with ground truth under this protocol: no value, not a score of 0.
            const bool none = s.f1[p].n == 0;
            const auto cell = [&](const char* fmt, double v) {
                return none ? "-" : format(fmt, v);
            };
            md << "| " << runs[m].method << " | " << cell("%.2f", s.precision[p].mean) << " | "
               << cell("%.2f", s.recall[p].mean) << " | " << cell("%.2f", s.f1[p].mean) << " | "
               << cell("%.2f", s.f1[p].std) << " | " << cell("%.2f", s.accuracy[p].mean) << " | "
               << cell("%.2f", s.accuracy[p].std) << " | "
               << (s.f1[0].n + s.f1[1].n == 0 ? "-" : format("%.1f", s.ground_ms)) << " |\n";
            if (s.f1[p].n < frames.size())
                partly +=
                    (partly.empty() ? "" : ", ") + runs[m].method + " " + std::to_string(s.f1[p].n);
        }
        if (!partly.empty())
            md << "\nScored frames (of " << frames.size() << "): " << partly
               << "; the others hold no ground truth under this protocol ('-': none does).\n";
    }
    md << "\n## Objects\n\n"
       << "| method | USE μ | USE σ | OSE μ | OSE σ | coverage | purity | split | merged | ms |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::size_t instances = 0;
    for (std::size_t m = 0; m < runs.size(); ++m) {
        const EvaluationSummary& s = runs[m].summary;
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

void writeFramesCsv(std::ostream& csv, const std::vector<MethodRun>& runs) {
    csv << "method,frame,points,A_precision,A_recall,A_f1,A_accuracy,B_precision,B_recall,B_f1,"
           "B_accuracy,USE_sum,OSE_sum,USE_mean,OSE_mean,gt_objects,mean_coverage,mean_purity,"
           "instances,clustered,split,merged,clusters,ground_ms,objects_ms\n";
    for (const MethodRun& run : runs) {
        for (const FrameRow& r : run.rows) {
            csv << run.method << ',' << r.frame << ',' << r.points;
            for (int p = 0; p < 2; ++p)
                if (r.ground[p].points == 0)  // nothing scored under this protocol
                    csv << ",,,,";
                else
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

SweepSpec parseSweep(const std::string& spec, const Params& base) {
    const std::string help =
        "--sweep '" + spec + "': expected KEY=v1,v2,... (e.g. " + "tgf_resolution=2,4,6,8,10)";
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0) throw ConfigError(help);
    SweepSpec s{spec.substr(0, eq), travel::splitList(spec.substr(eq + 1), ',')};
    // travel.KEY as --set writes it: a sweep varies the travel section's keys, no other's.
    const auto [section, key] = sectionAndKey(s.key);
    if (!section.empty() && section != "travel")
        throw ConfigError(help + ": a sweep varies the keys of section travel only");
    s.key = key;
    if (s.values.empty()) throw ConfigError(help + ": no values");
    for (const std::string& v : s.values) {
        if (v.empty()) throw ConfigError(help + ": empty value");
        // Every value is checked (key known, value in range, params consistent) before the
        // first run, so a typo in the last value does not waste the whole sweep.
        Params p = base;
        applyOverride(s.key + "=" + v, p);
        p.validate();
    }
    return s;
}

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

void writeSweepCsv(std::ostream& csv, const SweepSpec& spec,
                   const std::vector<EvaluationSummary>& sums, std::size_t frames) {
    csv << spec.key
        << ",frames,B_precision,B_recall,B_f1,B_f1_std,A_f1,A_f1_std,coverage,purity,USE,OSE,"
           "ground_ms_median,objects_ms_median\n";
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const EvaluationSummary& s = sums[i];
        // Empty cells, not zeros, where no frame had ground truth under the protocol.
        csv << spec.values[i] << ',' << frames;
        if (s.f1[1].n)
            csv << ',' << s.precision[1].mean << ',' << s.recall[1].mean << ',' << s.f1[1].mean
                << ',' << s.f1[1].std;
        else
            csv << ",,,,";
        if (s.f1[0].n)
            csv << ',' << s.f1[0].mean << ',' << s.f1[0].std;
        else
            csv << ",,";
        if (s.clusters)
            csv << ',' << s.objects.mean_coverage << ',' << s.objects.mean_purity << ','
                << s.use.mean << ',' << s.ose.mean;
        else
            csv << ",,,,";
        csv << ',' << s.ground_ms << ',' << s.objects_ms << '\n';
    }
}

SweepScore parseSweepScore(const std::string& name) {
    for (SweepScore s :
         {SweepScore::GroundF1B, SweepScore::GroundF1A, SweepScore::Coverage, SweepScore::Purity})
        if (name == sweepScoreName(s)) return s;
    throw ConfigError("unknown leave-one-out score '" + name +
                      "' (valid: f1b, f1a, coverage, purity)");
}

const char* sweepScoreName(SweepScore score) {
    switch (score) {
        case SweepScore::GroundF1B:
            return "f1b";
        case SweepScore::GroundF1A:
            return "f1a";
        case SweepScore::Coverage:
            return "coverage";
        case SweepScore::Purity:
            return "purity";
    }
    return "?";
}

double sweepScore(const FrameRow& row, SweepScore score) {
    switch (score) {
        case SweepScore::GroundF1B:
            return row.ground[1].f1;
        case SweepScore::GroundF1A:
            return row.ground[0].f1;
        case SweepScore::Coverage:
            return row.coverage;
        case SweepScore::Purity:
            return row.purity;
    }
    return 0;
}

std::vector<std::size_t> scoredFrames(const std::vector<std::vector<FrameRow>>& rows,
                                      SweepScore score) {
    // A frame has a score when it has something to score at every value: ground truth under the
    // protocol; thing instances for coverage (an instance left unclustered covers 0, a true
    // score); for purity, an instance in a cluster (purity is a mean over those: a frame whose
    // instances are all unclustered has none, 0 by convention). The others are left out, not
    // averaged in as zeros.
    const auto scored = [&](const FrameRow& row) {
        switch (score) {
            case SweepScore::GroundF1B:
                return row.ground[1].points > 0;
            case SweepScore::GroundF1A:
                return row.ground[0].points > 0;
            case SweepScore::Purity:
                return !row.objects || row.clustered > 0;
            default:
                return !row.objects || row.instances > 0;
        }
    };
    std::vector<std::size_t> kept;
    for (std::size_t f = 0; !rows.empty() && f < rows[0].size(); ++f)
        if (std::all_of(rows.begin(), rows.end(), [&](const std::vector<FrameRow>& r) {
                return f < r.size() && scored(r[f]);
            }))
            kept.push_back(f);
    return kept;
}

LeaveOneOut leaveOneOut(const std::vector<std::vector<FrameRow>>& rows, SweepScore score) {
    if (rows.empty()) throw std::invalid_argument("leaveOneOut: no values");
    const std::size_t frames = rows[0].size();
    if (frames < 2) throw std::invalid_argument("leaveOneOut: needs two frames or more");
    for (const auto& r : rows)
        if (r.size() != frames) throw std::invalid_argument("leaveOneOut: frame counts differ");
    // Coverage and purity exist only where the method clustered (FrameRow::objects; the sweep
    // CSV leaves them empty otherwise): a fold of zeros would choose the first value on nothing.
    const bool objects = score == SweepScore::Coverage || score == SweepScore::Purity;
    if (objects) {
        bool clustered = false;
        for (const auto& r : rows)
            for (const FrameRow& row : r) clustered = clustered || row.objects;
        if (!clustered)
            throw std::invalid_argument(
                std::string("leave-one-out on ") + sweepScoreName(score) +
                ": no frame was clustered at any value (a ground-only method, or cluster_objects "
                "false): choose f1b or f1a");
    }
    const std::vector<std::size_t> kept = scoredFrames(rows, score);
    if (kept.size() < 2)
        throw std::invalid_argument(
            std::string("leave-one-out on ") + sweepScoreName(score) + ": " +
            std::to_string(kept.size()) + " of " + std::to_string(frames) +
            " frames have a score at every value (" +
            (objects ? "thing instances" : "ground truth under the protocol") + "); it needs two");
    // Mean score of value v over every kept frame but `skip` (skip = frames: none skipped).
    const auto mean_without = [&](std::size_t v, std::size_t skip) {
        double sum = 0;
        std::size_t n = 0;
        for (const std::size_t f : kept)
            if (f != skip) sum += sweepScore(rows[v][f], score), ++n;
        return sum / double(n);
    };
    const auto best_without = [&](std::size_t skip) {
        std::size_t best = 0;
        for (std::size_t v = 1; v < rows.size(); ++v)
            if (mean_without(v, skip) > mean_without(best, skip)) best = v;
        return best;
    };
    LeaveOneOut loo;
    for (const std::size_t f : kept) {
        LeaveOneOut::Fold fold;
        fold.frame = rows[0][f].frame;
        fold.chosen = best_without(f);
        fold.held_out = sweepScore(rows[fold.chosen][f], score);
        loo.held_out_mean += fold.held_out / double(kept.size());
        loo.folds.push_back(fold);
    }
    loo.in_sample = best_without(frames);
    loo.in_sample_mean = mean_without(loo.in_sample, frames);
    return loo;
}

void writeLeaveOneOutCsv(std::ostream& csv, const SweepSpec& spec, SweepScore score,
                         const LeaveOneOut& loo) {
    csv << "held_out_frame,chosen_" << spec.key << ",held_out_" << sweepScoreName(score) << '\n';
    for (const LeaveOneOut::Fold& fold : loo.folds)
        csv << fold.frame << ',' << spec.values[fold.chosen] << ',' << fold.held_out << '\n';
    csv << "mean (leave-one-out),," << loo.held_out_mean << '\n';
    csv << "in-sample best," << spec.values[loo.in_sample] << ',' << loo.in_sample_mean << '\n';
}

}  // namespace travel::eval
