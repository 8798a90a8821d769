// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/CTraversabilityMap.hpp"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <bitset>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

#include "travel/Errors.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/traversability/FrameFusion.hpp"
#include "travel/traversability/StaticScene.hpp"
#include "travel_mrpt/GzFileOutput.hpp"
#include "travel_mrpt/MapExport.hpp"
#include "travel_mrpt/MrptMessage.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace travel_mrpt {

IMPLEMENTS_SERIALIZABLE(CTraversabilityMap, CMetricMap, travel_mrpt)

// "traversabilityMap" is the name .ini files use: traversabilityMap_count=1.
MAP_DEFINITION_REGISTER("travel_mrpt::CTraversabilityMap,traversabilityMap",
                        travel_mrpt::CTraversabilityMap)

CTraversabilityMap::TMapDefinition::TMapDefinition() = default;

void CTraversabilityMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& sectionNamePrefix) {
    // One set of keys: a preset in either section is the base of both (docs/map.md).
    options.loadFromMapDefinition(source, sectionNamePrefix);
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

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Packs an OctoMap key into one sortable integer.
uint64_t pack(const octomap::OcTreeKey& k) {
    return travel::packVoxelKey(k[0], k[1], k[2]);
}
octomap::OcTreeKey unpack(uint64_t v) {
    return octomap::OcTreeKey(uint16_t(v >> 32), uint16_t(v >> 16), uint16_t(v));
}

/// Sets leaf values of the tree, keys in any order (octree order is fastest), with one walk
/// down the tree: consecutive keys share most of their path from the root, so each descends
/// only from the deepest node it shares with the previous one (not from the root twice, as
/// OcTree::updateNode does with its early-abort search), creating nodes as updateNode does (a
/// pruned node expanded, its children inheriting its value), and a node's occupancy (the max
/// of its children, as updateInnerOccupancy sets it) is refreshed when the walk leaves it:
/// only the nodes above the voxels set, not the whole tree. finish() refreshes the rest.
class LeafWalk {
  public:
    explicit LeafWalk(octomap::OcTree& tree) : tree_(tree) {}

    void set(uint64_t packed, float log_odds) {
        const octomap::OcTreeKey key = unpack(packed);
        if (!tree_.getRoot()) {  // the root is the tree's to create: the first node of a tree
            tree_.setNodeValue(key, log_odds, /*lazy_eval=*/false);
            return;
        }
        if (valid_ < 0) {
            path_[0] = tree_.getRoot(), created_[0] = false, valid_ = 0;
        } else {
            // Deepest shared node: the child index at depth d uses key bit (15 - d).
            const uint64_t differ = packed ^ previous_;
            const uint32_t bits = uint32_t((differ >> 32) | (differ >> 16) | differ) & 0xFFFF;
            leave(bits ? kDepth - 1 - (31 - __builtin_clz(bits)) : kDepth);
        }
        for (int d = valid_; d < kDepth; ++d) {
            octomap::OcTreeNode* node = path_[d];
            const unsigned child = octomap::computeChildIdx(key, kDepth - 1 - d);
            bool just_created = false;
            if (!tree_.nodeChildExists(node, child)) {
                if (!tree_.nodeHasChildren(node) && !created_[d])
                    tree_.expandNode(node);  // a pruned node: its children inherit its value
                else
                    tree_.createNodeChild(node, child), just_created = true;
            }
            path_[d + 1] = tree_.getNodeChild(node, child), created_[d + 1] = just_created;
        }
        valid_ = kDepth;
        path_[kDepth]->setLogOdds(log_odds);
        previous_ = packed;
    }
    void finish() { leave(-1); }

  private:
    static constexpr int kDepth = 16;  // OctoMap's tree depth: keys of 16 bits
    /// Refreshes the inner nodes below `depth` on the path.
    void leave(int depth) {
        for (; valid_ > depth; --valid_)
            if (valid_ < kDepth) path_[valid_]->updateOccupancyChildren();
    }
    octomap::OcTree& tree_;
    octomap::OcTreeNode* path_[kDepth + 1];
    bool created_[kDepth + 1];
    int valid_ = -1;  // path_[0..valid_] is the current path
    uint64_t previous_ = 0;
};

/// VoxelLogOdds::BlockFill from the OctoMap: the log-odds the tree holds for the 8^3 voxels of
/// a block (a pruned ancestor's value, 0 for a voxel the tree lacks: a new node's value).
void fillBlockFromTree(void* context, uint64_t corner, float* values) {
    const auto& tree = *static_cast<const octomap::OcTree*>(context);
    constexpr int kBlockDepth = 16 - travel::VoxelLogOdds::kBlockBits;
    constexpr int kVoxels = 1 << (3 * travel::VoxelLogOdds::kBlockBits);
    const octomap::OcTreeKey key = unpack(corner);
    const octomap::OcTreeNode* node = tree.getRoot();
    for (int d = 0; node && d < kBlockDepth; ++d) {
        if (!tree.nodeHasChildren(node)) break;  // a pruned node: its value for all
        const unsigned child = octomap::computeChildIdx(key, 15 - d);
        node = tree.nodeChildExists(node, child) ? tree.getNodeChild(node, child) : nullptr;
    }
    if (!node || !tree.nodeHasChildren(node)) {
        std::fill(values, values + kVoxels, node ? node->getLogOdds() : 0.f);
        return;
    }
    for (int index = 0; index < kVoxels; ++index) {
        // The block's index interleaves the x, y, z bits as the children's numbers do.
        const octomap::OcTreeNode* voxel = node;
        for (int level = travel::VoxelLogOdds::kBlockBits - 1; voxel && level >= 0; --level) {
            if (!tree.nodeHasChildren(voxel)) break;
            const unsigned child = unsigned(index >> (3 * level)) & 7;
            voxel = tree.nodeChildExists(voxel, child) ? tree.getNodeChild(voxel, child) : nullptr;
        }
        values[index] = voxel ? voxel->getLogOdds() : 0.f;
    }
}

/// Checks the node stream of an OctoMap .ot file before octomap reads it: octomap's reader
/// (readNodesRecurs) recurses once per child bit without a depth limit and reads on past the end
/// of a truncated stream, so a corrupt file overflows the stack instead of failing. The stream
/// after the "data" header line is, depth first, per node a float value and a byte of child
/// bits; a complete one ends exactly at the end of the file with no node deeper than 16.
/// Returns what is wrong, or an empty string.
std::string otNodeStreamProblem(const std::string& bytes) {
    const std::string marker = "\ndata\n";
    const std::size_t data = bytes.find(marker);
    if (bytes.rfind("# Octomap OcTree file", 0) != 0 || data == std::string::npos)
        return "not an OctoMap OcTree file (.ot)";
    constexpr std::size_t kNodeBytes = sizeof(float) + 1;
    constexpr std::size_t kMaxDepth = 16;  // octomap's tree depth
    std::size_t pos = data + marker.size();
    std::vector<int> pending;  // children still to read, per open level
    const auto readNode = [&]() {
        if (bytes.size() - pos < kNodeBytes) return false;
        pending.push_back(
            static_cast<int>(std::bitset<8>(static_cast<unsigned char>(bytes[pos + 4])).count()));
        pos += kNodeBytes;
        return true;
    };
    if (!readNode()) return "truncated (no root node)";
    while (!pending.empty()) {
        if (pending.back() == 0) {
            pending.pop_back();
            continue;
        }
        --pending.back();
        if (pending.size() > kMaxDepth) return "corrupt: a node deeper than 16 levels";
        if (!readNode()) return "truncated";
    }
    if (pos != bytes.size()) return "corrupt: bytes after the last node";
    return {};
}

}  // namespace

struct CTraversabilityMap::Scratch {
    travel::Result static_result;  ///< the frame without its moving objects, when it has any
    travel::RayEnds ends;
    travel::VoxelUpdate voxels;
    /// The voxels' log-odds, the master copy for every block it holds: fuseVoxels() updates
    /// them here, syncOctree() writes the changed ones into the OctoMap when it is read.
    travel::VoxelLogOdds log_odds;
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
    octree_ = std::make_unique<octomap::OcTree>(other.octree());  // copy constructor only
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
    scratch_->log_odds.clear();
}

const octomap::OcTree& CTraversabilityMap::octree() const {
    syncOctree();
    return *octree_;
}

void CTraversabilityMap::syncOctree() const {
    travel::VoxelLogOdds& store = scratch_->log_odds;
    if (!store.hasChanges()) return;
    LeafWalk walk(*octree_);
    store.takeChanged([&](uint64_t key, float log_odds) { walk.set(key, log_odds); });
    walk.finish();
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
    if (!isFinitePose(pose)) {
        last_rejection_ =
            "'" + obs.sensorLabel + "': the robot pose is not finite: " + pose.asString();
        return false;
    }
    if (robotPose) filter_->setRobotPose(pose, obs.timestamp);
    last_rejection_.clear();
    if (!filter_->filter(obs, *frame_, &last_rejection_)) return false;
    fuseFrame(*frame_, pose);
    last_times_.convert_ms = frame_->convert_ms;
    last_times_.segment_ms = frame_->process_ms;
    return true;
}

bool CTraversabilityMap::segment(const travel::PointCloud& cloud,
                                 const mrpt::poses::CPose3D& robotPose, mrpt::Clock::time_point t,
                                 TravelFrame& frame, const std::string& sensorLabel,
                                 const mrpt::poses::CPose3D& sensorPose) {
    if (cloud.empty()) {
        last_rejection_ = "'" + sensorLabel + "': empty point cloud";
        return false;
    }
    if (!isFinitePose(robotPose) || !isFinitePose(sensorPose)) {
        last_rejection_ = "'" + sensorLabel +
                          "': the robot or sensor pose is not finite: " + robotPose.asString() +
                          ", " + sensorPose.asString();
        return false;
    }
    last_rejection_.clear();
    filter_->setRobotPose(robotPose, t);  // as insertObservation(obs, robotPose)
    filter_->filter(cloud, sensorPose, t, sensorLabel, frame);
    return true;
}

void CTraversabilityMap::fuseFrame(const TravelFrame& frame,
                                   const mrpt::poses::CPose3D& robotPose) {
    last_times_.grid_ms = fuseGrid(frame, robotPose, scratch_->ends);
    last_times_.octomap_ms = fuseVoxels(scratch_->ends);
    last_times_.convert_ms = last_times_.segment_ms = 0;
}

double CTraversabilityMap::fuseGrid(const TravelFrame& frame, const mrpt::poses::CPose3D& robotPose,
                                    travel::RayEnds& rays) {
    if (!frame.aligned) throw std::invalid_argument("fuseFrame: the frame has no aligned cloud");
    if (!isFinitePose(robotPose))
        throw std::invalid_argument("fuseFrame: the robot pose is not finite: " +
                                    robotPose.asString());
    const auto start = Clock::now();
    // aligned -> sensor (R_align^T) -> world (robot pose + sensor pose).
    const AlignedInWorld world = alignedInWorld(frame, robotPose);
    // Objects the tracker flags moving stay out of the static map (grid and OctoMap).
    const travel::Result& static_result =
        travel::withoutMovingObjects(frame.result, *frame.aligned, scratch_->static_result);
    const travel::PlacedFrame placed{*frame.aligned, static_result, world.rotation, world.origin,
                                     mrpt::Clock::toDouble(frame.timestamp)};
    travel::fuseFrame(placed, options_, grid_, rays);
    ++frames_inserted_;
    return msSince(start);
}

double CTraversabilityMap::fuseVoxels(const travel::RayEnds& rays) {
    const auto start = Clock::now();
    // The ray ends as OctoMap keys; the voxels along the rays are carved free, the obstacle
    // ends marked occupied, each voxel once.
    travel::VoxelUpdate& voxels = scratch_->voxels;
    voxels.clear();
    octomap::OcTreeKey key;
    const auto toKeys = [&](const std::vector<Eigen::Vector3f>& points,
                            std::vector<uint64_t>& keys) {
        for (const Eigen::Vector3f& p : points)
            if (octree_->coordToKeyChecked(p.x(), p.y(), p.z(), key)) keys.push_back(pack(key));
    };
    toKeys(rays.ground, voxels.ground_ends);
    toKeys(rays.obstacle, voxels.obstacle_ends);
    toKeys(rays.far, voxels.far_ends);
    // The sensor in key units: OctoMap's key is floor(coordinate / resolution) + 32768.
    const double inv_res = 1.0 / options_.octomap_resolution;
    const Eigen::Vector3d origin = rays.origin.cast<double>() * inv_res +
                                   Eigen::Vector3d::Constant(double(octree_->coordToKey(0.0)));
    voxels.cast(std::size_t(options_.ray_stride), origin);
    // Free and occupied are disjoint: one update per voxel and frame, as OcTree::updateNode.
    const float min = float(octree_->getClampingThresMinLog()),
                max = float(octree_->getClampingThresMaxLog());
    travel::VoxelLogOdds& store = scratch_->log_odds;
    store.add(voxels.freeKeys(), octree_->getProbMissLog(), min, max, fillBlockFromTree,
              octree_.get());
    store.add(voxels.occupiedKeys(), octree_->getProbHitLog(), min, max, fillBlockFromTree,
              octree_.get());
    obstacle_points_dirty_ = true;
    return msSince(start);
}

bool CTraversabilityMap::isEmpty() const {
    return grid_.empty() && octree().getNumLeafNodes() == 0;
}

double CTraversabilityMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation&, const mrpt::poses::CPose3D&) const {
    return 0.0;
}

const mrpt::maps::CSimplePointsMap* CTraversabilityMap::getAsSimplePointsMap() const {
    if (!obstacle_points_) obstacle_points_ = std::make_shared<mrpt::maps::CSimplePointsMap>();
    if (obstacle_points_dirty_) {
        obstacle_points_->clear();
        const octomap::OcTree& tree = octree();
        for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it)
            if (tree.isNodeOccupied(*it))
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
    const double z_mean = grid_.meanGroundHeight();
    auto plane = mrpt::opengl::CTexturedPlane::Create(float(g.min_x), float(g.max_x),
                                                      float(g.min_y), float(g.max_y));
    plane->assignImage(traversabilityImage(*this, /*north_up=*/false));
    plane->setLocation(0, 0, std::isfinite(z_mean) ? z_mean - 0.02 : 0.0);
    o.insert(plane);

    auto voxels = mrpt::opengl::CPointCloudColoured::Create();
    const mrpt::maps::CSimplePointsMap& points = *getAsSimplePointsMap();
    voxels->loadFromPointsMap(&points);
    voxels->recolorizeByCoordinate(0.f, 3.f, 2);  // jet over 0..3 m
    voxels->setPointSize(4.0f);
    o.insert(voxels);
}

std::string CTraversabilityMap::asString() const {
    const auto counts = grid_.stateCounts(options_);
    std::ostringstream out;
    out << "CTraversabilityMap: " << grid_.sizeX() << " x " << grid_.sizeY() << " cells of "
        << options_.resolution << " m, " << grid_.observedCells() << " observed ("
        << counts[int(CellState::Traversable)] << " traversable, "
        << counts[int(CellState::Obstacle)] << " obstacle), OctoMap " << octree().getNumLeafNodes()
        << " leaves of " << options_.octomap_resolution << " m, " << frames_inserted_ << " frames";
    return out.str();
}

void CTraversabilityMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
    exportAll(*this, prefix);
}

// ---- Serialization: options as ini text, the grid arrays, the OctoMap as .ot bytes ----

namespace {
/// The first bytes of a .travelgrid file (saveTo), then its format version.
constexpr const char* kGridFileMagic = "TRAVEL traversability grid";
constexpr uint32_t kGridFileVersion = 1;
/// The longest options text a grid state may hold (saveToConfigFile writes a few kB).
constexpr std::size_t kMaxOptionsText = std::size_t(1) << 20;

/// The OcTree of .ot bytes (OctoMap's full format: every voxel's log-odds), checked before
/// octomap reads them and against the options' voxel size, with the options' hit and miss
/// probabilities; `where` leads every message.
std::unique_ptr<octomap::OcTree> readOtTree(std::string bytes,
                                            const TraversabilityMapOptions& options,
                                            const std::string& where) {
    const double resolution = options.octomap_resolution;
    const std::string problem = otNodeStreamProblem(bytes);
    if (!problem.empty()) throw std::runtime_error(where + ": " + problem);
    std::istringstream in(std::move(bytes));
    std::unique_ptr<octomap::AbstractOcTree> any(octomap::AbstractOcTree::read(in));
    auto* tree = dynamic_cast<octomap::OcTree*>(any.get());
    if (!tree || in.fail())
        throw std::runtime_error(where + ": not an OctoMap OcTree file (.ot), or truncated");
    if (std::abs(tree->getResolution() - resolution) > 1e-9)
        throw std::runtime_error(
            where + ": voxels of " + std::to_string(tree->getResolution()) +
            " m, but the grid file says octomap_resolution=" + std::to_string(resolution));
    any.release();
    tree->setProbHit(options.octomap_prob_hit);
    tree->setProbMiss(options.octomap_prob_miss);
    return std::unique_ptr<octomap::OcTree>(tree);
}

/// The length of the next string or vector operator<< wrote (its uint32 count), refused when
/// above `most` before anything is allocated: a corrupt count would otherwise ask for up to
/// 16 GB, and get it on a large machine, before the read fails.
uint32_t readCount(mrpt::serialization::CArchive& in, std::size_t most, const std::string& what) {
    uint32_t n = 0;
    in >> n;
    if (n > most)
        throw std::runtime_error("corrupt grid state: " + what + " of " + std::to_string(n) +
                                 " values (at most " + std::to_string(most) + ")");
    return n;
}

/// A string as operator<< wrote it (its uint32 length, then the bytes), read 1 MiB at a time:
/// a corrupt length runs into the end of the data after at most that much more, instead of
/// allocating up to 4 GiB first.
std::string readBytes(mrpt::serialization::CArchive& in) {
    uint32_t n = 0;
    in >> n;
    std::string bytes;
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    for (std::size_t got = 0; got < n;) {
        const std::size_t chunk = std::min<std::size_t>(kChunk, n - got);
        bytes.resize(got + chunk);
        in.ReadBuffer(bytes.data() + got, chunk);
        got += chunk;
    }
    return bytes;
}

/// A per-cell array as operator<< wrote it (count, then the values), holding exactly `cells`
/// values: the count is checked before the array grows.
template <class T>
void readCellArray(mrpt::serialization::CArchive& in, std::vector<T>& values, std::size_t cells,
                   const std::string& what) {
    uint32_t n = 0;
    in >> n;
    if (n != cells)
        throw std::runtime_error("corrupt grid state: " + what + " of " + std::to_string(n) +
                                 " values, but the options give " + std::to_string(cells) +
                                 " cells");
    values.resize(n);
    if (n > 0) in.ReadBufferFixEndianness(values.data(), n);
}
}  // namespace

void CTraversabilityMap::writeGridState(mrpt::serialization::CArchive& out) const {
    mrpt::config::CConfigFileMemory text;
    options_.saveToConfigFile(text, "traversabilityMap");
    out << text.getContent();
    auto arrays = const_cast<TraversabilityGrid&>(grid_).arrays();
    for (auto* v : arrays.floats) out << *v;
    for (auto* v : arrays.counts) out << *v;
    for (auto* v : arrays.doubles) out << *v;
    out << uint64_t(frames_inserted_);
}

void CTraversabilityMap::readGridState(mrpt::serialization::CArchive& in) {
    // The options are a few kB of ini text.
    std::string text(readCount(in, kMaxOptionsText, "options text"), '\0');
    if (!text.empty()) in.ReadBuffer(text.data(), text.size());
    TraversabilityMapOptions options;
    try {
        options.loadFromConfigFile(mrpt::config::CConfigFileMemory(text), "traversabilityMap");
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("CTraversabilityMap: corrupt options: ") + e.what());
    }
    setOptions(options);
    const std::size_t cells = grid_.cellCount();  // setOptions sized the grid
    auto arrays = grid_.arrays();
    int array = 0;
    const auto what = [&] { return "per-cell array " + std::to_string(++array); };
    for (auto* v : arrays.floats) readCellArray(in, *v, cells, what());
    for (auto* v : arrays.counts) readCellArray(in, *v, cells, what());
    for (auto* v : arrays.doubles) readCellArray(in, *v, cells, what());
    grid_.arraysLoaded();
    uint64_t frames = 0;
    in >> frames;
    frames_inserted_ = std::size_t(frames);
    obstacle_points_dirty_ = true;
}

// Version 1 stores the OctoMap as .ot bytes (every voxel's log-odds: a loaded map goes on
// fusing as if never saved); version 0 stored .bt bytes (occupied / free only), still read.
uint8_t CTraversabilityMap::serializeGetVersion() const {
    return 1;
}

void CTraversabilityMap::serializeTo(mrpt::serialization::CArchive& out) const {
    writeGridState(out);
    std::ostringstream ot;
    octree().write(ot);
    out << ot.str();
}

void CTraversabilityMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    if (version > 1) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    readGridState(in);
    std::string bytes = readBytes(in);  // the OctoMap's, as long as the map
    scratch_->log_odds.clear();         // the tree read is the master copy now
    if (version == 1) {
        octree_ = readOtTree(std::move(bytes), options_, "CTraversabilityMap");
    } else {
        std::istringstream bt_in(bytes);
        if (!octree_->readBinary(bt_in))
            throw std::runtime_error("CTraversabilityMap: corrupt OctoMap data");
    }
    obstacle_points_dirty_ = true;
}

void CTraversabilityMap::saveTo(const std::string& prefix) const {
    // Written beside and moved (travel::PartFile), so that a failed save never leaves half a
    // file under the name, nor a part file behind.
    {
        travel::PartFile grid(prefix + ".travelgrid");
        {
            GzFileOutput out(grid.part(), grid.path());
            try {
                auto archive = mrpt::serialization::archiveFrom(out);
                archive << std::string(kGridFileMagic) << kGridFileVersion;
                writeGridState(archive);
            } catch (const std::exception& e) {
                const std::string message = mrptMessage(e.what());  // GzFileOutput's names it
                // (mrptMessage writes the path's control and non-UTF-8 bytes as \xNN too)
                throw message.rfind(travel::printableText(grid.path()), 0) == 0
                    ? std::runtime_error(message)
                    : std::runtime_error(travel::cannotWriteMessage(grid.path(), message));
            }
            out.close();
        }
        grid.commit();
    }
    travel::writeThroughPartFile(prefix + ".ot", [&](std::ostream& out) { octree().write(out); });
}

void CTraversabilityMap::loadFrom(const std::string& prefix) {
    const std::string grid_path = prefix + ".travelgrid", tree_path = prefix + ".ot";
    // Into a new map first: a bad file leaves this one as it was.
    CTraversabilityMap loaded;
    {
        // CFileGZInputStream::open throws MRPT's own exception for a missing file: ask first.
        mrpt::io::CFileGZInputStream in;
        if (!std::ifstream(grid_path, std::ios::binary) || !in.open(grid_path))
            throw std::runtime_error(grid_path + ": cannot open");
        try {
            auto archive = mrpt::serialization::archiveFrom(in);
            // A wrong file: compare the magic's length before reading a string of any length.
            uint32_t length = 0;
            archive >> length;
            std::string magic(std::string(kGridFileMagic).size(), ' ');
            if (length != magic.size())
                throw std::runtime_error("not a traversability grid file (saveTo)");
            archive.ReadBuffer(magic.data(), length);
            if (magic != kGridFileMagic)
                throw std::runtime_error("not a traversability grid file (saveTo)");
            uint32_t version = 0;
            archive >> version;
            if (version != kGridFileVersion)
                throw std::runtime_error("unknown format version " + std::to_string(version));
            loaded.readGridState(archive);
        } catch (const std::exception& e) {
            throw std::runtime_error(grid_path + ": " + mrptMessage(e.what()));
        }
    }
    {
        std::ifstream file(tree_path, std::ios::binary);
        if (!file) throw std::runtime_error(tree_path + ": cannot open");
        std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        loaded.octree_ = readOtTree(std::move(bytes), loaded.options_, tree_path);
    }
    setOptions(loaded.options_);
    grid_ = std::move(loaded.grid_);
    octree_ = std::move(loaded.octree_);
    scratch_->log_odds.clear();  // the tree read is the master copy now
    frames_inserted_ = loaded.frames_inserted_;
    obstacle_points_dirty_ = true;
}

}  // namespace travel_mrpt
