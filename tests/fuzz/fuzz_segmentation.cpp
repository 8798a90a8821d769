// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes -> points -> Pipeline::process under several parameter sets, checking the invariants
// of the result (one label per point, cluster ids in 0..clusters.size(), clustered points are
// NonGround).
//
// Input layout: byte 0 = flags, byte 1 = parameter variant, then point records.
//   flags bit 0: records carry a ring (uint16)       bit 1: records carry a time (float32)
//   flags bit 2: coordinates are int16 centimetres (dense, realistic geometry) instead of float32
//   flags bit 3: a FrameInput with gravity and velocities (deskew) from the last 36 bytes
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>

#include "FuzzCommon.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace {
constexpr std::size_t kMaxPoints = 20000;
constexpr int kVariants = 5;

travel::Params variant(int v) {
    travel::Params p;  // 0: defaults (HDL-64E / KITTI)
    switch (v) {
        case 1:  // small grid, small range image, everything clusters
            p.tgf_resolution = 0.5;
            p.max_range = 30;
            p.min_range = 0.5;
            p.node_min_points = 3;
            p.min_cluster_size = 1;
            p.num_rings = 8;
            p.num_columns = 64;
            p.vertical_column_extension = 0;
            p.label_with_node_plane = true;
            break;
        case 2:  // VLP-16 preset
            p = travel::loadPreset("vlp16");
            break;
        case 3:  // uniform table, no TTMF, rings from the table only
            p.ring_source = "table";
            p.elevation_table = "uniform";
            p.num_rings = 4;
            p.num_columns = 16;
            p.ttmf = false;
            p.min_cluster_size = 1;
            p.max_cluster_size = 5;
            p.vertical_ring_span = 1024;
            p.max_slope_deg = 90;
            break;
        case 4:  // coarse, extreme tolerances
            p.tgf_resolution = 100;
            p.min_range = 0;
            p.max_range = 2000;
            p.lpr_num_points = 1;
            p.seed_search_radius = 0;
            p.eps1 = 3.2;
            p.eps2 = 0;
            p.reseed_min_weight_ratio = 1;
            p.num_rings = 1;
            p.horizontal_merge_dist = 0;
            p.vertical_merge_dist = 100;
            break;
    }
    p.validate();
    return p;
}

template <class T>
T take(const uint8_t*& p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    p += sizeof(T);
    return v;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    static std::array<std::unique_ptr<travel::Pipeline>, kVariants> pipelines;
    if (!pipelines[0])
        for (int v = 0; v < kVariants; ++v)
            pipelines[v] = std::make_unique<travel::Pipeline>(variant(v));
    if (size < 2) return 0;
    const uint8_t flags = data[0];
    const int v = data[1] % kVariants;
    const bool has_ring = flags & 1, has_time = flags & 2, cm = flags & 4, frame = flags & 8;

    travel::FrameInput input;
    const uint8_t* p = data + 2;
    const uint8_t* end = data + size;
    if (frame && end - p >= 36) {
        end -= 36;
        const uint8_t* q = end;
        auto vec = [&] {
            const float a = take<float>(q), b = take<float>(q), c = take<float>(q);
            return Eigen::Vector3d(a, b, c);
        };
        input.gravity_in_sensor = vec();
        input.linear_velocity = vec();
        input.angular_velocity = vec();
    }
    const std::size_t rec = (cm ? 6 : 16) + (has_ring ? 2 : 0) + (has_time ? 4 : 0);
    const std::size_t n = std::min<std::size_t>((end - p) / rec, kMaxPoints);

    static travel::PointCloud cloud;
    cloud.clear();
    cloud.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        float x, y, z, in = 0.f;
        if (cm) {
            x = take<int16_t>(p) * 0.01f, y = take<int16_t>(p) * 0.01f,
            z = take<int16_t>(p) * 0.01f;
        } else {
            x = take<float>(p), y = take<float>(p), z = take<float>(p), in = take<float>(p);
        }
        cloud.push_back(x, y, z, in);
        if (has_ring) cloud.ring.push_back(take<uint16_t>(p));
        if (has_time) cloud.time.push_back(take<float>(p));
    }

    static travel::Result result;
    travel::Pipeline& pipeline = *pipelines[v];
    pipeline.process(cloud, input, result);
    travel_fuzz::checkResult(cloud, pipeline.params(), result);
    // Buffers are reused across frames: a second run on the same frame gives the same labels.
    if (size % 7 == 0) {
        const auto labels = result.labels;
        const auto ids = result.cluster_id;
        pipeline.process(cloud, input, result);
        FUZZ_CHECK(result.labels == labels && result.cluster_id == ids);
    }
    return 0;
}
