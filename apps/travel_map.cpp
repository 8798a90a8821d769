// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-map: builds a travel_mrpt::CTraversabilityMap (2-D traversability grid + OctoMap)
// from an MRPT rawlog or a KITTI sequence and writes every export (see --help).
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <octomap/OcTree.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "MapSources.hpp"
#include "MemoryLimit.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/io/ScanList.hpp"
#include "travel/traversability/PoseFiles.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/GzFileOutput.hpp"
#include "travel_mrpt/MapExport.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/Registration.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace fs = std::filesystem;
using mrpt::poses::CPose3D;
using Clock = std::chrono::steady_clock;

namespace {

using travel::apps::Options;
using travel::apps::PoseFileSource;
using travel::apps::Stats;

/// --extent / --resolution, the map section's grid keys as flags.
void applyGridFlags(const Options& o, travel::MapSection& map) {
    if (!o.extent.empty()) {
        const std::vector<double> v = travel::apps::parseNumbers(
            o.extent, 4, "--extent", "MIN_X,MAX_X,MIN_Y,MAX_Y in metres");
        map.min_x = v[0], map.max_x = v[1], map.min_y = v[2], map.max_y = v[3];
    }
    if (o.resolution) map.resolution = *o.resolution;
}

/// CPU time of the process so far, every thread [s].
double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// The map's options from the sections travel, filter and map of the configuration.
travel_mrpt::TraversabilityMapOptions mapOptions(const travel::Config& configuration) {
    travel_mrpt::TraversabilityMapOptions options;
    options.map() = configuration.map;
    options.travel.params = configuration.travel;
    static_cast<travel::FilterSection&>(options.travel) = configuration.filter;
    options.validate();
    return options;
}

int run(int argc, char** argv) {
    travel::apps::CommandLine line(
        "travel-map",
        "Builds a traversability map (travel_mrpt::CTraversabilityMap) from 3-D LiDAR: every "
        "frame is segmented by TRAVEL and fused, at its robot pose, into a 2-D traversability "
        "grid (traversable / obstacle / unknown per cell, log-odds, ground height and spread, "
        "slope, step height) and an OctoMap of obstacle voxels with free space carved along the "
        "rays.\n"
        "-i: (a) an MRPT rawlog: robot poses from SensoryFrame actions "
        "(CActionRobotMovement2D, integrated) or CObservationOdometry records, or from --poses "
        "(TUM: by observation timestamp; KITTI: by LiDAR frame index); IMU records level the "
        "frames; (b) a KITTI sequence folder (velodyne/ scans) or a folder of scans (.bin, .pcd, "
        ".ply; -f): poses from --poses or DIR/poses.txt (cam0 poses, turned into LiDAR poses "
        "with the Tr of --calib or DIR/calib.txt). Without any pose source every frame is mapped "
        "at the identity pose, with a warning.\n"
        "-o: the output folder, with (NAME = input file name without extension): NAME.bt "
        "(OctoMap, for octovis), NAME_grid.gridmap.gz (COccupancyGridMap2D: traversable free, "
        "obstacle occupied, unknown 0.5), NAME_height.gridmap.gz (CHeightGridMap2D), "
        "NAME_traversability.png (green traversable, red obstacle, light grey observed but "
        "undecided, dark grey unseen; north up), NAME_occupancy.png, NAME_height.png (jet), "
        "NAME.3Dscene (SceneViewer3D), NAME.travelmap (the serialized map). Exit status 0 on "
        "success, 1 on any error.",
        {"travel-map -i data/sequences/00 -o map00",
         "travel-map -i drive.rawlog -o map -p vlp16 --resolution 0.25",
         "travel-map -i drive.rawlog --poses gt.tum -o map --probe 2.5,0 -q"});
    TCLAP::CmdLine& cmd = line.cmd;
    const travel::apps::CommonFlags flags(line, false, "");
    TCLAP::ValueArg<std::string> extent(
        "", "extent", "Grid extent in metres, world frame (default -40,40,-40,40)", false, "",
        "MIN_X,MAX_X,MIN_Y,MAX_Y", cmd);
    TCLAP::ValueArg<double> resolution("", "resolution", "Grid cell side [m] (default 0.2)", false,
                                       0, "M", cmd);
    line.checks.push_back([&resolution] {
        if (resolution.isSet() &&
            !(resolution.getValue() > 0 && std::isfinite(resolution.getValue())))
            throw travel::apps::usageError("--resolution must be > 0 (metres)");
    });
    TCLAP::ValueArg<std::string> poses("", "poses", "Pose file (TUM or KITTI format)", false, "",
                                       "FILE", cmd);
    TCLAP::ValueArg<std::string> calib(
        "", "calib",
        "KITTI calib.txt (Tr: velodyne -> cam0) turning a KITTI pose file's cam0 poses into LiDAR "
        "poses; scan inputs only (default: DIR/calib.txt)",
        false, "", "FILE", cmd);
    const travel::apps::MaxFramesFlag max_frames(line, "LiDAR frames");
    const travel::apps::MemoryLimitFlag max_memory(cmd);
    const travel::apps::JobsFlag jobs(
        line, "scan folders",
        "one reading, segmenting and fusing the next scans into the grid while the other "
        "updates the OctoMap with the previous ones (more than 2 do not help: both go frame by "
        "frame; rawlogs: 1)");
    TCLAP::MultiArg<std::string> probe(
        "", "probe",
        "Print the state of the grid cell at world X,Y after mapping (repeatable; a line "
        "'probe X,Y: traversable|obstacle|unknown|outside', also with -q)",
        false, "X,Y", cmd);
    if (auto code = line.parse(argc, argv)) return *code;

    Options o;
    o.extent = extent.getValue();
    if (resolution.isSet()) o.resolution = resolution.getValue();
    o.poses = poses.getValue();
    o.calib = calib.getValue();
    o.max_frames = max_frames.count();
    o.jobs = jobs.count();
    o.verbosity = travel::apps::verbosityFrom(flags.quiet(), flags.verbose());
    const bool print = o.verbosity != travel::apps::Verbosity::Quiet;
    std::vector<std::pair<double, double>> probes;
    for (const std::string& text : probe.getValue()) {
        const std::vector<double> xy =
            travel::apps::parseNumbers(text, 2, "--probe", "X,Y in metres");
        probes.emplace_back(xy[0], xy[1]);
    }
    const std::string note = travel::apps::applyMemoryLimit(max_memory.mib());
    if (!note.empty() && print) std::cerr << "travel-map: " << note << "\n";

    // An 80 m x 80 m grid unless the configuration or --extent says otherwise; --set last.
    travel::Config defaults;
    defaults.map.min_x = defaults.map.min_y = -40;
    defaults.map.max_x = defaults.map.max_y = 40;
    const travel::Config configuration = flags.config.load(
        defaults, [&o](travel::Config& config) { applyGridFlags(o, config.map); });
    if (flags.config.print(configuration)) return 0;
    o.input = flags.inputPath();
    o.output_dir = flags.outputPath();
    o.format = flags.scanFormat();

    travel_mrpt::registerClasses();
    const auto start = Clock::now();
    travel::apps::Notes notes("travel-map", o.verbosity);  // outlives the map's filter
    travel_mrpt::CTraversabilityMap map(mapOptions(configuration));
    notes.listen(map.filter());
    // Scans (a folder, a KITTI sequence or one scan file) or else a rawlog.
    const bool kitti = fs::is_directory(o.input) || travel::isScanPath(o.input);
    if (!kitti) flags.requireAutoFormat("rawlogs (-f is for scan inputs)");
    std::optional<travel::ScanList> scans;
    if (kitti) scans = travel::listScans(o.input, o.format);
    std::string pose_path = o.poses;
    // A folder's poses.txt (not a single scan's: KITTI poses go by frame index).
    const fs::path sequence = kitti ? travel::apps::sequenceFolder(*scans, o.input) : fs::path();
    if (pose_path.empty() && fs::is_directory(o.input) && fs::exists(sequence / "poses.txt"))
        pose_path = (sequence / "poses.txt").string();
    std::optional<PoseFileSource> pose_file;
    if (!pose_path.empty()) pose_file = PoseFileSource{travel::readPoseFile(pose_path)};
    o.poses = pose_path;
    // --calib acts on a KITTI pose file of scan inputs only: anywhere else it would be ignored.
    if (calib.isSet() && !kitti)
        throw travel::apps::usageError(
            "--calib is for scan inputs with a KITTI pose file; a rawlog's poses are robot poses");
    if (calib.isSet() && (!pose_file || pose_file->trajectory.timed()))
        throw travel::apps::usageError(
            "--calib needs a KITTI pose file (--poses, or poses.txt beside the scans) to apply "
            "its Tr to");

    travel::apps::requireCreatableFolder(o.output_dir);  // created when the map is written

    Stats stats;
    const double cpu_start = cpuSeconds();
    if (kitti)
        travel::apps::mapKitti(o, *scans, map, stats, pose_file, notes);
    else
        travel::apps::mapRawlog(o, map, stats, pose_file, notes);
    const double map_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double map_cpu_seconds = cpuSeconds() - cpu_start;
    if (stats.inserted == 0 && stats.no_pose > 0)
        throw std::runtime_error(o.poses + ": no pose for any of the " +
                                 std::to_string(stats.no_pose) +
                                 " LiDAR frames (TUM: timestamps outside the file's range or "
                                 "more than 1 s between poses; KITTI: fewer lines than frames)");
    if (stats.inserted == 0)
        throw std::runtime_error(
            o.input + ": no LiDAR frame could be mapped" +
            (map.lastRejection().empty() ? "" : " (last: " + map.lastRejection() + ")"));

    const std::string name = fs::is_directory(o.input) ? fs::path(o.input).filename().string()
                                                       : fs::path(o.input).stem().string();
    travel::apps::createFolder(o.output_dir);
    const std::string prefix = (fs::path(o.output_dir) / name).string();
    const auto export_start = Clock::now();
    std::vector<std::string> written;
    {
        const travel::apps::MuteLibraryStderr mute;  // liboctomap's " done." per tree write
        written = travel_mrpt::exportAll(map, prefix);
        travel::PartFile file(prefix + ".travelmap");
        travel_mrpt::GzFileOutput out(file.part(), file.path());
        mrpt::serialization::archiveFrom(out) << map;
        out.close();
        file.commit();
        written.push_back(file.path());
    }
    const double export_seconds =
        std::chrono::duration<double>(Clock::now() - export_start).count();

    if (print) {
        std::size_t traversable = 0, obstacle = 0;
        for (std::size_t c = 0; c < map.grid().cellCount(); ++c) {
            traversable += map.state(long(c)) == travel::CellState::Traversable;
            obstacle += map.state(long(c)) == travel::CellState::Obstacle;
        }
        std::printf("travel-map: %s -> %s\n", o.input.c_str(), o.output_dir.c_str());
        std::printf("  records: %zu, LiDAR frames mapped: %zu, rejected: %zu", stats.records,
                    stats.inserted, stats.rejected);
        if (stats.no_pose) std::printf(", without pose: %zu", stats.no_pose);
        std::printf("\n");
        std::printf("  poses: %s\n", stats.pose_source.c_str());
        std::printf(
            "  grid: %d x %d cells of %.3g m, observed %zu: traversable %zu, obstacle %zu\n",
            map.grid().sizeX(), map.grid().sizeY(), map.options().resolution,
            map.grid().observedCells(), traversable, obstacle);
        std::printf("  OctoMap: %zu leaves of %.3g m, %zu occupied voxels\n",
                    map.octree().getNumLeafNodes(), map.options().octomap_resolution,
                    map.getAsSimplePointsMap()->size());
        std::printf(
            "  time: mapping %.2f s in all, start-up and first frame included (mean %.1f ms per "
            "frame; CPU %.1f ms per frame, all threads), exports %.2f s\n",
            map_seconds, 1000.0 * map_seconds / double(stats.inserted),
            1000.0 * map_cpu_seconds / double(stats.inserted), export_seconds);
        if (!stats.times.empty()) {
            // Medians, not means: the first frames and a busy machine make outliers.
            const auto median = [&](auto get) {
                std::vector<double> v;
                for (const auto& t : stats.times) v.push_back(get(t));
                std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
                return v[v.size() / 2];
            };
            using T = travel::apps::FrameTimes;
            std::printf(
                "  per frame (median, wall): read %.1f ms, convert %.1f ms, segmentation %.1f ms, "
                "grid %.1f ms, OctoMap %.1f ms; whole frame %.1f ms (-j %u)\n",
                median([](const T& t) { return t.read_ms; }),
                median([](const T& t) { return t.map.convert_ms; }),
                median([](const T& t) { return t.map.segment_ms; }),
                median([](const T& t) { return t.map.grid_ms; }),
                median([](const T& t) { return t.map.octomap_ms; }),
                median([](const T& t) { return t.interval_ms; }),
                kitti ? std::min(o.jobs, 2u) : 1u);
            if (kitti)  // CPU, not wall: what each thread costs, whatever else the machine runs
                std::printf(
                    "  per frame (median, CPU): read + segmentation + grid %.1f ms, "
                    "OctoMap %.1f ms\n",
                    median([](const T& t) { return t.cpu_ms[0]; }),
                    median([](const T& t) { return t.cpu_ms[1]; }));
        }
        for (const auto& path : written) std::printf("  wrote %s\n", path.c_str());
    }
    for (const auto& [x, y] : probes) {
        const long cell = map.grid().cellIndex(x, y);
        std::printf("probe %g,%g: %s\n", x, y,
                    cell < 0 ? "outside" : travel::toString(map.state(cell)));
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return travel::apps::runMain("travel-map", run, argc, argv);
}
