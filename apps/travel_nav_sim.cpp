// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-nav-sim: closed-loop reactive navigation (MRPT's CReactiveNavigationSystem3D on a
// simulated differential-drive robot) with a synthetic LiDAR on board, on the obstacles of
// TRAVEL or of a comparison source. With no arguments: the default world, the TRAVEL source,
// outputs in the current directory:
//   <world>_<source>.reactivenavlog   the navigator's log (navlog-viewer opens it)
//   <world>_<source>.csv              the trajectory
//   <world>_<source>.png              the world from above with the path
// --source all runs the three sources and also writes <world>_sources.png (side by side).
#include <mrpt/img/CImage.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "nav/Simulation.hpp"
#include "nav/TopView.hpp"
#include "nav/World.hpp"
#include "travel/ParamsIO.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"

namespace fs = std::filesystem;
using namespace travel::navsim;

namespace {

/// A file given as is when it exists, else looked up under <share>/<subdir>/ (names without a
/// directory, as "ramp_kerb.world").
std::string findShared(const std::string& name, const std::string& subdir) {
    std::error_code ec;
    if (fs::is_regular_file(name, ec)) return name;
    if (fs::path(name).has_parent_path()) throw std::runtime_error(name + ": file not found");
    std::string searched;
    for (const auto& dir : travel::shareSearchDirs()) {
        const fs::path candidate = fs::path(dir) / subdir / name;
        if (fs::is_regular_file(candidate, ec)) return candidate.string();
        searched += " " + candidate.string();
    }
    throw std::runtime_error(name + ": not found (looked in the current directory and" + searched +
                             ")");
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "travel-nav-sim: reactive navigation on TRAVEL obstacles, in closed-loop simulation", ' ',
        "1.0");
    TCLAP::ValueArg<std::string> world_arg("w", "world", "World file, or a name in share/worlds",
                                           false, "ramp_kerb.world", "FILE", cmd);
    TCLAP::ValueArg<std::string> source_arg("s", "source",
                                            "Obstacle source: travel, raw, threshold or all", false,
                                            "travel", "NAME", cmd);
    TCLAP::ValueArg<std::string> config_arg(
        "c", "config", "Reactive navigator .ini, or a name in share/configs/nav", false,
        "reactive3d_travel.ini", "FILE", cmd);
    TCLAP::ValueArg<std::string> out_arg("o", "out", "Output directory", false, ".", "DIR", cmd);
    TCLAP::ValueArg<double> timeout_arg("t", "timeout", "Simulated seconds before giving up", false,
                                        60.0, "S", cmd);
    TCLAP::ValueArg<double> threshold_arg(
        "", "threshold", "Height-threshold source: min height [m]", false, 0.25, "M", cmd);
    TCLAP::MultiArg<std::string> set_arg("", "set",
                                         "Override KEY=VALUE or SECTION.KEY=VALUE (sections "
                                         "travel and nav; see --print-config)",
                                         false, "KEY=VALUE", cmd);
    TCLAP::ValueArg<unsigned> seed_arg(
        "", "seed",
        "Move the world's kerbs and boxes by a seeded random shift (up to +/-0.3 m; 0: as in "
        "the file)",
        false, 0, "N", cmd);
    TCLAP::SwitchArg no_log_arg("", "no-navlog", "Do not write the .reactivenavlog", cmd);
    TCLAP::SwitchArg verbose_arg("v", "verbose", "Navigator console output, DEBUG included", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "Print nothing but errors", cmd);
    const travel::apps::PrintConfigFlag print_config(cmd);
    if (const auto code = travel::apps::parseCommandLine(cmd, argc, argv)) return *code;
    // The simulation's defaults (its robot and LiDAR; obstacles kept for 1 s), then each --set.
    const SimOptions defaults;
    travel::Config configuration;
    configuration.travel = defaults.travel;
    configuration.nav = defaults.nav;
    travel::apps::applyConfigSources("", set_arg.getValue(), configuration);
    if (print_config.print(configuration)) return 0;

    const World world = shiftedObstacles(loadWorld(findShared(world_arg.getValue(), "worlds")),
                                         seed_arg.getValue());
    const std::string config = findShared(config_arg.getValue(), "configs/nav");
    std::vector<SourceKind> sources;
    if (source_arg.getValue() == "all")
        sources = {SourceKind::Travel, SourceKind::Raw, SourceKind::Threshold};
    else
        sources = {parseSourceKind(source_arg.getValue())};
    const fs::path out_dir = out_arg.getValue();
    fs::create_directories(out_dir);

    SimOptions options;
    options.nav_config_file = config;
    options.timeout = timeout_arg.getValue();
    options.threshold_min_z = threshold_arg.getValue();
    options.verbosity = travel::apps::verbosityFrom(quiet.getValue(), verbose_arg.getValue());
    const bool print = options.verbosity != travel::apps::Verbosity::Quiet;
    options.travel = configuration.travel;
    options.nav = configuration.nav;
    const auto footprint = footprintFromConfig(config);

    if (print)
        std::cout << "travel-nav-sim: world " << world.name << " (" << world.source
                  << "), navigator " << config << "\n";
    std::vector<mrpt::img::CImage> panels;
    std::vector<std::string> titles;
    for (const SourceKind kind : sources) {
        options.source = kind;
        const std::string stem = (out_dir / (world.name + "_" + toString(kind))).string();
        options.navlog_file = no_log_arg.getValue() ? "" : stem + ".reactivenavlog";
        const RunReport r = runSimulation(world, options);
        writeTrajectoryCsv(r, stem + ".csv");
        TopViewOptions view;
        view.title = world.name + ": " + toString(kind) + " obstacles";
        mrpt::img::CImage img;
        renderTopView(world, footprint, &r, view, img);
        travel_mrpt::savePicture(img, stem + ".png");
        panels.push_back(std::move(img));
        titles.push_back(toString(kind));
        if (!print) continue;
        std::printf(
            "  %-9s %-17s time %5.1f s  path %5.2f m  min clearance %.2f m (%s)  climbed %.2f m"
            "  %.1f ms/step%s%s\n",
            toString(kind), toString(r.outcome), r.time, r.path_length, r.min_clearance,
            r.min_clearance_to.empty() ? "-" : r.min_clearance_to.c_str(), r.max_height_gain,
            r.mean_step_ms, r.detail.empty() ? "" : "  : ", r.detail.c_str());
        std::cout << "    outputs: " << stem << ".{csv,png"
                  << (options.navlog_file.empty() ? "" : ",reactivenavlog") << "}\n";
    }
    if (panels.size() > 1) {
        mrpt::img::CImage all = panels[0], tmp;
        for (std::size_t i = 1; i < panels.size(); ++i) {
            travel_mrpt::sideBySide(all, panels[i], "", "", tmp);
            all = tmp;
        }
        const std::string path = (out_dir / (world.name + "_sources.png")).string();
        travel_mrpt::savePicture(all, path);
        if (print) std::cout << "  side by side: " << path << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-nav-sim", run, argc, argv);
}
