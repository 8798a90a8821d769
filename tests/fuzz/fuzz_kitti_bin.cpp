// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes -> file -> readKittiBin / readBinXYZIR -> (if it parses) Pipeline on the first 20k points.
#include <cstdint>

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
        FUZZ_CHECK(size % 16 != 0);
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
