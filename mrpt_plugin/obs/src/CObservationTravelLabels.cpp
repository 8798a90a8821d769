// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/CObservationTravelLabels.hpp"

#include <mrpt/opengl/CArrow.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "travel/Errors.hpp"
#include "travel/io/LabelledFrameCodec.hpp"
#include "travel_mrpt/BirdsEyeView.hpp"

using travel::PointClass;

IMPLEMENTS_SERIALIZABLE(CObservationTravelLabels, CObservation, travel_mrpt)

namespace travel_mrpt {
namespace {

// Version v stores travel::io's LabelledFrame layout v: 0 without tracking, 1 with track ids,
// velocities and moving flags (issue 19). Every older version is still read.
constexpr uint8_t kSerializationVersion = travel::io::kLabelledFrameLayout;

/// The archive as the byte stream of travel::io's LabelledFrame codec.
struct ArchiveSink final : travel::io::ByteSink {
    explicit ArchiveSink(mrpt::serialization::CArchive& a) : archive(a) {}
    void write(const void* data, std::size_t bytes) override { archive.WriteBuffer(data, bytes); }
    mrpt::serialization::CArchive& archive;
};

struct ArchiveSource final : travel::io::ByteSource {
    explicit ArchiveSource(mrpt::serialization::CArchive& a) : archive(a) {}
    std::size_t read(void* data, std::size_t bytes) override {
        try {
            return archive.ReadBuffer(data, bytes);
        } catch (const std::exception&) {
            return 0;  // MRPT throws at the end of the stream
        }
    }
    mrpt::serialization::CArchive& archive;
};

mrpt::img::TColor toTColor(uint32_t rgb, uint8_t alpha = 255) {
    return mrpt::img::TColor((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF, alpha);
}

}  // namespace

// ---------------------------------------------------------------- serialization
// Header (sensor label, timestamp, sensor pose, source class), then travel::io's LabelledFrame.

uint8_t CObservationTravelLabels::serializeGetVersion() const {
    return kSerializationVersion;
}

void CObservationTravelLabels::serializeTo(mrpt::serialization::CArchive& out) const {
    ArchiveSink sink(out);
    travel::io::writeString(sink, sensorLabel);
    out << timestamp;
    out << sensorPose.x() << sensorPose.y() << sensorPose.z() << sensorPose.yaw()
        << sensorPose.pitch() << sensorPose.roll();
    travel::io::writeString(sink, sourceClass);
    travel::io::writeLabelledFrame(sink, *this);
}

void CObservationTravelLabels::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    if (version > kSerializationVersion)
        throw std::runtime_error("CObservationTravelLabels: unknown version " +
                                 std::to_string(version) + " (this build reads versions 0.." +
                                 std::to_string(kSerializationVersion) + ")");
    ArchiveSource source(in);
    // A failed read leaves a consistent (empty) object behind.
    const auto forget = [this] { static_cast<travel::LabelledFrame&>(*this) = {}; };
    try {
        travel::io::readString(source, sensorLabel, "sensor label");
        in >> timestamp;
        double pose[6];
        travel::io::readExactly(source, pose, sizeof(pose), "sensor pose");
        for (double v : pose)
            if (!std::isfinite(v)) throw travel::InputError("non-finite sensor pose");
        sensorPose = mrpt::poses::CPose3D(pose[0], pose[1], pose[2], pose[3], pose[4], pose[5]);
        travel::io::readString(source, sourceClass, "source class");
        travel::io::readLabelledFrame(source, *this, kMaxPoints, version);
    } catch (const travel::InputError& e) {
        forget();
        throw std::runtime_error(std::string("CObservationTravelLabels: ") + e.what());
    } catch (...) {
        forget();
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

bool CObservationTravelLabels::drawsVelocityArrow(const travel::ClusterSummary& c) {
    return c.moving || (c.track_id != 0 && c.velocity.norm() >= kMinArrowSpeed);
}

void CObservationTravelLabels::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
    const std::size_t n = std::min({labels.size(), x.size(), y.size(), z.size()});
    const bool any_cluster = !clusters.empty();
    // A tracked cluster is drawn in its track's colour, the same in every frame.
    std::vector<uint32_t> colour_of_cluster(clusters.size());
    for (std::size_t k = 0; k < clusters.size(); ++k)
        colour_of_cluster[k] = travel::viz::clusterColour(clusters[k]);

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
        const bool in_cluster = c == PointClass::NonGround && id > 0 && id <= clusters.size();
        const mrpt::img::TColor t = toTColor(
            in_cluster ? colour_of_cluster[id - 1] : travel::viz::pointColour(c, id, any_cluster));
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

    auto arrows = mrpt::opengl::CSetOfObjects::Create();
    arrows->setName("travel_velocity_arrows");
    for (std::size_t k = 0; k < clusters.size(); ++k) {
        const travel::ClusterSummary& c = clusters[k];
        const mrpt::img::TColor colour = toTColor(colour_of_cluster[k]);
        auto box = mrpt::opengl::CBox::Create(
            mrpt::math::TPoint3D(c.aabb_min.x(), c.aabb_min.y(), c.aabb_min.z()),
            mrpt::math::TPoint3D(c.aabb_max.x(), c.aabb_max.y(), c.aabb_max.z()), true, 1.f);
        // MRPT 2.5.8 draws wireframe boxes with the border colour, not the object colour.
        box->setColor_u8(colour);
        box->setBoxBorderColor(colour);
        aligned->insert(box);
        if (!drawsVelocityArrow(c)) continue;
        // From the top of the box's centre to where the object will be in kArrowSeconds (the
        // velocity is in the aligned axes, like the box).
        const Eigen::Vector3f from(c.centroid.x(), c.centroid.y(), c.aabb_max.z());
        const Eigen::Vector3f to = from + c.velocity * kArrowSeconds;
        auto arrow = mrpt::opengl::CArrow::Create(from.x(), from.y(), from.z(), to.x(), to.y(),
                                                  to.z(), 0.25f, 0.05f, 0.15f);
        arrow->setName("track " + std::to_string(c.track_id));
        arrow->setColor_u8(colour);
        arrows->insert(arrow);
    }
    aligned->insert(arrows);
    o.insert(aligned);
}

}  // namespace travel_mrpt
