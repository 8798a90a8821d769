// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-view: bird's-eye picture of one scan segmented by one or two methods (side by
// side), for looking at what a method does and comparing two of them on the same frame.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "Progress.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/Text.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/eval/Report.hpp"
#include "travel/eval/Segmenter.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"

namespace fs = std::filesystem;
using travel::PointClass;

namespace {

using travel::apps::AppError;

struct Options {
    std::optional<int> exit_code;  // set when the command line says stop (--help, error)
    std::string scan, out;
    travel::ScanFormat format = travel::ScanFormat::Auto;
    std::vector<std::string> methods;
    travel::Params params;  // --preset, --config, --set
    double mpp = 0.075;
    int size = 800;
    bool nodes = true;
    bool quiet = false;
};

/// The methods whose ground stage is TRAVEL's tri-grid search: they have a terrain model.
bool usesTriGrid(const std::string& method) {
    return method.rfind("travel", 0) == 0 || method.rfind("tgs", 0) == 0;
}

Options parseCommandLine(int argc, char** argv) {
    travel::apps::CommandLine line(
        "travel-view",
        "Bird's-eye PNG of one scan segmented by one or two methods (two: side by side). -i: a "
        "scan (.bin KITTI or nuScenes, .pcd, .ply), or a folder of scans or a KITTI sequence "
        "folder with --frame choosing the scan; -o: the picture (.png). Ground green, each "
        "cluster its own colour, non-ground without cluster grey, outliers blue; for the "
        "TGS-based methods (travel, travel-no-ttmf, tgs, tgs+...) the traversable tri-grid nodes "
        "of the terrain model are outlined underneath. Points are drawn in the aligned "
        "(levelled) frame, centred on the sensor, up = forward. Parameters: HDL-64E/KITTI "
        "defaults, then --preset, then --config, then each --set.",
        {"travel-view -i data/sequences/00/velodyne/000000.bin -o view.png",
         "travel-view -i data/sequences/00 --frame 5 -o view.png --methods travel,gpf+slr",
         "travel-view -i scan.pcd -p vlp16 --mpp 0.05 -o view.png"});
    TCLAP::CmdLine& cmd = line.cmd;
    const travel::apps::CommonFlags flags(line, false, "");
    TCLAP::ValueArg<std::string> methods(
        "", "methods",
        "One or two methods, comma-separated (see travel-kitti --help for names; default travel)",
        false, "travel", "M1[,M2]", cmd);
    TCLAP::ValueArg<int> frame("", "frame", "The scan of a folder or sequence -i (0: the first)",
                               false, 0, "N", cmd);
    const travel::apps::PictureFlags picture(cmd);
    TCLAP::SwitchArg no_nodes("", "no-nodes", "Do not draw the terrain model's nodes", cmd);
    Options o;
    o.exit_code = line.parse(argc, argv);
    if (o.exit_code) return o;
    const travel::Config configuration = flags.config.load();
    if (flags.config.print(configuration)) {
        o.exit_code = 0;
        return o;
    }
    o.params = configuration.travel;

    o.format = flags.scanFormat();
    const travel::ScanList scans = travel::listScans(flags.inputPath(), o.format);
    // A flag that changes nothing is a usage error, not ignored (docs/cli.md).
    if (frame.isSet() && !fs::is_directory(flags.inputPath()))
        throw travel::apps::usageError("--frame chooses a scan of a folder or sequence; -i " +
                                       flags.inputPath() + " is one scan");
    if (frame.getValue() < 0 || std::size_t(frame.getValue()) >= scans.files.size())
        throw AppError("--frame " + std::to_string(frame.getValue()) + ": " + flags.inputPath() +
                       " has " + std::to_string(scans.files.size()) + " scans");
    o.scan = scans.files[frame.getValue()];
    o.out = flags.outputPath();
    travel_mrpt::requirePictureName(o.out);
    travel::apps::requireFileName("-o", o.out);
    travel::apps::checkOutputsApart({{"-i", o.scan}}, {{"-o", o.out}});
    o.quiet = flags.quiet();
    for (const std::string& m : travel::splitList(methods.getValue(), ','))
        if (!m.empty()) o.methods.push_back(m);
    o.mpp = picture.metresPerPixel();
    o.size = picture.sidePixels();
    o.nodes = !no_nodes.getValue();
    if (o.methods.empty() || o.methods.size() > 2)
        throw AppError("--methods: give one or two method names, comma-separated");
    if (!o.nodes && std::none_of(o.methods.begin(), o.methods.end(), usesTriGrid))
        throw travel::apps::usageError(
            "--no-nodes: no method here draws tri-grid nodes (only travel, travel-no-ttmf, tgs and "
            "tgs+... have a terrain model)");
    return o;
}

/// One panel: labels from the method's Segmenter (the same code travel-kitti evaluates), points
/// in the aligned frame, and for tri-grid methods the terrain model of a Pipeline run with the
/// same parameters (the Segmenter does not expose it; its ground labels are the same).
void renderMethod(const std::string& method, const travel::Params& params,
                  const travel::PointCloud& cloud, const Options& o, mrpt::img::CImage& panel) {
    auto segmenter = travel::eval::makeSegmenter(method, params);
    travel::eval::Segmentation seg;
    segmenter->segment(cloud, seg);

    if (seg.mount && !o.quiet)
        std::cerr << travel::apps::mountNoteLine("travel-view", method, seg.mount) << "\n";

    travel::Result result;
    std::unique_ptr<travel::Pipeline> pipeline;
    // Tri-grid methods: the points as the pipeline aligned them (with its `auto` mount
    // estimates), so that they and the terrain nodes agree; baselines take the mount as set.
    if (usesTriGrid(method)) {
        travel::Params p = params;
        p.ttmf = method != "travel-no-ttmf";
        p.cluster_objects = false;  // only the terrain is needed
        pipeline = std::make_unique<travel::Pipeline>(p);
        pipeline->process(cloud, travel::FrameInput{}, result);
    }
    travel::AlignedCloud preprocessed;
    if (!pipeline) travel::preprocess(cloud, params, travel::FrameInput{}, preprocessed);
    const travel::AlignedCloud& aligned = pipeline ? pipeline->aligned() : preprocessed;

    std::size_t valid = 0, ground = 0, outliers = 0;
    uint32_t clusters = 0;
    for (std::size_t i = 0; i < seg.labels.size(); ++i) {
        valid += seg.labels[i] != PointClass::Invalid;
        ground += seg.labels[i] == PointClass::Ground;
        outliers += seg.labels[i] == PointClass::Outlier;
    }
    for (uint32_t id : seg.cluster_id) clusters = std::max(clusters, id);  // ids are 1..K
    const double pct = valid ? 100.0 / valid : 0.0;

    char title[200];
    std::snprintf(title, sizeof title, "%s: ground %.1f%%  outlier %.1f%%  %u clusters",
                  method.c_str(), ground * pct, outliers * pct, clusters);
    travel_mrpt::BirdsEyeOptions opt;
    opt.size_px = o.size;
    opt.metres_per_pixel = o.mpp;
    opt.title = title;
    opt.draw_nodes = o.nodes;
    travel_mrpt::renderBirdsEye(aligned, seg.labels, seg.cluster_id,
                                pipeline && o.nodes ? &result.terrain : nullptr, opt, panel);
}

int run(int argc, char** argv) {
    const Options o = parseCommandLine(argc, argv);
    if (o.exit_code) return *o.exit_code;
    const travel::Params& params = o.params;
    // Unknown method names fail before any file is read (the message lists the valid ones).
    for (const auto& method : o.methods) travel::eval::makeSegmenter(method, params);

    travel::PointCloud cloud;
    try {
        travel::readScan(o.scan, cloud, o.format);
    } catch (const std::exception& e) {
        const std::string what = e.what();
        // Name the file even if the reader's message does not.
        throw AppError(what.find(o.scan) == std::string::npos ? o.scan + ": " + what : what);
    }
    if (cloud.size() == 0) throw AppError(o.scan + ": empty scan");

    std::vector<mrpt::img::CImage> panels(o.methods.size());
    for (std::size_t k = 0; k < o.methods.size(); ++k)
        renderMethod(o.methods[k], params, cloud, o, panels[k]);

    travel::apps::createParentFolder(o.out);
    const std::string name = fs::path(o.scan).filename().string();
    if (panels.size() == 1) {
        travel_mrpt::savePicture(panels[0], o.out);
    } else {
        mrpt::img::CImage both;
        travel_mrpt::sideBySide(panels[0], panels[1], name + " - " + o.methods[0],
                                name + " - " + o.methods[1], both);
        travel_mrpt::savePicture(both, o.out);
    }
    if (!o.quiet)
        std::printf("travel-view: %s (%zu points) -> %s\n", o.scan.c_str(), cloud.size(),
                    o.out.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-view", run, argc, argv);
}
