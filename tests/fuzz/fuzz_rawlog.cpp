// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes -> file -> travel_mrpt::RawlogReader (travel-rawlog's and travel-map's reader: plain or
// gzip; its errors must name the file) -> for every
// LiDAR observation (also inside CSensoryFrames) toTravelCloud + Pipeline; our own
// CObservationTravelLabels (registered here) is deserialized, checked, described and drawn.
// Exceptions from MRPT's deserialization are expected; crashes and sanitizer reports are findings.
// MRPT itself is not instrumented (distribution packages): coverage guidance is for the
// adapters and libtravel, ASan still sees every heap access made through malloc.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <malloc.h>
#include <cstdint>
#include <cstdlib>
#include <exception>

#include <algorithm>
#include <atomic>
#include <memory>
#include <new>

#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/rtti/CObject.h>

#include <sstream>

#include "FuzzCommon.hpp"
#include "travel/Errors.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/RawlogReader.hpp"

// MRPT's deserializers allocate whatever size the stream announces (a corrupt length of 3.5 GB
// is one mutation away). Without ASan that throws std::bad_alloc, which travel-rawlog reports as
// "corrupt record"; under ASan, operator new aborts instead and libFuzzer calls it an OOM. Give
// the harness the production behaviour: operator new throws std::bad_alloc above 256 MB in one
// block, or when the live total through new passes 1 GB (CSensoryFrame reads a count and grows a
// deque of that many pointers, in small blocks). It forwards to malloc/free, which ASan still
// intercepts (overflows, use-after-free, leaks).
namespace {
constexpr std::size_t kMaxAlloc = std::size_t(256) << 20;
constexpr std::size_t kMaxLive = std::size_t(1) << 30;
std::atomic<std::size_t> g_live{0};
void* fuzzNew(std::size_t n) {
    if (n > kMaxAlloc || g_live.load(std::memory_order_relaxed) + n > kMaxLive)
        throw std::bad_alloc();
    if (void* p = std::malloc(n ? n : 1)) {
        g_live += malloc_usable_size(p);
        return p;
    }
    throw std::bad_alloc();
}
void fuzzFree(void* p) {
    if (p) g_live -= malloc_usable_size(p);
    std::free(p);
}
void* fuzzNewAligned(std::size_t n, std::align_val_t a) {
    if (n > kMaxAlloc) throw std::bad_alloc();
    const std::size_t al = static_cast<std::size_t>(a);
    if (void* p = std::aligned_alloc(al, (std::max<std::size_t>(n, 1) + al - 1) / al * al)) {
        g_live += malloc_usable_size(p);
        return p;
    }
    throw std::bad_alloc();
}
}  // namespace
void* operator new(std::size_t n) {
    return fuzzNew(n);
}
void* operator new[](std::size_t n) {
    return fuzzNew(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return fuzzNew(n);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return fuzzNew(n);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new(std::size_t n, std::align_val_t a) {
    return fuzzNewAligned(n, a);
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return fuzzNewAligned(n, a);
}
void operator delete(void* p) noexcept {
    fuzzFree(p);
}
void operator delete[](void* p) noexcept {
    fuzzFree(p);
}
void operator delete(void* p, std::size_t) noexcept {
    fuzzFree(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    fuzzFree(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    fuzzFree(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    fuzzFree(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    fuzzFree(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    fuzzFree(p);
}

namespace {
constexpr std::size_t kMaxPoints = 20000;
constexpr int kMaxRecords = 32;

/// A labels object that deserialized must be self-consistent (the reader validates it).
void checkLabels(const travel_mrpt::CObservationTravelLabels& labels) {
    const std::size_t n = labels.size();
    FUZZ_CHECK(labels.y.size() == n && labels.z.size() == n && labels.intensity.size() == n);
    FUZZ_CHECK(labels.labels.size() == n && labels.clusterId.size() == n);
    for (std::size_t i = 0; i < n; ++i) {
        FUZZ_CHECK(labels.labels[i] <= 3);
        FUZZ_CHECK(labels.clusterId[i] <= labels.clusters.size());
    }
    std::ostringstream text;
    labels.getDescriptionAsText(text);
    mrpt::opengl::CSetOfObjects scene;
    labels.getVisualizationInto(scene);
}

void processObservation(const mrpt::obs::CObservation& obs) {
    if (auto* labels = dynamic_cast<const travel_mrpt::CObservationTravelLabels*>(&obs)) {
        checkLabels(*labels);
        return;
    }
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

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // Only our labels class (not registerClasses(), which would pull in every class of ours).
    mrpt::rtti::registerClass(CLASS_ID(travel_mrpt::CObservationTravelLabels));
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string& path = travel_fuzz::tempPath(".rawlog");
    travel_fuzz::writeFile(path, data, size);
    try {
        travel_mrpt::RawlogReader reader(path);
        while (reader.index() < kMaxRecords) {
            const auto obj = reader.next();
            if (!obj) break;
            if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
                for (const auto& obs : *sf)
                    if (obs) processObservation(*obs);
            } else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) {
                processObservation(*obs);
            }
        }
    } catch (const travel::InputError& e) {
        // Not a rawlog, truncated, unknown class ...: expected; the message names the record.
        FUZZ_CHECK(std::string(e.what()).rfind(path, 0) == 0);
    }
    return 0;
}
