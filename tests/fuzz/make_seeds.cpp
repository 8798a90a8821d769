// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// Regenerates the seed corpus (run once, the files are committed):
//   cmake -S tests/fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DTRAVEL_FUZZ_SEEDGEN=ON
//   cmake --build build-fuzz --target make_seeds && build-fuzz/make_seeds tests/fuzz/corpus
// Every file is a few KB: small synthetic scans (travel::sim), never a real dataset file.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "travel/eval/KittiIO.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

#ifdef TRAVEL_FUZZ_MRPT
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include "travel/Pipeline.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#endif

namespace {
using travel::PointCloud;

PointCloud subsample(const PointCloud& in, std::size_t n, bool keep_zero = false) {
    PointCloud out;
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < in.size(); ++i)
        if (keep_zero || in.x[i] != 0.f || in.y[i] != 0.f || in.z[i] != 0.f) idx.push_back(i);
    const std::size_t step = std::max<std::size_t>(1, idx.size() / n);
    for (std::size_t k = 0; k < idx.size() && out.size() < n; k += step) {
        const std::size_t i = idx[k];
        out.push_back(in.x[i], in.y[i], in.z[i], in.intensity.empty() ? 0.f : in.intensity[i]);
        out.ring.push_back(in.hasRing() ? in.ring[i] : 0);
        out.time.push_back(in.hasTime() ? in.time[i] : 0.f);
    }
    return out;
}

template <class T>
void put(std::string& s, T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
    std::cout << path << " " << bytes.size() << " bytes\n";
}

/// fuzz_scan_reader input: a selector byte (file suffix | format << 2, see fuzz_scan_reader.cpp)
/// and the bytes a library writer produced in `scratch`.
void writeScanSeed(const std::string& path, unsigned selector, const std::string& scratch) {
    std::ifstream in(scratch, std::ios::binary);
    writeBytes(path, std::string(1, char(selector)) +
                         std::string((std::istreambuf_iterator<char>(in)), {}));
}

/// fuzz_segmentation record layout (see fuzz_segmentation.cpp).
std::string segInput(const PointCloud& c, uint8_t flags, uint8_t variant) {
    std::string s;
    put<uint8_t>(s, flags), put<uint8_t>(s, variant);
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (flags & 4) {
            put<int16_t>(s, int16_t(c.x[i] * 100)), put<int16_t>(s, int16_t(c.y[i] * 100)),
                put<int16_t>(s, int16_t(c.z[i] * 100));
        } else {
            put(s, c.x[i]), put(s, c.y[i]), put(s, c.z[i]), put(s, c.intensity[i]);
        }
        if (flags & 1) put<uint16_t>(s, c.ring[i]);
        if (flags & 2) put<float>(s, c.time[i]);
    }
    if (flags & 8)
        for (float f : {0.f, 0.05f, -1.f, 5.f, 0.f, 0.f, 0.f, 0.f, 0.3f}) put(s, f);
    return s;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_seeds CORPUS_DIR\n";
        return 2;
    }
    const std::string dir = argv[1];
    namespace sim = travel::sim;
    const auto urban = sim::urbanObjects();
    const auto scan64 = sim::scan(urban, sim::LidarModel::hdl64(256),
                                  sim::sensorPoseAt(urban, 0, 0, 1.73, 0, 0, 0));
    const auto flat = sim::flatGround();
    const auto scan16 =
        sim::scan(flat, sim::LidarModel::vlp16(180), sim::sensorPoseAt(flat, 0, 0, 1.0, 0, 0, 0));

    // fuzz_kitti_bin: KITTI .bin (16 B/point) and XYZIR (20 B/point), and an empty file.
    const PointCloud c50 = subsample(scan64.cloud, 50), c200 = subsample(scan64.cloud, 200);
    travel::writeKittiBin(dir + "/fuzz_kitti_bin/hdl64_50.bin", c50);
    travel::writeKittiBin(dir + "/fuzz_kitti_bin/hdl64_200.bin", c200);
    {
        std::string s;
        for (std::size_t i = 0; i < c50.size(); ++i)
            put(s, c50.x[i]), put(s, c50.y[i]), put(s, c50.z[i]), put(s, c50.intensity[i]),
                put(s, float(c50.ring[i]));
        writeBytes(dir + "/fuzz_kitti_bin/xyzir_50.bin", s);
        writeBytes(dir + "/fuzz_kitti_bin/empty.bin", "");
    }
    // fuzz_scan_reader: every format and encoding, auto-detected or explicit.
    {
        const std::string d = dir + "/fuzz_scan_reader/", tmp = d + "scratch.tmp";
        PointCloud plain = c50;
        plain.ring.clear(), plain.time.clear();
        PointCloud timed = c50;
        timed.time.assign(c50.size(), 0.f);
        for (std::size_t i = 0; i < c50.size(); ++i) timed.time[i] = 0.002f * float(i);
        travel::writeKittiBin(tmp, plain);
        writeScanSeed(d + "kitti_auto.bin", 0, tmp);
        writeScanSeed(d + "kitti_explicit.bin", 1 << 2, tmp);
        travel::writePcd(tmp, plain, travel::PcdEncoding::Ascii);
        writeScanSeed(d + "ascii.pcd", 1, tmp);
        travel::writePcd(tmp, timed, travel::PcdEncoding::Binary);
        writeScanSeed(d + "binary_ring_time.pcd", 1, tmp);
        travel::writePcd(tmp, timed, travel::PcdEncoding::BinaryCompressed);
        writeScanSeed(d + "compressed_ring_time.pcd", 1, tmp);
        travel::writePcd(tmp, plain, travel::PcdEncoding::BinaryCompressed);
        writeScanSeed(d + "compressed.pcd", 1 | 3 << 2, tmp);
        travel::writePly(tmp, timed, travel::PlyEncoding::Ascii);
        writeScanSeed(d + "ascii_ring_time.ply", 2, tmp);
        travel::writePly(tmp, plain, travel::PlyEncoding::BinaryLittleEndian);
        writeScanSeed(d + "binary.ply", 2 | 4 << 2, tmp);
        std::remove(tmp.c_str());
        std::string s;  // nuScenes records: by name (.pcd.bin) and by values (.bin)
        for (std::size_t i = 0; i < 12; ++i)
            put(s, c50.x[i]), put(s, c50.y[i]), put(s, c50.z[i]), put(s, c50.intensity[i]),
                put(s, float(c50.ring[i]));
        writeBytes(d + "nuscenes_name.bin", std::string(1, char(3)) + s);
        writeBytes(d + "nuscenes_values.bin", std::string(1, char(0)) + s.substr(0, 7 * 20));
        writeBytes(d + "faces.ply",
                   std::string(1, char(2)) +
                       "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int "
                       "vertex_indices\nelement vertex 2\nproperty double x\nproperty float y\n"
                       "property short z\nproperty uchar intensity\nend_header\n3 0 1 1\n1 2 3 "
                       "4\n-1 0.5 2 255\n");
    }
    // fuzz_label_file: travel-kitti style labels of 50 points (first byte picks the mode).
    {
        std::vector<uint32_t> labels;
        for (std::size_t i = 0; i < 50; ++i)
            labels.push_back(travel::encodeLabel(travel::PointClass(i % 4), i % 3 ? 0 : 70000 + i));
        travel::writeLabelFile(dir + "/fuzz_label_file/mixed_50.label", labels);
        labels.assign(10, 40);  // SemanticKITTI "road"
        labels[0] = 0x00010009;
        travel::writeLabelFile(dir + "/fuzz_label_file/road_10.label", labels);
    }
    // fuzz_segmentation: int16 cm + ring, float + ring + time, frame input, each variant.
    const PointCloud c300 = subsample(scan64.cloud, 300), v300 = subsample(scan16.cloud, 300);
    writeBytes(dir + "/fuzz_segmentation/hdl64_cm_ring.bin", segInput(c300, 4 | 1, 0));
    writeBytes(dir + "/fuzz_segmentation/hdl64_cm_smallgrid.bin", segInput(c300, 4, 1));
    writeBytes(dir + "/fuzz_segmentation/vlp16_float_ring_time.bin",
               segInput(subsample(scan16.cloud, 150), 1 | 2, 2));
    writeBytes(dir + "/fuzz_segmentation/vlp16_cm_deskew.bin", segInput(v300, 4 | 2 | 8, 2));
    writeBytes(dir + "/fuzz_segmentation/hdl64_cm_table.bin", segInput(c300, 4, 3));
    writeBytes(dir + "/fuzz_segmentation/hdl64_cm_coarse.bin", segInput(c300, 4, 4));

#ifdef TRAVEL_FUZZ_MRPT
    // fuzz_rawlog: one CObservationPointCloud (XYZI, 100 points), plain and gzip, and the same
    // observation inside a CSensoryFrame.
    {
        const PointCloud c100 = subsample(scan64.cloud, 100);
        auto map = mrpt::maps::CPointsMapXYZI::Create();
        for (std::size_t i = 0; i < c100.size(); ++i) {
            map->insertPoint(c100.x[i], c100.y[i], c100.z[i]);
            map->setPointIntensity(i, 0.5f);
        }
        auto obs = mrpt::obs::CObservationPointCloud::Create();
        obs->pointcloud = map;
        obs->sensorLabel = "lidar";
        obs->sensorPose = mrpt::poses::CPose3D(0, 0, 1.73, 0, 0, 0);
        {
            mrpt::io::CFileOutputStream f(dir + "/fuzz_rawlog/pointcloud_100.rawlog");
            mrpt::serialization::archiveFrom(f) << *obs;
        }
        {
            mrpt::io::CFileGZOutputStream f(dir + "/fuzz_rawlog/pointcloud_100.rawlog.gz");
            mrpt::serialization::archiveFrom(f) << *obs;
        }
        {
            mrpt::obs::CSensoryFrame sf;
            sf.insert(obs);
            mrpt::io::CFileOutputStream f(dir + "/fuzz_rawlog/sensoryframe_100.rawlog");
            mrpt::serialization::archiveFrom(f) << sf;
        }
    }
    // CObservationTravelLabels of 300 points in the current version (with tracking: track ids,
    // velocities, moving flags); travel_labels_small.rawlog is a version-0 object (no tracking).
    {
        travel::Params params;
        params.sensor_height = 1.73;
        travel::Pipeline pipeline(params);
        travel::Result result;
        pipeline.process(c300, {}, result);
        auto labels = travel_mrpt::CObservationTravelLabels::Create();
        labels->assign(c300, result, pipeline.aligned().rotation);
        labels->sensorLabel = "lidar_travel";
        labels->sourceClass = "mrpt::obs::CObservationPointCloud";
        for (std::size_t k = 0; k < labels->clusters.size(); ++k) {
            travel::ClusterSummary& c = labels->clusters[k];
            c.track_id = uint32_t(100 + k);
            c.moving = k % 2 == 1;
            c.velocity = {c.moving ? 3.f : 0.f, 0.5f, 0.f};
            c.velocity_sigma = {0.2f, 0.2f, 0.1f};
        }
        mrpt::io::CFileOutputStream f(dir + "/fuzz_rawlog/travel_labels_tracked.rawlog");
        mrpt::serialization::archiveFrom(f) << *labels;
    }
    // A CObservationVelodyneScan cut down to 2 packets, if MRPT's sample dataset is installed
    // (TRAVEL_VLP16_RAWLOG=/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog); the seed is ~3 KB,
    // not the dataset.
    if (const char* vlp = std::getenv("TRAVEL_VLP16_RAWLOG")) {
        mrpt::io::CFileGZInputStream in(vlp);
        auto a = mrpt::serialization::archiveFrom(in);
        for (int k = 0; k < 50; ++k) {
            auto obj = a.ReadObject();
            auto v = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(obj);
            if (!v) continue;
            v->scan_packets.resize(std::min<std::size_t>(2, v->scan_packets.size()));
            v->point_cloud.clear_deep();
            mrpt::io::CFileOutputStream f(dir + "/fuzz_rawlog/velodyne_2packets.rawlog");
            mrpt::serialization::archiveFrom(f) << *v;
            break;
        }
    }
#endif
    return 0;
}
