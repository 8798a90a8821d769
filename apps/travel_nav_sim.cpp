// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-nav-sim: closed-loop reactive navigation (MRPT's CReactiveNavigationSystem3D on a
// simulated differential-drive robot) with a synthetic LiDAR on board, on the obstacles of
// TRAVEL, of the traversability map built from TRAVEL (with a global path on it), or of a
// comparison source. With no arguments: the default world, the TRAVEL source,
// outputs in the current directory:
//   <world>_<source>.reactivenavlog   the navigator's log (navlog-viewer opens it)
//   <world>_<source>.csv              the trajectory
//   <world>_<source>.png              the world from above with the path
//   <world>_map.bt, _grid.gridmap.gz, ...   the map source's map (CTraversabilityMap exports)
// --source all runs the per-frame sources (travel, raw, threshold) and also writes
// <world>_sources.png (side by side).
#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <stdexcept>
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
    travel::apps::CommandLine line(
        "travel-nav-sim",
        "travel-nav-sim: reactive navigation on TRAVEL obstacles, in closed-loop simulation. -i: "
        "the world (a .world file, or a name in share/worlds; default ramp_kerb.world); -o: the "
        "output folder (default: the current one) for <world>_<source>.reactivenavlog (the "
        "navigator's log, navlog-viewer opens it), .csv (the trajectory) and .png (the world "
        "from above with the path); --source map also saves the map (<world>_map.bt, "
        "<world>_map_grid.gridmap.gz, ...) and draws it with the planned paths; --source all "
        "runs travel, raw and threshold and also writes <world>_sources.png. -p/-c/--set "
        "configure TRAVEL (travel:) and its obstacle rule (nav:) on top of the simulation's "
        "robot and LiDAR; --nav-config is MRPT's reactive navigator .ini.",
        {"travel-nav-sim", "travel-nav-sim -i ramp_kerb.world --source all -o nav",
         "travel-nav-sim -i dead_end.world -s map --seed 3",
         "travel-nav-sim -i my.world --set nav.max_step_height=0.1 --nav-config my_nav.ini -q"});
    TCLAP::CmdLine& cmd = line.cmd;
    const travel::apps::CommonFlags flags(line, false, "");
    TCLAP::ValueArg<std::string> source_arg(
        "s", "source",
        "Obstacle source: travel, raw, threshold, map (the traversability map, with a global "
        "path on it) or all (travel, raw and threshold); default travel",
        false, "travel", "NAME", cmd);
    TCLAP::ValueArg<std::string> nav_config_arg(
        "", "nav-config",
        "Reactive navigator .ini, or a name in share/configs/nav (default reactive3d_travel.ini)",
        false, "reactive3d_travel.ini", "FILE", cmd);
    TCLAP::ValueArg<double> timeout_arg(
        "t", "timeout", "Simulated seconds before giving up (default 60)", false, 60.0, "S", cmd);
    TCLAP::ValueArg<double> threshold_arg("", "threshold",
                                          "Height-threshold source: min height [m] (default 0.25)",
                                          false, 0.25, "M", cmd);
    // long, not unsigned: TCLAP reads "-3" into an unsigned as 4294967293.
    TCLAP::ValueArg<long> seed_arg(
        "", "seed",
        "Move the world's kerbs and boxes by a seeded random shift (up to +/-0.3 m; 0: as in "
        "the file)",
        false, 0, "N", cmd);
    TCLAP::SwitchArg track_arg(
        "", "track",
        "Track the clusters (TravelFilter's track_objects; parameters: section tracking): objects "
        "flagged moving are obstacles along their path predicted over nav.predict_seconds, and "
        "neither the memory nor the map keeps them (sources travel and map)",
        cmd);
    TCLAP::SwitchArg no_log_arg("", "no-navlog", "Do not write the .reactivenavlog", cmd);
    TCLAP::SwitchArg no_plan_arg(
        "", "no-plan",
        "Map source: no global path (the goal is the reactive navigator's only target)", cmd);
    TCLAP::SwitchArg no_map_arg("", "no-map-save", "Map source: do not save the map", cmd);
    std::vector<SourceKind> sources;
    line.checks.push_back([&] {
        if (!(timeout_arg.getValue() > 0))
            throw travel::apps::usageError("-t/--timeout must be > 0 (simulated seconds)");
        if (seed_arg.getValue() < 0 || seed_arg.getValue() > long(UINT32_MAX))
            throw travel::apps::usageError("--seed must be 0 to 4294967295");
        try {
            sources = parseSources(source_arg.getValue());
        } catch (const std::invalid_argument& e) {
            throw travel::apps::usageError(std::string("-s/--source: ") + e.what());
        }
        // A flag for a source this run does not drive would be ignored: name it instead.
        const auto runs = [&sources](SourceKind kind) {
            return std::find(sources.begin(), sources.end(), kind) != sources.end();
        };
        if (!runs(SourceKind::Map) && (no_plan_arg.getValue() || no_map_arg.getValue()))
            throw travel::apps::usageError("--no-plan and --no-map-save are for -s map");
        if (!runs(SourceKind::Threshold) && threshold_arg.isSet())
            throw travel::apps::usageError("--threshold is for -s threshold or -s all");
        if (!runs(SourceKind::Travel) && !runs(SourceKind::Map) && track_arg.getValue())
            throw travel::apps::usageError("--track is for the sources travel and map");
    });
    if (const auto code = line.parse(argc, argv)) return *code;
    // The simulation's defaults (its robot and LiDAR; obstacles kept for 1 s), then --preset,
    // --config, each --set.
    const SimOptions defaults;
    travel::Config default_config;
    default_config.travel = defaults.travel;
    default_config.nav = defaults.nav;
    default_config.tracking = defaults.tracking;
    const travel::Config configuration = flags.config.load(default_config);
    if (flags.config.print(configuration)) return 0;
    flags.requireAutoFormat("world files");
    const bool quiet = flags.quiet();

    const World world =
        shiftedObstacles(loadWorld(findShared(flags.inputPath("ramp_kerb.world"), "worlds")),
                         static_cast<unsigned>(seed_arg.getValue()));
    const std::string config = findShared(nav_config_arg.getValue(), "configs/nav");
    const fs::path out_dir = flags.outputPath(".");
    travel::apps::createFolder(out_dir.string());

    SimOptions options;
    options.nav_config_file = config;
    options.timeout = timeout_arg.getValue();
    options.threshold_min_z = threshold_arg.getValue();
    options.verbosity = travel::apps::verbosityFrom(flags.quiet(), flags.verbose());
    options.travel = configuration.travel;
    options.nav = configuration.nav;
    options.track = track_arg.getValue();
    options.tracking = configuration.tracking;
    const auto footprint = footprintFromConfig(config);

    if (!quiet)
        std::cout << "travel-nav-sim: world " << world.name << " (" << world.source
                  << "), navigator " << config << "\n";
    std::vector<mrpt::img::CImage> panels;
    std::vector<std::string> titles;
    for (const SourceKind kind : sources) {
        options.source = kind;
        const std::string stem = (out_dir / (world.name + "_" + toString(kind))).string();
        options.navlog_file = no_log_arg.getValue() ? "" : stem + ".reactivenavlog";
        options.plan = !no_plan_arg.getValue();
        options.map_prefix = kind == SourceKind::Map && !no_map_arg.getValue() ? stem : "";
        const RunReport r = runSimulation(world, options);
        writeTrajectoryCsv(r, stem + ".csv");
        TopViewOptions view;
        view.title =
            world.name + ": " + toString(kind) + " obstacles" + (options.track ? ", tracking" : "");
        mrpt::img::CImage img;
        renderTopView(world, footprint, &r, view, img);
        travel_mrpt::savePicture(img, stem + ".png");
        panels.push_back(std::move(img));
        titles.push_back(toString(kind));
        if (quiet) continue;
        std::printf(
            "  %-9s %-17s time %5.1f s  path %5.2f m  min clearance %.2f m (%s)  climbed %.2f m"
            "  %.1f ms/step%s%s\n",
            toString(kind), toString(r.outcome), r.time, r.path_length, r.min_clearance,
            r.min_clearance_to.empty() ? "-" : r.min_clearance_to.c_str(), r.max_height_gain,
            r.mean_step_ms, r.detail.empty() ? "" : "  : ", r.detail.c_str());
        if (r.min_mover_clearance < 1e9)
            std::printf("    min clearance to the movers %.2f m%s\n", r.min_mover_clearance,
                        options.track ? " (tracking on)" : "");
        if (kind == SourceKind::Map)
            std::printf(
                "    map update + sensing %.2f ms/step (median; map fusion %.2f ms; CPU %.2f ms; "
                "max %.1f ms), planning %.2f ms/step, %zu plans\n",
                r.median_map_ms, r.median_fusion_ms, r.median_map_cpu_ms, r.max_map_ms,
                r.mean_plan_ms, r.planned_paths.size());
        std::cout << "    outputs: " << stem << ".{csv,png"
                  << (options.navlog_file.empty() ? "" : ",reactivenavlog") << "}"
                  << (options.map_prefix.empty()
                          ? ""
                          : "  map: " + stem + ".bt, " + stem + "_grid.gridmap.gz, ...")
                  << "\n";
    }
    if (panels.size() > 1) {
        mrpt::img::CImage all = panels[0], tmp;
        for (std::size_t i = 1; i < panels.size(); ++i) {
            travel_mrpt::sideBySide(all, panels[i], "", "", tmp);
            all = tmp;
        }
        const std::string path = (out_dir / (world.name + "_sources.png")).string();
        travel_mrpt::savePicture(all, path);
        if (!quiet) std::cout << "  side by side: " << path << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-nav-sim", run, argc, argv);
}
