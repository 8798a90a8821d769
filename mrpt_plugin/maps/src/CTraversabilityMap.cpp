// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/CTraversabilityMap.hpp"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "travel/Errors.hpp"
#include "travel_mrpt/MapExport.hpp"
#include "travel_mrpt/TravelFilter.hpp"

using travel::PointClass;

namespace travel_mrpt {

IMPLEMENTS_SERIALIZABLE(CTraversabilityMap, CMetricMap, travel_mrpt)

// "traversabilityMap" is the name .ini files use: traversabilityMap_count=1.
MAP_DEFINITION_REGISTER("travel_mrpt::CTraversabilityMap,traversabilityMap",
                        travel_mrpt::CTraversabilityMap)

CTraversabilityMap::TMapDefinition::TMapDefinition() = default;

void CTraversabilityMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& sectionNamePrefix) {
    options.loadFromConfigFile(source, sectionNamePrefix + "_creationOpts");
    options.loadFromConfigFile(source, sectionNamePrefix + "_insertOpts");
}

void CTraversabilityMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
    mrpt::config::CConfigFileMemory text;
    options.saveToConfigFile(text, "traversabilityMap");
    out << text.getContent();
}

mrpt::maps::CMetricMap* CTraversabilityMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
    const auto& definition = dynamic_cast<const CTraversabilityMap::TMapDefinition&>(def);
    return new CTraversabilityMap(definition.options);
}

// ------------------------------------------------------------------------------------------

namespace {

/// Packs an OctoMap key into one sortable integer.
uint64_t pack(const octomap::OcTreeKey& k) {
    return (uint64_t(k[0]) << 32) | (uint64_t(k[1]) << 16) | uint64_t(k[2]);
}
octomap::OcTreeKey unpack(uint64_t v) {
    return octomap::OcTreeKey(uint16_t(v >> 32), uint16_t(v >> 16), uint16_t(v));
}

}  // namespace

struct CTraversabilityMap::Scratch {
    std::vector<uint64_t> ground_ends, obstacle_ends, far_ends, free_keys;
    octomap::KeyRay ray;
};

CTraversabilityMap::CTraversabilityMap(const TraversabilityMapOptions& options)
    : filter_(std::make_unique<TravelFilter>()),
      frame_(std::make_unique<TravelFrame>()),
      scratch_(std::make_unique<Scratch>()) {
    setOptions(options);
}

CTraversabilityMap::CTraversabilityMap(const CTraversabilityMap& other)
    : CTraversabilityMap(other.options_) {
    *this = other;
}

CTraversabilityMap& CTraversabilityMap::operator=(const CTraversabilityMap& other) {
    if (this == &other) return *this;
    setOptions(other.options_);
    grid_ = other.grid_;
    octree_ = std::make_unique<octomap::OcTree>(*other.octree_);  // copy constructor only
    frames_inserted_ = other.frames_inserted_;
    obstacle_points_dirty_ = true;
    return *this;
}

CTraversabilityMap::~CTraversabilityMap() = default;

void CTraversabilityMap::setOptions(const TraversabilityMapOptions& options) {
    options.validate();
    options_ = options;
    filter_->setOptions(options_.travel);
    internal_clear();
}

void CTraversabilityMap::resetOctree() {
    octree_ = std::make_unique<octomap::OcTree>(options_.octomap_resolution);
    octree_->setProbHit(options_.octomap_prob_hit);
    octree_->setProbMiss(options_.octomap_prob_miss);
}

void CTraversabilityMap::internal_clear() {
    grid_.reset(options_);
    resetOctree();
    filter_->reset();
    frames_inserted_ = 0;
    obstacle_points_dirty_ = true;
}

CellState CTraversabilityMap::stateAt(double x, double y) const {
    return grid_.state(grid_.cellIndex(x, y), options_);
}

bool CTraversabilityMap::internal_insertObservation(
    const mrpt::obs::CObservation& obs,
    const std::optional<const mrpt::poses::CPose3D>& robotPose) {
    const mrpt::poses::CPose3D pose = robotPose ? *robotPose : mrpt::poses::CPose3D();
    if (robotPose) filter_->setRobotPose(pose, obs.timestamp);
    last_rejection_.clear();
    if (!filter_->filter(obs, *frame_, &last_rejection_)) return false;
    fuseFrame(*frame_, pose);
    return true;
}

void CTraversabilityMap::fuseFrame(const TravelFrame& frame,
                                   const mrpt::poses::CPose3D& robotPose) {
    if (!frame.aligned) throw std::invalid_argument("fuseFrame: the frame has no aligned cloud");
    const travel::AlignedCloud& a = *frame.aligned;
    const travel::Result& result = frame.result;
    const travel::TerrainModel& terrain = result.terrain;
    const std::size_t n = std::min({a.x.size(), a.valid.size(), result.labels.size()});

    // aligned -> sensor (R_align^T) -> world (robot pose + sensor pose).
    const mrpt::poses::CPose3D sensor_in_world = robotPose + frame.sensorPose;
    const Eigen::Matrix3f to_world = sensor_in_world.getRotationMatrix().asEigen().cast<float>() *
                                     frame.alignedRotation.transpose();
    const Eigen::Vector3f origin(float(sensor_in_world.x()), float(sensor_in_world.y()),
                                 float(sensor_in_world.z()));
    const float sensor_height = float(options_.travel.params.sensor_height);
    const float min_h = float(options_.obstacle_min_height);
    const float max_h = float(options_.obstacle_max_height);
    const float max_ray = float(options_.max_ray_length);

    Scratch& s = *scratch_;
    s.ground_ends.clear();
    s.obstacle_ends.clear();
    s.far_ends.clear();
    octomap::OcTreeKey key;
    const auto endKey = [&](const Eigen::Vector3f& p, std::vector<uint64_t>& near_list) {
        Eigen::Vector3f end = p;
        std::vector<uint64_t>* list = &near_list;
        const float range = (p - origin).norm();
        if (range > max_ray) {  // too long to trust its end: carve up to max_ray only
            end = origin + (p - origin) * (max_ray / range);
            list = &s.far_ends;
        }
        if (octree_->coordToKeyChecked(end.x(), end.y(), end.z(), key)) list->push_back(pack(key));
    };

    grid_.beginFrame();
    // Pass 1: ground points, so that pass 2 sees this frame's ground heights too.
    for (std::size_t i = 0; i < n; ++i) {
        if (!a.valid[i] || result.labels[i] != PointClass::Ground) continue;
        const Eigen::Vector3f pa(a.x[i], a.y[i], a.z[i]);
        const Eigen::Vector3f pw = to_world * pa + origin;
        grid_.addGround(pw.x(), pw.y(), pw.z(), terrain.groundSlopeDeg(pa.x(), pa.y()));
        endKey(pw, s.ground_ends);
    }
    // Pass 2: non-ground points, by their height above the local ground: TRAVEL's
    // (TerrainModel::heightAboveGround), else the ground fused in the grid cell this frame, else
    // its cluster's ground, else the sensor height.
    for (std::size_t i = 0; i < n; ++i) {
        if (!a.valid[i] || result.labels[i] != PointClass::NonGround) continue;
        const Eigen::Vector3f pa(a.x[i], a.y[i], a.z[i]);
        const Eigen::Vector3f pw = to_world * pa + origin;
        float height = terrain.heightAboveGround(pa.x(), pa.y(), pa.z());
        if (!std::isfinite(height)) {
            const long cell = grid_.cellIndex(pw.x(), pw.y());
            const uint32_t cluster = i < result.cluster_id.size() ? result.cluster_id[i] : 0;
            if (cell >= 0 && std::isfinite(grid_.groundHeightThisFrame(cell)))
                height = pw.z() - grid_.groundHeightThisFrame(cell);
            else if (cluster > 0 && cluster <= result.clusters.size() &&
                     std::isfinite(result.clusters[cluster - 1].ground_z))
                height = pa.z() - result.clusters[cluster - 1].ground_z;
            else
                height = pa.z() + sensor_height;
        }
        if (height < min_h) continue;  // kerb faces, low vegetation: neither ground nor obstacle
        if (height <= max_h) grid_.addObstacle(pw.x(), pw.y());
        endKey(pw, s.obstacle_ends);
    }
    grid_.endFrame(mrpt::Clock::toDouble(frame.timestamp), options_);

    // OctoMap: one ray per distinct end voxel (not per point), free voxels deduplicated, then
    // each voxel updated once: hits occupied, traversed voxels free unless hit in this frame.
    const auto sortUnique = [](std::vector<uint64_t>& v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
    };
    sortUnique(s.ground_ends);
    sortUnique(s.obstacle_ends);
    sortUnique(s.far_ends);
    s.free_keys.clear();
    const octomap::point3d o(origin.x(), origin.y(), origin.z());
    const auto castTo = [&](uint64_t end) {
        if (!octree_->computeRayKeys(o, octree_->keyToCoord(unpack(end)), s.ray)) return;
        for (const octomap::OcTreeKey& k : s.ray) s.free_keys.push_back(pack(k));
    };
    const std::size_t stride = std::size_t(options_.ray_stride);
    for (std::size_t k = 0; k < s.ground_ends.size(); k += stride) castTo(s.ground_ends[k]);
    for (uint64_t end : s.obstacle_ends) castTo(end);
    for (uint64_t end : s.far_ends) {
        castTo(end);
        s.free_keys.push_back(end);  // the truncated end itself was traversed
    }
    sortUnique(s.free_keys);
    for (uint64_t k : s.free_keys)
        if (!std::binary_search(s.obstacle_ends.begin(), s.obstacle_ends.end(), k))
            octree_->updateNode(unpack(k), false, true);
    for (uint64_t k : s.obstacle_ends) octree_->updateNode(unpack(k), true, true);
    octree_->updateInnerOccupancy();

    ++frames_inserted_;
    obstacle_points_dirty_ = true;
}

bool CTraversabilityMap::isEmpty() const {
    return grid_.empty() && octree_->getNumLeafNodes() == 0;
}

double CTraversabilityMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation&, const mrpt::poses::CPose3D&) const {
    return 0.0;
}

const mrpt::maps::CSimplePointsMap* CTraversabilityMap::getAsSimplePointsMap() const {
    if (!obstacle_points_) obstacle_points_ = std::make_shared<mrpt::maps::CSimplePointsMap>();
    if (obstacle_points_dirty_) {
        obstacle_points_->clear();
        for (auto it = octree_->begin_leafs(), end = octree_->end_leafs(); it != end; ++it)
            if (octree_->isNodeOccupied(*it))
                obstacle_points_->insertPointFast(float(it.getX()), float(it.getY()),
                                                  float(it.getZ()));
        obstacle_points_->mark_as_modified();
        obstacle_points_dirty_ = false;
    }
    return obstacle_points_.get();
}

void CTraversabilityMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
    const GridGeometry& g = options_;
    // The plane at the mean ground height of the observed cells, so that voxels sit on it.
    double z_sum = 0;
    std::size_t z_count = 0;
    for (std::size_t c = 0; c < grid_.cellCount(); ++c)
        if (std::isfinite(grid_.groundHeight(long(c))))
            z_sum += grid_.groundHeight(long(c)), ++z_count;
    auto plane = mrpt::opengl::CTexturedPlane::Create(float(g.min_x), float(g.max_x),
                                                      float(g.min_y), float(g.max_y));
    plane->assignImage(traversabilityImage(*this, /*north_up=*/false));
    plane->setLocation(0, 0, z_count ? z_sum / double(z_count) - 0.02 : 0.0);
    o.insert(plane);

    auto voxels = mrpt::opengl::CPointCloudColoured::Create();
    const mrpt::maps::CSimplePointsMap& points = *getAsSimplePointsMap();
    voxels->loadFromPointsMap(&points);
    voxels->recolorizeByCoordinate(0.f, 3.f, 2);  // jet over 0..3 m
    voxels->setPointSize(4.0f);
    o.insert(voxels);
}

std::string CTraversabilityMap::asString() const {
    std::size_t traversable = 0, obstacle = 0;
    for (std::size_t c = 0; c < grid_.cellCount(); ++c) {
        const CellState st = state(long(c));
        traversable += st == CellState::Traversable;
        obstacle += st == CellState::Obstacle;
    }
    std::ostringstream out;
    out << "CTraversabilityMap: " << grid_.sizeX() << " x " << grid_.sizeY() << " cells of "
        << options_.resolution << " m, " << grid_.observedCells() << " observed (" << traversable
        << " traversable, " << obstacle << " obstacle), OctoMap " << octree_->getNumLeafNodes()
        << " leaves of " << options_.octomap_resolution << " m, " << frames_inserted_ << " frames";
    return out.str();
}

void CTraversabilityMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
    exportAll(*this, prefix);
}

// ---- Serialization: options as ini text, the grid arrays, the OctoMap as .bt bytes ----

uint8_t CTraversabilityMap::serializeGetVersion() const {
    return 0;
}

void CTraversabilityMap::serializeTo(mrpt::serialization::CArchive& out) const {
    mrpt::config::CConfigFileMemory text;
    options_.saveToConfigFile(text, "traversabilityMap");
    out << text.getContent();
    auto arrays = const_cast<TraversabilityGrid&>(grid_).arrays();
    for (auto* v : arrays.floats) out << *v;
    for (auto* v : arrays.counts) out << *v;
    for (auto* v : arrays.doubles) out << *v;
    out << uint64_t(frames_inserted_);
    std::ostringstream bt;
    octree_->writeBinaryConst(bt);
    out << bt.str();
}

void CTraversabilityMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    if (version != 0) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    std::string text;
    in >> text;
    TraversabilityMapOptions options;
    try {
        options.loadFromConfigFile(mrpt::config::CConfigFileMemory(text), "traversabilityMap");
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("CTraversabilityMap: corrupt options: ") + e.what());
    }
    setOptions(options);
    auto arrays = grid_.arrays();
    for (auto* v : arrays.floats) in >> *v;
    for (auto* v : arrays.counts) in >> *v;
    for (auto* v : arrays.doubles) in >> *v;
    grid_.arraysLoaded();
    uint64_t frames = 0;
    in >> frames;
    frames_inserted_ = std::size_t(frames);
    std::string bt;
    in >> bt;
    std::istringstream bt_in(bt);
    if (!octree_->readBinary(bt_in))
        throw std::runtime_error("CTraversabilityMap: corrupt OctoMap data");
    obstacle_points_dirty_ = true;
}

}  // namespace travel_mrpt
