// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes -> file -> readScan as KITTI and as nuScenes -> (if it parses) Pipeline on the first 20k
// points. fuzz_scan_reader covers format detection, PCD and PLY.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "FuzzCommon.hpp"
#include "travel/Errors.hpp"
#include "travel/eval/KittiIO.hpp"

namespace {
constexpr std::size_t kMaxPoints = 20000;

void runPipeline(travel::PointCloud& cloud) {
    static travel::Params params;  // defaults: HDL-64E
    static travel::Pipeline pipeline(params);
    static travel::Result result;
    if (cloud.size() > kMaxPoints) cloud.resize(kMaxPoints);
    pipeline.process(cloud, {}, result);
    travel_fuzz::checkResult(cloud, params, result);
}
// True when some record of `record_size` bytes has finite x, y, z (little-endian host).
bool anyFinitePoint(const uint8_t* data, std::size_t size, std::size_t record_size) {
    for (std::size_t i = 0; i + record_size <= size; i += record_size) {
        float xyz[3];
        std::memcpy(xyz, data + i, sizeof(xyz));
        if (std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])) return true;
    }
    return false;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string& path = travel_fuzz::tempPath(".bin");
    travel_fuzz::writeFile(path, data, size);
    static travel::PointCloud cloud;
    try {
        travel::readScan(path, cloud, travel::ScanFormat::KittiBin);
        FUZZ_CHECK(cloud.size() * 16 == size);
        FUZZ_CHECK(cloud.y.size() == cloud.size() && cloud.intensity.size() == cloud.size());
        runPipeline(cloud);
    } catch (const travel::InputError&) {
        // Rejected: a size that is not whole records, an empty file, or no finite point.
        FUZZ_CHECK(size % 16 != 0 || size == 0 || !anyFinitePoint(data, size, 16));
    }
    try {
        travel::readScan(path, cloud, travel::ScanFormat::NuScenesBin);
        FUZZ_CHECK(cloud.size() * 20 == size);
        FUZZ_CHECK(cloud.ring.size() == cloud.size());
        runPipeline(cloud);
    } catch (const travel::InputError&) {
    }
    return 0;
}
