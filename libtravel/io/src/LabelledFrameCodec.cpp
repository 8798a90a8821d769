// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/LabelledFrameCodec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>

#include "travel/Errors.hpp"
#include "travel/io/BinaryFile.hpp"

namespace travel::io {
namespace {

constexpr int32_t kMaxCellsPerSide = 32767;  // 4 * cells^2 still fits a uint32 node index
constexpr uint8_t kTraversableFlag = 1, kRefittedFlag = 2;
// Large counts are read in slices, growing the vector as bytes actually arrive: a corrupt
// count then fails at the end of the stream instead of allocating gigabytes up front.
constexpr std::size_t kReadSlice = 1u << 16;

// Every stage of StageTimings, in stream order.
constexpr double StageTimings::*kTimingFields[] = {
    &StageTimings::preprocess,   &StageTimings::embedding,   &StageTimings::node_fitting,
    &StageTimings::graph_search, &StageTimings::ttmf,        &StageTimings::labelling,
    &StageTimings::ground_total, &StageTimings::range_image, &StageTimings::horizontal,
    &StageTimings::vertical,     &StageTimings::clusters,    &StageTimings::objects_total};

[[noreturn]] void corrupt(const std::string& what) {
    throw InputError("corrupt or truncated stream: " + what);
}

template <typename T>
void writePod(ByteSink& out, T value) {
    unsigned char bytes[sizeof(T)];
    le::store(value, bytes);
    out.write(bytes, sizeof(T));
}

template <typename T>
T readPod(ByteSource& in, const char* what) {
    unsigned char bytes[sizeof(T)];
    readExactly(in, bytes, sizeof(T), what);
    return le::load<T>(bytes);
}

/// Arrays of little-endian values: the host's bytes as they are, swapped on a big-endian host.
template <typename T>
void fixEndianness(T* values, std::size_t n) {
    if constexpr (le::kHostIsBigEndian && sizeof(T) > 1)
        for (std::size_t i = 0; i < n; ++i)
            values[i] = le::load<T>(reinterpret_cast<const unsigned char*>(&values[i]));
}

template <typename T>
void writePodArray(ByteSink& out, const std::vector<T>& v) {
    if constexpr (le::kHostIsBigEndian && sizeof(T) > 1) {
        for (const T& value : v) writePod(out, value);
    } else if (!v.empty()) {
        out.write(v.data(), v.size() * sizeof(T));
    }
}

template <typename T>
void readPodArray(ByteSource& in, std::vector<T>& v, std::size_t n, const char* what) {
    if (n <= v.capacity()) {
        v.resize(n);
        readExactly(in, v.data(), n * sizeof(T), what);
    } else {
        v.clear();
        while (v.size() < n) {
            const std::size_t done = v.size(), slice = std::min(kReadSlice, n - done);
            v.resize(done + slice);
            readExactly(in, v.data() + done, slice * sizeof(T), what);
        }
    }
    fixEndianness(v.data(), n);
}

void writeVec3(ByteSink& out, const Eigen::Vector3f& v) {
    for (int k = 0; k < 3; ++k) writePod(out, v[k]);
}

Eigen::Vector3f readVec3(ByteSource& in, const char* what) {
    Eigen::Vector3f v;
    for (int k = 0; k < 3; ++k) v[k] = readPod<float>(in, what);
    return v;
}

// The two directions of one wire layout: each record's fields are listed once (clusterFields,
// nodePlaneFields) and visited by a FieldIo, which writes the fields of a const record to `out`
// and reads those of a mutable one from `in`, so writing and reading cannot drift apart.
struct FieldIo {
    ByteSink* out = nullptr;
    ByteSource* in = nullptr;
    template <typename T>
    void operator()(T& value, const char* what) {
        using Value = std::remove_const_t<T>;
        constexpr bool kVector = std::is_same_v<Value, Eigen::Vector3f>;
        if constexpr (std::is_const_v<T>) {
            if constexpr (kVector)
                writeVec3(*out, value);
            else if constexpr (std::is_same_v<Value, bool>)
                writePod(*out, uint8_t(value ? 1 : 0));
            else
                writePod(*out, value);
        } else {
            if constexpr (kVector) {
                value = readVec3(*in, what);
            } else if constexpr (std::is_same_v<Value, bool>) {
                const auto byte = readPod<uint8_t>(*in, what);
                if (byte > 1)
                    corrupt(std::string(what) + " " + std::to_string(byte) + " (expected 0 or 1)");
                value = byte == 1;
            } else {
                value = readPod<Value>(*in, what);
            }
        }
    }
};

template <class Cluster>  // const ClusterSummary: written, ClusterSummary: read
void clusterFields(FieldIo io, Cluster& c) {
    io(c.id, "cluster id");
    io(c.num_points, "cluster size");
    io(c.first_point, "cluster first point");
    io(c.centroid, "cluster centroid");
    io(c.aabb_min, "cluster box");
    io(c.aabb_max, "cluster box");
    io(c.obb_yaw, "cluster yaw");
    io(c.obb_center, "cluster oriented box");
    io(c.obb_extent, "cluster oriented box");
    io(c.ground_z, "cluster ground height");
    io(c.height_above_ground, "cluster height");
}

// Layout 1 onwards: what travel::Tracker adds to a cluster.
template <class Cluster>
void clusterTrackFields(FieldIo io, Cluster& c) {
    io(c.track_id, "cluster track id");
    io(c.velocity, "cluster velocity");
    io(c.velocity_sigma, "cluster velocity sigma");
    io(c.moving, "cluster moving flag");
}

// A node: index, class and flags (checked on reading), then these plane fields.
template <class Node>  // const TerrainNodeRecord: written, TerrainNodeRecord: read
void nodePlaneFields(FieldIo io, Node& n) {
    io(n.normal, "node normal");
    io(n.d, "node plane");
    io(n.corner_z, "node corners");
    io(n.mean, "node mean");
}

void writeNode(ByteSink& out, const TerrainNodeRecord& n) {
    writePod(out, n.index);
    writePod(out, static_cast<uint8_t>(n.node_class));
    writePod(out,
             uint8_t((n.traversable ? kTraversableFlag : 0) | (n.refitted ? kRefittedFlag : 0)));
    nodePlaneFields(FieldIo{&out, nullptr}, n);
}

TerrainNodeRecord readNode(ByteSource& in) {
    TerrainNodeRecord n;
    n.index = readPod<uint32_t>(in, "node index");
    const auto node_class = readPod<uint8_t>(in, "node class");
    if (node_class < static_cast<uint8_t>(NodeClass::Unknown) ||
        node_class > static_cast<uint8_t>(NodeClass::Obstacle))
        corrupt("node class " + std::to_string(node_class) + " (expected 1..3)");
    n.node_class = static_cast<NodeClass>(node_class);
    const auto flags = readPod<uint8_t>(in, "node flags");
    if (flags & ~(kTraversableFlag | kRefittedFlag)) corrupt("node flags " + std::to_string(flags));
    n.traversable = flags & kTraversableFlag;
    n.refitted = flags & kRefittedFlag;
    nodePlaneFields(FieldIo{nullptr, &in}, n);
    return n;
}

void readFrame(ByteSource& in, LabelledFrame& f, std::size_t max_points, uint8_t layout) {
    if (layout > kLabelledFrameLayout)
        corrupt("layout " + std::to_string(layout) + " (this build reads 0.." +
                std::to_string(kLabelledFrameLayout) + ")");
    const auto n = readPod<uint32_t>(in, "point count");
    if (n > max_points)
        corrupt("point count " + std::to_string(n) + " above the limit of " +
                std::to_string(max_points));
    readPodArray(in, f.x, n, "x");
    readPodArray(in, f.y, n, "y");
    readPodArray(in, f.z, n, "z");
    readPodArray(in, f.intensity, n, "intensity");
    readPodArray(in, f.labels, n, "labels");
    readPodArray(in, f.clusterId, n, "cluster ids");
    for (std::size_t i = 0; i < n; ++i)
        if (f.labels[i] > static_cast<uint8_t>(PointClass::Outlier))
            corrupt("label " + std::to_string(f.labels[i]) + " of point " + std::to_string(i) +
                    " (expected 0..3)");

    // Every cluster holds at least one point.
    const auto num_clusters = readPod<uint32_t>(in, "cluster count");
    if (num_clusters > n)
        corrupt(std::to_string(num_clusters) + " clusters for " + std::to_string(n) + " points");
    f.clusters.clear();
    f.clusters.reserve(std::min<std::size_t>(num_clusters, kReadSlice));
    for (uint32_t k = 0; k < num_clusters; ++k) {
        ClusterSummary& c = f.clusters.emplace_back();
        clusterFields(FieldIo{nullptr, &in}, c);
        if (layout >= 1) clusterTrackFields(FieldIo{nullptr, &in}, c);  // else: untracked
        if (f.clusters.back().id != k + 1)
            corrupt("cluster " + std::to_string(k) + " has id " +
                    std::to_string(f.clusters.back().id) + " (expected " + std::to_string(k + 1) +
                    ")");
    }
    for (std::size_t i = 0; i < n; ++i)
        if (f.clusterId[i] > num_clusters)
            corrupt("cluster id " + std::to_string(f.clusterId[i]) + " of point " +
                    std::to_string(i) + " (only " + std::to_string(num_clusters) + " clusters)");

    TerrainSummary& terrain = f.terrain;
    terrain.resolution = readPod<float>(in, "terrain resolution");
    terrain.cells_per_side = readPod<int32_t>(in, "terrain size");
    terrain.origin_xy = readPod<float>(in, "terrain origin");
    if (terrain.cells_per_side < 0 || terrain.cells_per_side > kMaxCellsPerSide)
        corrupt("terrain of " + std::to_string(terrain.cells_per_side) +
                " cells per side (expected 0.." + std::to_string(kMaxCellsPerSide) + ")");
    if (terrain.cells_per_side > 0 &&
        !(std::isfinite(terrain.resolution) && terrain.resolution > 0.f &&
          std::isfinite(terrain.origin_xy)))
        corrupt("terrain resolution or origin not finite and positive");
    const uint64_t max_nodes = 4ull * static_cast<uint64_t>(terrain.cells_per_side) *
                               static_cast<uint64_t>(terrain.cells_per_side);
    const auto num_nodes = readPod<uint32_t>(in, "node count");
    if (num_nodes > max_nodes)
        corrupt(std::to_string(num_nodes) + " nodes in a grid of " + std::to_string(max_nodes));
    terrain.nodes.clear();
    terrain.nodes.reserve(std::min<std::size_t>(num_nodes, kReadSlice));
    for (uint32_t k = 0; k < num_nodes; ++k) {
        terrain.nodes.push_back(readNode(in));
        const uint32_t index = terrain.nodes.back().index;
        if (index >= max_nodes || (k > 0 && index <= terrain.nodes[k - 1].index))
            corrupt("node index " + std::to_string(index) + " (expected increasing indices below " +
                    std::to_string(max_nodes) + ")");
    }

    for (int i = 0; i < 9; ++i)
        f.alignedRotation.data()[i] = readPod<float>(in, "aligned rotation");
    for (const auto field : kTimingFields) f.timings.*field = readPod<double>(in, "timings");
}

}  // namespace

void writeString(ByteSink& out, const std::string& s) {
    const auto n = static_cast<uint32_t>(std::min(s.size(), kMaxStringLength));
    writePod(out, n);
    if (n) out.write(s.data(), n);
}

void readExactly(ByteSource& in, void* data, std::size_t bytes, const char* what) {
    if (bytes > 0 && in.read(data, bytes) != bytes)
        corrupt(std::string("stream ended while reading ") + what);
}

void readString(ByteSource& in, std::string& s, const char* what) {
    const auto n = readPod<uint32_t>(in, what);
    if (n > kMaxStringLength)
        corrupt(std::string(what) + " is " + std::to_string(n) + " characters long (limit " +
                std::to_string(kMaxStringLength) + ")");
    s.resize(n);
    readExactly(in, s.data(), n, what);
}

void writeLabelledFrame(ByteSink& out, const LabelledFrame& f) {
    const std::size_t n = f.labels.size();
    if (f.x.size() != n || f.y.size() != n || f.z.size() != n || f.intensity.size() != n ||
        f.clusterId.size() != n)
        throw std::logic_error(
            "LabelledFrame: x, y, z, intensity, labels and clusterId must have the same size "
            "before serialization");
    writePod(out, static_cast<uint32_t>(n));
    writePodArray(out, f.x);
    writePodArray(out, f.y);
    writePodArray(out, f.z);
    writePodArray(out, f.intensity);
    writePodArray(out, f.labels);
    writePodArray(out, f.clusterId);

    writePod(out, static_cast<uint32_t>(f.clusters.size()));
    for (const ClusterSummary& c : f.clusters) {
        clusterFields(FieldIo{&out, nullptr}, c);
        clusterTrackFields(FieldIo{&out, nullptr}, c);
    }

    writePod(out, f.terrain.resolution);
    writePod(out, f.terrain.cells_per_side);
    writePod(out, f.terrain.origin_xy);
    writePod(out, static_cast<uint32_t>(f.terrain.nodes.size()));
    for (const TerrainNodeRecord& node : f.terrain.nodes) writeNode(out, node);

    for (int i = 0; i < 9; ++i) writePod(out, f.alignedRotation.data()[i]);
    for (const auto field : kTimingFields) writePod(out, f.timings.*field);
}

void readLabelledFrame(ByteSource& in, LabelledFrame& frame, std::size_t max_points,
                       uint8_t layout) {
    try {
        readFrame(in, frame, max_points, layout);
    } catch (...) {
        // Leave a consistent (empty) frame behind.
        for (auto* v : {&frame.x, &frame.y, &frame.z, &frame.intensity}) v->clear();
        frame.labels.clear();
        frame.clusterId.clear();
        frame.clusters.clear();
        frame.terrain = TerrainSummary{};
        throw;
    }
}

}  // namespace travel::io
