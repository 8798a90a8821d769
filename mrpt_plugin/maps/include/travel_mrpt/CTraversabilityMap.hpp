// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A CMetricMap fusing TRAVEL-segmented LiDAR frames into
//   - a 2-D traversability grid (TraversabilityGrid: per cell state, log-odds, ground height and
//     spread, slope, step height, last-seen time), and
//   - an OctoMap (octomap::OcTree) of obstacle voxels, with free space carved along the rays to
//     ground and obstacle hits.
// insertObservation(obs, robotPose) runs the observation through a TravelFilter (any LiDAR
// observation the filter converts: Velodyne, rotating scans, point clouds, depth cameras), with
// the robot pose as its attitude source, and fuses the labelled points in the world frame.
//
// CMultiMetricMap creates it from an .ini (the plugin module registers it):
//   [map]
//   traversabilityMap_count=1
//   [map_traversabilityMap_00_creationOpts]
//   min_x=-30  max_x=30  min_y=-30  max_y=30  resolution=0.2
//   [map_traversabilityMap_00_insertOpts]
//   preset=vlp16  sensor_height=1.8  max_step_height=0.1
// The keys and their units are listed in TraversabilityMapOptions.hpp (and docs/map.md).
//
// The grid fusion, the obstacle rule (height above the local ground: its one fallback chain)
// and the ray bookkeeping are libtravel's (travel::fuseFrame, travel::VoxelUpdate in
// travel/traversability/FrameFusion.hpp); this class places the frame with MRPT poses and
// casts the rays in the OctoMap.
#pragma once

#include <mrpt/maps/CMetricMap.h>

#include <cstdint>
#include <memory>
#include <string>

#include "travel/traversability/TraversabilityGrid.hpp"
#include "travel_mrpt/TraversabilityMapOptions.hpp"

namespace octomap {
class OcTree;
}
namespace travel {
struct PointCloud;
struct RayEnds;
}  // namespace travel

namespace travel_mrpt {

class TravelFilter;
struct TravelFrame;

class CTraversabilityMap : public mrpt::maps::CMetricMap {
    DEFINE_SERIALIZABLE(CTraversabilityMap, travel_mrpt)

  public:
    explicit CTraversabilityMap(const TraversabilityMapOptions& options = {});
    CTraversabilityMap(const CTraversabilityMap& other);
    CTraversabilityMap& operator=(const CTraversabilityMap& other);
    ~CTraversabilityMap() override;

    /// Validates (throws travel::ConfigError), replaces the options and clears the map.
    void setOptions(const TraversabilityMapOptions& options);
    const TraversabilityMapOptions& options() const { return options_; }

    const TraversabilityGrid& grid() const { return grid_; }
    /// State of the cell holding world (x, y); Unknown outside the grid.
    CellState stateAt(double x, double y) const;
    CellState state(long cell) const { return grid_.state(cell, options_); }
    /// The OctoMap of the voxels. Frames update a flat store of the voxels' log-odds
    /// (travel::VoxelLogOdds); the tree is brought up to date here, with the voxels changed
    /// since the last call: same nodes and values as updating it frame by frame. The first
    /// call after frames writes into the tree: not to be called while another thread fuses
    /// voxels (fuseVoxels, fuseFrame) or reads the map.
    const octomap::OcTree& octree() const;

    /// The filter that segments each observation: feed it IMU / odometry (processImu...) in
    /// rawlog order for levelling and deskew. Its options are options().travel.
    TravelFilter& filter() { return *filter_; }
    /// The last frame fused (valid after a successful insertion).
    const TravelFrame& lastFrame() const { return *frame_; }
    std::size_t framesInserted() const { return frames_inserted_; }
    /// Why the last insertObservation() returned false (empty after a success).
    const std::string& lastRejection() const { return last_rejection_; }

    /// Wall-clock times of the last successful insertion, in ms: conversion of the observation
    /// to travel's cloud, TRAVEL segmentation, the 2-D grid, and the OctoMap update (voxel keys,
    /// ray casting, node updates). After fuseFrame() alone: grid and OctoMap only.
    struct InsertTimes {
        double convert_ms = 0, segment_ms = 0, grid_ms = 0, octomap_ms = 0;
    };
    const InsertTimes& lastInsertTimes() const { return last_times_; }

    /// insertObservation() for a cloud already in travel's form (own drivers, scan files), in
    /// two halves: segment() runs the filter on `cloud` (sensor frame, the sensor at
    /// sensorPose on the robot) taken at robotPose and time t, into `frame`; fuseFrame(frame,
    /// robotPose) fuses it (before the next segment(): frame.aligned is the filter's buffer).
    /// Frames are segmented in time order. segment() uses only the filter. Returns false (and
    /// lastRejection()) for an empty cloud or a robot or sensor pose that is not finite (as
    /// insertObservation(), which refuses a NaN robot pose so).
    bool segment(const travel::PointCloud& cloud, const mrpt::poses::CPose3D& robotPose,
                 mrpt::Clock::time_point t, TravelFrame& frame,
                 const std::string& sensorLabel = "lidar",
                 const mrpt::poses::CPose3D& sensorPose = {});
    /// Fuses an already segmented frame taken at robotPose (world). frame.aligned must be valid
    /// and robotPose finite (std::invalid_argument otherwise).
    /// The same as fuseGrid() then fuseVoxels().
    void fuseFrame(const TravelFrame& frame, const mrpt::poses::CPose3D& robotPose);
    /// fuseFrame() in two halves, for callers that overlap them on two threads: fuseGrid()
    /// fuses the frame into the 2-D grid and collects its rays in `rays` (world frame);
    /// fuseVoxels(rays) updates the OctoMap from them. fuseGrid() uses only the grid,
    /// fuseVoxels() only the OctoMap: each may run on its own thread, each in frame order.
    /// They return their wall time in ms (lastInsertTimes() is fuseFrame()'s).
    double fuseGrid(const TravelFrame& frame, const mrpt::poses::CPose3D& robotPose,
                    travel::RayEnds& rays);
    double fuseVoxels(const travel::RayEnds& rays);

    /// The map's state in two files, for a later run to start from: prefix.travelgrid (the
    /// options, as ini text, and every field of the traversability grid; gzip) and prefix.ot
    /// (the OctoMap with each voxel's log-odds: OctoMap's .ot format, octovis opens it; a .bt
    /// keeps only occupied / free, so an object seen once would come back as sure as a wall).
    /// Throws std::runtime_error naming the file. (The exports for other programs, .bt and
    /// .gridmap.gz: saveMetricMapRepresentationToFile.)
    void saveTo(const std::string& prefix) const;
    /// Replaces options, grid and OctoMap by those saveTo(prefix) wrote (the filter restarts).
    /// Throws std::runtime_error naming the file when one is missing, truncated or corrupt;
    /// the map is then left as it was.
    void loadFrom(const std::string& prefix);

    // ---- CMetricMap ----
    bool isEmpty() const override;
    /// Writes prefix.bt (OctoMap), prefix_grid.gridmap.gz (COccupancyGridMap2D),
    /// prefix_height.gridmap.gz (CHeightGridMap2D), prefix_traversability.png,
    /// prefix_occupancy.png, prefix_height.png and prefix.3Dscene. Throws std::runtime_error
    /// naming the file on failure.
    void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
    /// Centres of the occupied OctoMap voxels (obstacles), world frame. Rebuilt after changes.
    const mrpt::maps::CSimplePointsMap* getAsSimplePointsMap() const override;
    /// The traversability grid as a textured plane at its mean ground height and the occupied
    /// voxels as points coloured by height.
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
    std::string asString() const override;

    MAP_DEFINITION_START(CTraversabilityMap)
    TraversabilityMapOptions options;
    MAP_DEFINITION_END(CTraversabilityMap)

  private:
    void internal_clear() override;
    bool internal_insertObservation(
        const mrpt::obs::CObservation& obs,
        const std::optional<const mrpt::poses::CPose3D>& robotPose = std::nullopt) override;
    /// Not a localization map: always 0 (and canComputeObservationLikelihood() is false).
    double internal_computeObservationLikelihood(
        const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const override;
    bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation&) const override {
        return false;
    }
    void resetOctree();
    /// Writes the voxels changed since the last call into octree_ (octree() and every reader).
    void syncOctree() const;
    /// Options, grid arrays and frame count (serialization and saveTo's grid file).
    void writeGridState(mrpt::serialization::CArchive& out) const;
    void readGridState(mrpt::serialization::CArchive& in);

    TraversabilityMapOptions options_;
    TraversabilityGrid grid_;
    std::unique_ptr<octomap::OcTree> octree_;
    std::unique_ptr<TravelFilter> filter_;
    std::unique_ptr<TravelFrame> frame_;
    std::size_t frames_inserted_ = 0;
    std::string last_rejection_;
    InsertTimes last_times_;

    // Per-frame scratch, reused: voxel keys of ray end points and of the traversed voxels.
    struct Scratch;
    std::unique_ptr<Scratch> scratch_;
    mutable std::shared_ptr<mrpt::maps::CSimplePointsMap> obstacle_points_;
    mutable bool obstacle_points_dirty_ = true;
};

}  // namespace travel_mrpt
