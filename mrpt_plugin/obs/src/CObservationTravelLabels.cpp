// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/CObservationTravelLabels.hpp"

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "travel_mrpt/BirdsEyeView.hpp"

using travel::PointClass;

IMPLEMENTS_SERIALIZABLE(CObservationTravelLabels, CObservation, travel_mrpt)

namespace travel_mrpt {
namespace {

constexpr uint8_t kSerializationVersion = 0;
constexpr uint32_t kMaxStringLength = 65536;
constexpr int32_t kMaxCellsPerSide = 32767;  // 4 * cells^2 still fits a uint32 node index
constexpr uint8_t kTraversableFlag = 1, kRefittedFlag = 2;
// Large counts are read in slices, growing the vector as bytes actually arrive: a corrupt
// count then fails at the end of the stream instead of allocating gigabytes up front.
constexpr std::size_t kReadSlice = 1u << 16;

// Every stage of travel::StageTimings, in serialization order.
using travel::StageTimings;
constexpr double StageTimings::*kTimingFields[] = {
    &StageTimings::preprocess,   &StageTimings::embedding,   &StageTimings::node_fitting,
    &StageTimings::graph_search, &StageTimings::ttmf,        &StageTimings::labelling,
    &StageTimings::ground_total, &StageTimings::range_image, &StageTimings::horizontal,
    &StageTimings::vertical,     &StageTimings::clusters,    &StageTimings::objects_total};

[[noreturn]] void corrupt(const std::string& what) {
    throw std::runtime_error("CObservationTravelLabels: corrupt or truncated stream: " + what);
}

void readExactly(mrpt::serialization::CArchive& in, void* dst, std::size_t bytes,
                 const char* what) {
    if (bytes == 0) return;
    std::size_t got = 0;
    try {
        got = in.ReadBuffer(dst, bytes);
    } catch (const std::exception&) {
        got = 0;
    }
    if (got != bytes) corrupt(std::string("stream ended while reading ") + what);
}

template <typename T>
T readPod(mrpt::serialization::CArchive& in, const char* what) {
    T value{};
    readExactly(in, &value, sizeof(T), what);
    return value;
}

template <typename T>
void writePodArray(mrpt::serialization::CArchive& out, const std::vector<T>& v) {
    if (!v.empty()) out.WriteBufferFixEndianness(v.data(), v.size());
}

template <typename T>
void readPodArray(mrpt::serialization::CArchive& in, std::vector<T>& v, std::size_t n,
                  const char* what) {
    if (n <= v.capacity()) {
        v.resize(n);
        readExactly(in, v.data(), n * sizeof(T), what);
        return;
    }
    v.clear();
    while (v.size() < n) {
        const std::size_t done = v.size(), slice = std::min(kReadSlice, n - done);
        v.resize(done + slice);
        readExactly(in, v.data() + done, slice * sizeof(T), what);
    }
}

void writeString(mrpt::serialization::CArchive& out, const std::string& s) {
    const uint32_t n = static_cast<uint32_t>(std::min<std::size_t>(s.size(), kMaxStringLength));
    out << n;
    if (n) out.WriteBuffer(s.data(), n);
}

void readString(mrpt::serialization::CArchive& in, std::string& s, const char* what) {
    const auto n = readPod<uint32_t>(in, what);
    if (n > kMaxStringLength)
        corrupt(std::string(what) + " is " + std::to_string(n) + " characters long (limit " +
                std::to_string(kMaxStringLength) + ")");
    s.resize(n);
    readExactly(in, s.data(), n, what);
}

void writeVec3(mrpt::serialization::CArchive& out, const Eigen::Vector3f& v) {
    out << v.x() << v.y() << v.z();
}

Eigen::Vector3f readVec3(mrpt::serialization::CArchive& in, const char* what) {
    float v[3];
    readExactly(in, v, sizeof(v), what);
    return {v[0], v[1], v[2]};
}

void writeCluster(mrpt::serialization::CArchive& out, const travel::ClusterSummary& c) {
    out << c.id << c.num_points << c.first_point;
    writeVec3(out, c.centroid);
    writeVec3(out, c.aabb_min);
    writeVec3(out, c.aabb_max);
    out << c.obb_yaw;
    writeVec3(out, c.obb_center);
    writeVec3(out, c.obb_extent);
    out << c.ground_z << c.height_above_ground;
}

travel::ClusterSummary readCluster(mrpt::serialization::CArchive& in) {
    travel::ClusterSummary c;
    c.id = readPod<uint32_t>(in, "cluster id");
    c.num_points = readPod<uint32_t>(in, "cluster size");
    c.first_point = readPod<uint32_t>(in, "cluster first point");
    c.centroid = readVec3(in, "cluster centroid");
    c.aabb_min = readVec3(in, "cluster box");
    c.aabb_max = readVec3(in, "cluster box");
    c.obb_yaw = readPod<float>(in, "cluster yaw");
    c.obb_center = readVec3(in, "cluster oriented box");
    c.obb_extent = readVec3(in, "cluster oriented box");
    c.ground_z = readPod<float>(in, "cluster ground height");
    c.height_above_ground = readPod<float>(in, "cluster height");
    return c;
}

void writeNode(mrpt::serialization::CArchive& out, const TerrainNodeRecord& n) {
    const uint8_t flags = (n.traversable ? kTraversableFlag : 0) | (n.refitted ? kRefittedFlag : 0);
    out << n.index << static_cast<uint8_t>(n.node_class) << flags;
    writeVec3(out, n.normal);
    out << n.d;
    writeVec3(out, n.corner_z);
    writeVec3(out, n.mean);
}

TerrainNodeRecord readNode(mrpt::serialization::CArchive& in) {
    TerrainNodeRecord n;
    n.index = readPod<uint32_t>(in, "node index");
    const auto node_class = readPod<uint8_t>(in, "node class");
    if (node_class < static_cast<uint8_t>(travel::NodeClass::Unknown) ||
        node_class > static_cast<uint8_t>(travel::NodeClass::Obstacle))
        corrupt("node class " + std::to_string(node_class) + " (expected 1..3)");
    n.node_class = static_cast<travel::NodeClass>(node_class);
    const auto flags = readPod<uint8_t>(in, "node flags");
    if (flags & ~(kTraversableFlag | kRefittedFlag)) corrupt("node flags " + std::to_string(flags));
    n.traversable = flags & kTraversableFlag;
    n.refitted = flags & kRefittedFlag;
    n.normal = readVec3(in, "node normal");
    n.d = readPod<float>(in, "node plane");
    n.corner_z = readVec3(in, "node corners");
    n.mean = readVec3(in, "node mean");
    return n;
}

mrpt::img::TColor toTColor(uint32_t rgb, uint8_t alpha = 255) {
    return mrpt::img::TColor((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF, alpha);
}

}  // namespace

// ---------------------------------------------------------------- serialization

uint8_t CObservationTravelLabels::serializeGetVersion() const {
    return kSerializationVersion;
}

void CObservationTravelLabels::serializeTo(mrpt::serialization::CArchive& out) const {
    const std::size_t n = labels.size();
    if (x.size() != n || y.size() != n || z.size() != n || intensity.size() != n ||
        clusterId.size() != n)
        throw std::logic_error(
            "CObservationTravelLabels: x, y, z, intensity, labels and clusterId must have the "
            "same size before serialization");
    writeString(out, sensorLabel);
    out << timestamp;
    out << sensorPose.x() << sensorPose.y() << sensorPose.z() << sensorPose.yaw()
        << sensorPose.pitch() << sensorPose.roll();
    writeString(out, sourceClass);

    out << static_cast<uint32_t>(n);
    writePodArray(out, x);
    writePodArray(out, y);
    writePodArray(out, z);
    writePodArray(out, intensity);
    writePodArray(out, labels);
    writePodArray(out, clusterId);

    out << static_cast<uint32_t>(clusters.size());
    for (const auto& c : clusters) writeCluster(out, c);

    out << terrain.resolution << terrain.cells_per_side << terrain.origin_xy
        << static_cast<uint32_t>(terrain.nodes.size());
    for (const auto& node : terrain.nodes) writeNode(out, node);

    for (int i = 0; i < 9; ++i) out << alignedRotation.data()[i];
    for (const auto field : kTimingFields) out << timings.*field;
}

void CObservationTravelLabels::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    if (version != kSerializationVersion)
        corrupt("unknown version " + std::to_string(version) + " (this build reads version " +
                std::to_string(kSerializationVersion) + ")");
    try {
        readString(in, sensorLabel, "sensor label");
        in >> timestamp;
        double pose[6];
        readExactly(in, pose, sizeof(pose), "sensor pose");
        for (double v : pose)
            if (!std::isfinite(v)) corrupt("non-finite sensor pose");
        sensorPose = mrpt::poses::CPose3D(pose[0], pose[1], pose[2], pose[3], pose[4], pose[5]);
        readString(in, sourceClass, "source class");

        const auto n = readPod<uint32_t>(in, "point count");
        if (n > kMaxPoints)
            corrupt("point count " + std::to_string(n) + " above the limit of " +
                    std::to_string(kMaxPoints));
        readPodArray(in, x, n, "x");
        readPodArray(in, y, n, "y");
        readPodArray(in, z, n, "z");
        readPodArray(in, intensity, n, "intensity");
        readPodArray(in, labels, n, "labels");
        readPodArray(in, clusterId, n, "cluster ids");
        for (std::size_t i = 0; i < n; ++i)
            if (labels[i] > static_cast<uint8_t>(PointClass::Outlier))
                corrupt("label " + std::to_string(labels[i]) + " of point " + std::to_string(i) +
                        " (expected 0..3)");

        // Every cluster holds at least one point.
        const auto num_clusters = readPod<uint32_t>(in, "cluster count");
        if (num_clusters > n)
            corrupt(std::to_string(num_clusters) + " clusters for " + std::to_string(n) +
                    " points");
        clusters.clear();
        clusters.reserve(std::min<std::size_t>(num_clusters, kReadSlice));
        for (uint32_t k = 0; k < num_clusters; ++k) {
            clusters.push_back(readCluster(in));
            if (clusters.back().id != k + 1)
                corrupt("cluster " + std::to_string(k) + " has id " +
                        std::to_string(clusters.back().id) + " (expected " + std::to_string(k + 1) +
                        ")");
        }
        for (std::size_t i = 0; i < n; ++i)
            if (clusterId[i] > num_clusters)
                corrupt("cluster id " + std::to_string(clusterId[i]) + " of point " +
                        std::to_string(i) + " (only " + std::to_string(num_clusters) +
                        " clusters)");

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
                corrupt("node index " + std::to_string(index) +
                        " (expected increasing indices below " + std::to_string(max_nodes) + ")");
        }

        readExactly(in, alignedRotation.data(), 9 * sizeof(float), "aligned rotation");
        for (const auto field : kTimingFields) timings.*field = readPod<double>(in, "timings");
    } catch (...) {
        // Leave a consistent (empty) object behind.
        for (auto* v : {&x, &y, &z, &intensity}) v->clear();
        labels.clear();
        clusterId.clear();
        clusters.clear();
        terrain = TerrainSummary{};
        throw;
    }
}

// ---------------------------------------------------------------- text

void CObservationTravelLabels::getDescriptionAsText(std::ostream& o) const {
    CObservation::getDescriptionAsText(o);
    o << "TRAVEL labels of a " << (sourceClass.empty() ? "(unknown)" : sourceClass) << "\n";
    describe(o);
}

// ---------------------------------------------------------------- 3-D view

void CObservationTravelLabels::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
    const std::size_t n = std::min({labels.size(), x.size(), y.size(), z.size()});
    const bool any_cluster = !clusters.empty();

    auto points = mrpt::opengl::CPointCloudColoured::Create();
    points->setName("travel_points");
    points->setPointSize(3.f);
    points->setPose(sensorPose);
    points->reserve(n - std::min(n, count(PointClass::Invalid)));
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<PointClass>(labels[i]);
        if (c == PointClass::Invalid || labels[i] > static_cast<uint8_t>(PointClass::Outlier))
            continue;  // not drawn
        const uint32_t id = i < clusterId.size() ? clusterId[i] : 0;
        const mrpt::img::TColor t = toTColor(travel::viz::pointColour(c, id, any_cluster));
        points->push_back(x[i], y[i], z[i], t.R / 255.f, t.G / 255.f, t.B / 255.f);
    }
    o.insert(points);

    // Terrain and boxes live in the aligned frame: place that frame at sensorPose rotated by
    // aligned -> sensor (the transpose of alignedRotation).
    const Eigen::Matrix3d to_sensor = alignedRotation.transpose().cast<double>();
    mrpt::math::CMatrixDouble33 rot;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) rot(r, c) = to_sensor(r, c);
    const mrpt::poses::CPose3D aligned_pose =
        sensorPose +
        mrpt::poses::CPose3D::FromRotationAndTranslation(rot, mrpt::math::CVectorFixedDouble<3>());

    auto aligned = mrpt::opengl::CSetOfObjects::Create();
    aligned->setName("travel_aligned_frame");
    aligned->setPose(aligned_pose);

    auto nodes = mrpt::opengl::CSetOfTriangles::Create();
    nodes->setName("travel_traversable_nodes");
    nodes->enableLight(false);
    const mrpt::img::TColor node_colour(230, 200, 90, 110);
    std::array<Eigen::Vector3f, 3> corners;
    for (const TerrainNodeRecord& node : terrain.nodes) {
        if (!node.traversable || !terrain.triangle3D(node, corners)) continue;
        mrpt::opengl::TTriangle tri;
        for (int k = 0; k < 3; ++k)
            tri.vertex(k) = {corners[k].x(), corners[k].y(), corners[k].z()};
        tri.computeNormals();
        tri.setColor(node_colour);
        nodes->insertTriangle(tri);
    }
    aligned->insert(nodes);

    for (const travel::ClusterSummary& c : clusters) {
        auto box = mrpt::opengl::CBox::Create(
            mrpt::math::TPoint3D(c.aabb_min.x(), c.aabb_min.y(), c.aabb_min.z()),
            mrpt::math::TPoint3D(c.aabb_max.x(), c.aabb_max.y(), c.aabb_max.z()), true, 1.f);
        // MRPT 2.5.8 draws wireframe boxes with the border colour, not the object colour.
        box->setColor_u8(toTColor(clusterColour(c.id)));
        box->setBoxBorderColor(toTColor(clusterColour(c.id)));
        aligned->insert(box);
    }
    o.insert(aligned);
}

}  // namespace travel_mrpt
