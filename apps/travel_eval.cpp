// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-eval: the paper-style evaluation of TRAVEL and its baselines on SemanticKITTI.
//
//   travel-eval report -i DIR --labels DIR -o DIR [--methods a,b,...]
//       every method over every labelled frame: report.md (ground tables for protocols A and B,
//       an object table) and frames.csv (one row per method and frame).
//   travel-eval sweep -i DIR --labels DIR -o DIR --sweep KEY=v1,v2,... [--method NAME]
//       one method, one parameter: sweep_KEY.csv and three PNG plots (ground F1, objects, time).
//   travel-eval merges -i DIR --labels DIR -o DIR [--method NAME]
//       where under-segmentation comes from: merges.md (MergeDiagnostics).
//
// Metrics and timings are those of travel-kitti (same libtravel APIs), aggregated differently.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "LargePages.hpp"
#include "OrderedWork.hpp"
#include "Progress.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Text.hpp"
#include "travel/eval/MergeDiagnostics.hpp"
#include "travel/eval/Report.hpp"
#include "travel/eval/Segmenter.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"

namespace fs = std::filesystem;
using mrpt::img::CImage;
using mrpt::img::TColor;

namespace {

using travel::eval::EvaluationSummary;
using travel::eval::FrameRef;
using travel::eval::MethodRun;

// ---------------------------------------------------------------------------------------------
// Running one method over the frames, with a progress display

/// Called on the worker that evaluated frame `f`, right after it, with that worker's segmenter
/// (its pipeline still holds the frame): merges reads the object stage's state there.
using FrameHook = std::function<void(std::size_t f, const travel::eval::FrameEvaluation& frame,
                                     const travel::eval::Segmenter& segmenter)>;

// Frames are evaluated on `jobs` workers (one segmenter each, built with the first one and given
// its state once its mount is settled) and added to the run in frame order: the same run as with
// one worker.
MethodRun runMethod(const std::string& method, const travel::Params& params,
                    const std::vector<FrameRef>& frames, const std::string& progress_label,
                    travel::apps::Verbosity verbosity, unsigned jobs,
                    const FrameHook& on_frame = {}) {
    // -v: one line per frame (its name) instead of the progress line.
    const bool per_frame_lines = verbosity == travel::apps::Verbosity::Verbose;
    travel::apps::ProgressLine progress(
        progress_label, frames.size(),
        per_frame_lines ? travel::apps::Verbosity::Quiet : verbosity);
    MethodRun run;
    run.method = method;
    travel::eval::EvaluationAccumulator totals;
    // The other workers' segmenters are built on their own threads meanwhile.
    const unsigned workers =
        static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(jobs, frames.size())));
    travel::apps::BackgroundBuilds<std::unique_ptr<travel::eval::Segmenter>> worker_segmenters(
        workers - 1, [&](unsigned) { return travel::eval::makeSegmenter(method, params); });
    std::vector<std::unique_ptr<travel::eval::Segmenter>> segmenters;
    segmenters.push_back(travel::eval::makeSegmenter(method, params));
    travel::apps::forEachInOrder<travel::eval::FrameEvaluation>(
        frames.size(), workers, [&] { return !segmenters[0]->independentFrames(); },
        [&](unsigned workers) { segmenters.resize(workers); },
        [&](unsigned w, std::size_t f, travel::eval::FrameEvaluation& frame) {
            if (!segmenters[w]) {
                segmenters[w] = worker_segmenters.take(w - 1);
                segmenters[w]->adoptSettledState(*segmenters[0]);
            }
            travel::eval::evaluateFrame(frames[f].scan, frames[f].label, *segmenters[w], frame,
                                        frames[f].format);
            if (on_frame) on_frame(f, frame, *segmenters[w]);
        },
        [&](std::size_t f, const travel::eval::FrameEvaluation& frame) {
            travel::apps::throwIfInterrupted();  // nothing is written before all frames ran
            if (per_frame_lines)
                std::fprintf(stderr, "%s: frame %zu/%zu %s\n", progress_label.c_str(), f + 1,
                             frames.size(), frames[f].name.c_str());
            travel::eval::addFrame(frames[f], frame, run, totals);
            progress.update(f + 1);
        });
    run.summary = totals.summary();
    if (run.mount && verbosity != travel::apps::Verbosity::Quiet)
        progress.note(travel::apps::mountNoteLine("travel-eval", method, run.mount));
    return run;
}

/// The whole text or an error naming the file (writeFileBytes: no half a file is left).
void writeText(const fs::path& path, const std::string& text) {
    travel::writeFileBytes(path.string(), text);
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

// ---------------------------------------------------------------------------------------------
// sweep

void writeSweep(const fs::path& dir, const std::string& method, const travel::eval::SweepSpec& spec,
                const std::vector<EvaluationSummary>& sums, std::size_t frames) {
    const std::string stem = "sweep_" + spec.key;
    std::ostringstream csv;
    travel::eval::writeSweepCsv(csv, spec, sums, frames);
    writeText(dir / (stem + ".csv"), csv.str());

    const std::vector<double> xs = travel::eval::sweepPositions(spec.values);
    const std::string what = method + ", " + std::to_string(frames) + " frames";
    const auto col = [&](auto get) {
        std::vector<double> y;
        for (const EvaluationSummary& s : sums) y.push_back(get(s));
        return y;
    };
    const auto obj = [&](auto get) {  // NaN (not drawn) when the method does not cluster
        return col([&](const EvaluationSummary& s) { return s.clusters ? get(s) : NAN; });
    };

    CImage ground = whiteImage(800, 500);
    drawChart(
        ground, 0, 0, 800, 500, "Ground F1 vs " + spec.key + " (" + what + ")", spec.key, "F1 [%]",
        xs, spec.values,
        {{"F1 protocol B", col([](const EvaluationSummary& s) { return s.f1[1].mean; }), kBlue},
         {"F1 protocol A", col([](const EvaluationSummary& s) { return s.f1[0].mean; }), kOrange}});
    travel_mrpt::savePicture(ground, (dir / (stem + "_ground.png")).string());

    CImage objects = whiteImage(800, 900);
    drawChart(objects, 0, 0, 800, 450, "Thing instances vs " + spec.key + " (" + what + ")",
              spec.key, "share of instance / cluster", xs, spec.values,
              {{"coverage", obj([](const EvaluationSummary& s) { return s.objects.mean_coverage; }),
                kGreen},
               {"purity", obj([](const EvaluationSummary& s) { return s.objects.mean_purity; }),
                kPurple}});
    drawChart(objects, 0, 450, 800, 450, "Segmentation entropy vs " + spec.key, spec.key,
              "per-frame sum (lower is better)", xs, spec.values,
              {{"USE", obj([](const EvaluationSummary& s) { return s.use.mean; }), kRed},
               {"OSE", obj([](const EvaluationSummary& s) { return s.ose.mean; }), kBlue}});
    objects.line(20, 450, 780, 450, kGrid);
    travel_mrpt::savePicture(objects, (dir / (stem + "_objects.png")).string());

    CImage time = whiteImage(800, 500);
    drawChart(
        time, 0, 0, 800, 500, "Median ms per frame vs " + spec.key + " (" + what + ")", spec.key,
        "milliseconds (single thread)", xs, spec.values,
        {{"ground", col([](const EvaluationSummary& s) { return s.ground_ms; }), kBlue},
         {"objects", obj([](const EvaluationSummary& s) { return s.objects_ms; }), kGreen},
         {"ground + objects",
          col([](const EvaluationSummary& s) { return s.ground_ms + s.objects_ms; }), kBlack}},
        true);
    travel_mrpt::savePicture(time, (dir / (stem + "_time.png")).string());
}
// ---------------------------------------------------------------------------------------------

int run(int argc, char** argv) {
    travel::apps::CommandLine line(
        "travel-eval",
        "Evaluation of TRAVEL and its baselines on SemanticKITTI (labelled frames only). -i: a "
        "KITTI sequence folder (labels/ beside velodyne/), or a folder of scans with --labels; "
        "repeat -i (and --labels, paired by order) for several sequences. -o: the output "
        "folder.\n"
        "  report: runs every --methods method (default: all) over the frames and writes "
        "<output>/report.md (ground P, R, F1 and accuracy mu/sigma and median ms per method, one "
        "table per protocol A and B; objects USE/OSE mu/sigma, coverage, purity, split, merged "
        "and median ms for the methods that cluster), printed to stdout as well, and "
        "<output>/frames.csv (one row per method and frame, every per-frame value).\n"
        "  sweep: runs one --method (default travel) once per value of one parameter "
        "(--sweep KEY=v1,v2,..., any key of travel-kitti --print-config) and writes "
        "<output>/sweep_KEY.csv (per value: B P/R/F1, A F1, coverage, purity, USE, OSE, median "
        "ground / objects ms) and the plots sweep_KEY_ground.png (F1, protocols A and B), "
        "sweep_KEY_objects.png (coverage, purity; USE, OSE) and sweep_KEY_time.png. Paper "
        "studies: tgf_resolution=2,4,6,8,10, vertical_ring_span=1,2,3,4,5, "
        "vertical_column_extension=1,3,5,10,20.\n"
        "  merges: runs one --method with TRAVEL's object stage (default travel) and writes "
        "<output>/merges.md: the clusters holding points of more than one ground-truth object, "
        "by linkage rule, class pair and range (printed to stdout as well), and merges.csv (one "
        "row per part).",
        {"travel-eval report -i data/sequences/00 -o eval",
         "travel-eval report -i seq/00 -i seq/01 --methods travel,gpf+slr -o eval",
         "travel-eval sweep -i data/sequences/00 --sweep tgf_resolution=2,4,6,8,10 -o sweep"});
    TCLAP::CmdLine& cmd = line.cmd;
    std::vector<std::string> commands{"report", "sweep", "merges"};
    TCLAP::ValuesConstraint<std::string> command_values(commands);
    // Not required by TCLAP: --print-config needs no command, as in every other app.
    TCLAP::UnlabeledValueArg<std::string> command("command", "report, sweep or merges", false, "",
                                                  &command_values, cmd);
    const travel::apps::CommonFlags flags(line, true, "hdl64");
    TCLAP::MultiArg<std::string> labels(
        "", "labels",
        "SemanticKITTI .label folder for the -i of the same position (default: each sequence's "
        "labels/)",
        false, "DIR", cmd);
    TCLAP::ValueArg<std::string> methods("", "methods",
                                         "report: comma-separated methods (default: all of them)",
                                         false, "", "A,B,...", cmd);
    TCLAP::ValueArg<std::string> method("", "method", "sweep, merges: the method (default travel)",
                                        false, "travel", "NAME", cmd);
    TCLAP::ValueArg<std::string> loo_score(
        "", "loo-score",
        "sweep: what the leave-one-out choice maximises per frame: f1b (ground F1, protocol B; "
        "the default), f1a, coverage or purity",
        false, "f1b", "SCORE", cmd);
    TCLAP::ValueArg<std::string> sweep("", "sweep",
                                       "sweep: KEY=v1,v2,... e.g. tgf_resolution=2,4,6,8,10", false,
                                       "", "KEY=VALUES", cmd);
    const travel::apps::MaxFramesFlag max_frames(line, "labelled frames");
    const travel::apps::JobsFlag jobs(line, "frames");
    if (const auto exit_code = line.parse(argc, argv)) return *exit_code;
    const travel::Config configuration = flags.config.load();
    if (flags.config.print(configuration)) return 0;
    if (!command.isSet())
        throw travel::apps::usageError("missing the command: report, sweep or merges");
    travel::apps::preferLargePages(jobs.count());  // before any pipeline or thread

    const bool is_sweep = command.getValue() == "sweep";
    const bool is_merges = command.getValue() == "merges";
    // Configuration errors first, before any file is read.
    const std::string out = flags.outputPath();
    const bool quiet = flags.quiet();
    const travel::apps::Verbosity verbosity =
        travel::apps::verbosityFrom(flags.quiet(), flags.verbose());
    if ((is_sweep || is_merges) && methods.isSet())
        throw travel::apps::usageError(command.getValue() + " runs one --method, not --methods");
    if (!is_sweep && !is_merges && method.isSet())
        throw travel::apps::usageError("report takes --methods; --method is for sweep and merges");
    if (!is_sweep && sweep.isSet()) throw travel::apps::usageError("--sweep is for sweep");
    if (is_sweep && !sweep.isSet())
        throw travel::apps::usageError("sweep needs --sweep KEY=v1,v2,...");
    if (!is_sweep && loo_score.isSet()) throw travel::apps::usageError("--loo-score is for sweep");
    const travel::eval::SweepScore score = travel::eval::parseSweepScore(loo_score.getValue());
    const travel::Params& params = configuration.travel;
    const std::string setup = flags.config.describe();

    std::vector<std::string> names =
        methods.isSet() ? travel::splitList(methods.getValue(), ',') : travel::eval::methodNames();
    if (is_sweep || is_merges) names = {method.getValue()};
    if (names.empty()) throw travel::apps::usageError("--methods names no method");
    for (const std::string& name : names) {
        // Throws, listing the valid names.
        const auto segmenter = travel::eval::makeSegmenter(name, params);
        if (is_merges && !params.cluster_objects)
            throw travel::apps::usageError(
                "merges diagnoses the object stage, which cluster_objects=false turns off");
        if (is_merges && !segmenter->objectPipeline())
            throw travel::apps::usageError(
                "merges names the linkage rules of TRAVEL's object stage: --method travel or "
                "travel-no-ttmf, not '" +
                name + "'");
    }
    const travel::eval::SweepSpec spec =
        is_sweep ? travel::eval::parseSweep(sweep.getValue(), params) : travel::eval::SweepSpec{};

    const std::vector<FrameRef> frames = travel::eval::labelledFrames(
        flags.inputs(), labels.getValue(), static_cast<std::size_t>(max_frames.count()),
        flags.scanFormat());
    // No output in an input: -o is not a sequence, scans or ground-truth labels folder read here
    // (docs/cli.md), however spelt.
    std::vector<travel::apps::NamedPath> read;
    for (const std::string& input : flags.inputs()) read.push_back({"-i", input});
    std::set<std::string> folders;
    for (const FrameRef& f : frames) {
        const std::string scans = fs::path(f.scan).parent_path().string();
        const std::string truth = fs::path(f.label).parent_path().string();
        if (folders.insert(scans).second) read.push_back({"the scans folder", scans});
        if (folders.insert(truth).second) read.push_back({"the labels folder", truth});
    }
    travel::apps::checkOutputsApart(read, {{"-o", out}});
    if (loo_score.isSet() && frames.size() < 2)
        throw travel::apps::usageError(
            "--loo-score: the leave-one-out needs two labelled frames "
            "or more; " +
            std::to_string(frames.size()) + " found");
    // Created when the outputs are written, after every frame ran: a run that fails on a frame
    // (or is interrupted) leaves nothing behind.
    travel::apps::requireCreatableFolder(out);
    const fs::path dir(out);

    if (is_merges) {
        // Each frame's parts are read on the worker that segmented it (its pipeline holds the
        // frame's range image); they are tabulated and written in frame order at the end.
        std::vector<std::vector<travel::eval::MergedPart>> parts(frames.size());
        runMethod(names[0], params, frames, names[0], verbosity, jobs.count(),
                  [&](std::size_t f, const travel::eval::FrameEvaluation& frame,
                      const travel::eval::Segmenter& segmenter) {
                      parts[f] = travel::eval::mergedParts(frame.segmentation.cluster_id,
                                                           frame.ground_truth, frame.cloud,
                                                           *segmenter.objectPipeline());
                  });
        travel::eval::MergeTable table;
        std::ostringstream csv;
        for (std::size_t k = 0; k < frames.size(); ++k) {
            table.add(parts[k]);
            travel::eval::writeMergedPartsCsv(csv, frames[k].name, parts[k], k == 0);
        }
        const std::string md = table.markdown();
        travel::apps::createFolder(out);
        writeText(dir / "merges.csv", csv.str());
        writeText(dir / "merges.md", md);
        if (!quiet)
            std::cout << md << "\nWritten: " << (dir / "merges.md").string() << ", "
                      << (dir / "merges.csv").string() << "\n";
        return 0;
    }
    if (!is_sweep) {
        std::vector<MethodRun> runs;
        for (const std::string& name : names)
            runs.push_back(runMethod(name, params, frames, name, verbosity, jobs.count()));
        const std::string md = travel::eval::reportMarkdown(runs, frames, setup, jobs.count());
        travel::apps::createFolder(out);
        writeText(dir / "report.md", md);
        std::ostringstream frames_csv;
        travel::eval::writeFramesCsv(frames_csv, runs);
        writeText(dir / "frames.csv", frames_csv.str());
        if (!quiet)
            std::cout << md << "\nWritten: " << (dir / "report.md").string() << ", "
                      << (dir / "frames.csv").string() << "\n";
        return 0;
    }

    std::vector<EvaluationSummary> sums;
    std::vector<std::vector<travel::eval::FrameRow>> rows;  // per value, for the leave-one-out
    for (const std::string& value : spec.values) {
        travel::Params p = params;
        travel::applyOverride(spec.key + "=" + value, p);
        p.validate();
        const MethodRun run =
            runMethod(names[0], p, frames, spec.key + "=" + value, verbosity, jobs.count());
        sums.push_back(run.summary);
        rows.push_back(run.rows);
        const EvaluationSummary& s = sums.back();
        if (quiet) continue;
        std::printf("%s=%-8s", spec.key.c_str(), value.c_str());
        for (const int p : {1, 0})  // "-": no frame with ground truth under the protocol
            if (s.f1[p].n)
                std::printf("%s F1 %6.2f", p ? " B" : "  A", s.f1[p].mean);
            else
                std::printf("%s F1      -", p ? " B" : "  A");
        if (s.clusters)
            std::printf("  coverage %.3f purity %.3f  USE %6.2f OSE %6.2f", s.objects.mean_coverage,
                        s.objects.mean_purity, s.use.mean, s.ose.mean);
        std::printf("  ms %.2f + %.2f\n", s.ground_ms, s.objects_ms);
    }
    // Before anything is written: a score the runs do not have (coverage of a ground-only
    // method) is an error that leaves no files.
    std::optional<travel::eval::LeaveOneOut> leave_one_out;
    // Without --loo-score, a sweep whose frames leave fewer than two scored (labels without
    // ground truth) has no leave-one-out, as one of a single frame; with it, an error.
    if (frames.size() >= 2 &&
        (loo_score.isSet() || travel::eval::scoredFrames(rows, score).size() >= 2))
        leave_one_out = travel::eval::leaveOneOut(rows, score);
    travel::apps::createFolder(out);
    writeSweep(dir, names[0], spec, sums, frames.size());
    const std::string stem = (dir / ("sweep_" + spec.key)).string();
    if (leave_one_out) {
        const travel::eval::LeaveOneOut& loo = *leave_one_out;
        std::ostringstream loo_csv;
        travel::eval::writeLeaveOneOutCsv(loo_csv, spec, score, loo);
        writeText(stem + "_loo.csv", loo_csv.str());
        if (!quiet) {
            std::printf("Leave-one-out over %zu frames (%s, each value chosen on the others)",
                        loo.folds.size(), travel::eval::sweepScoreName(score));
            if (loo.folds.size() < frames.size())
                std::printf("; %zu frames without a score left out",
                            frames.size() - loo.folds.size());
            std::printf(":\n");
            for (const auto& fold : loo.folds)
                std::printf("  held out %-16s chosen %s=%-8s held-out %s %.4g\n",
                            fold.frame.c_str(), spec.key.c_str(), spec.values[fold.chosen].c_str(),
                            travel::eval::sweepScoreName(score), fold.held_out);
            std::printf("  mean held-out %.4g; in-sample best %s=%s: %.4g\n", loo.held_out_mean,
                        spec.key.c_str(), spec.values[loo.in_sample].c_str(), loo.in_sample_mean);
        }
    }
    if (!quiet)
        std::printf("Written: %s.csv, %s_ground.png, %s_objects.png, %s_time.png%s\n", stem.c_str(),
                    stem.c_str(), stem.c_str(), stem.c_str(),
                    leave_one_out ? (", " + stem + "_loo.csv").c_str() : "");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-eval", run, argc, argv);
}
