// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes -> file -> travel-rawlog's read loop (CFileGZInputStream: plain or gzip) -> for every
// LiDAR observation (also inside CSensoryFrames) toTravelCloud + Pipeline. Exceptions from MRPT's
// deserialization are expected; crashes and sanitizer reports are findings.
// MRPT itself is not instrumented (distribution packages): coverage guidance is for the
// adapters and libtravel, ASan still sees every heap access made through malloc.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <exception>
#include <memory>

#include "FuzzCommon.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"

namespace {
constexpr std::size_t kMaxPoints = 20000;
constexpr int kMaxRecords = 32;

void processObservation(const mrpt::obs::CObservation& obs) {
    static travel::Params params;
    static travel::Pipeline pipeline(params);
    static travel::PointCloud cloud;
    static travel::Result result;
    mrpt::poses::CPose3D sensor_pose;
    std::string why;
    if (!travel_mrpt::toTravelCloud(obs, cloud, sensor_pose, &why)) {
        FUZZ_CHECK(cloud.empty());
        return;
    }
    FUZZ_CHECK(cloud.y.size() == cloud.size() && cloud.z.size() == cloud.size());
    FUZZ_CHECK(cloud.ring.empty() || cloud.ring.size() == cloud.size());
    FUZZ_CHECK(cloud.time.empty() || cloud.time.size() == cloud.size());
    if (cloud.size() > kMaxPoints) cloud.resize(kMaxPoints);
    pipeline.process(cloud, travel::FrameInput{}, result);
    travel_fuzz::checkResult(cloud, params, result);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string& path = travel_fuzz::tempPath(".rawlog");
    travel_fuzz::writeFile(path, data, size);
    mrpt::io::CFileGZInputStream file;
    if (!file.open(path)) return 0;
    auto archive = mrpt::serialization::archiveFrom(file);
    for (int record = 0; record < kMaxRecords; ++record) {
        mrpt::serialization::CSerializable::Ptr obj;
        try {
            obj = archive.ReadObject();
        } catch (const std::exception&) {
            break;  // not a rawlog, truncated, unknown class ...: expected
        }
        if (!obj) break;
        if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
            for (const auto& obs : *sf)
                if (obs) processObservation(*obs);
        } else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) {
            processObservation(*obs);
        }
    }
    return 0;
}
