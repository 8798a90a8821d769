// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// First byte -> file name and format (auto or explicit); the rest -> file -> readScan.
// A successful read must give a consistent cloud with a finite point, and must survive a
// round trip through binary_compressed PCD (the LZF encoder and decoder) and ascii PLY.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "FuzzCommon.hpp"
#include "travel/Errors.hpp"
#include "travel/io/ScanIO.hpp"

namespace {

void checkCloud(const travel::PointCloud& c) {
    const std::size_t n = c.size();
    FUZZ_CHECK(n > 0);
    FUZZ_CHECK(c.y.size() == n && c.z.size() == n && c.intensity.size() == n);
    FUZZ_CHECK(c.ring.empty() || c.ring.size() == n);
    FUZZ_CHECK(c.time.empty() || c.time.size() == n);
    bool finite = false;
    for (std::size_t i = 0; i < n && !finite; ++i)
        finite = std::isfinite(c.x[i]) && std::isfinite(c.y[i]) && std::isfinite(c.z[i]);
    FUZZ_CHECK(finite);
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const kSuffixes[] = {".bin", ".pcd", ".ply", ".pcd.bin"};
    static const travel::ScanFormat kFormats[] = {
        travel::ScanFormat::Auto, travel::ScanFormat::KittiBin, travel::ScanFormat::NuScenesBin,
        travel::ScanFormat::Pcd, travel::ScanFormat::Ply};
    const char* suffix = kSuffixes[data[0] & 3];
    const travel::ScanFormat format = kFormats[(data[0] >> 2) % 5];
    // One temp file per suffix (tempPath keeps the first suffix it is given).
    const std::string path = travel_fuzz::tempPath(".scan") + suffix;
    travel_fuzz::writeFile(path, data + 1, size - 1);
    static travel::PointCloud cloud, copy;
    try {
        travel::readScan(path, cloud, format);
    } catch (const travel::InputError&) {
        return 0;
    }
    checkCloud(cloud);
    if (cloud.size() > 5000) return 0;  // keep the round trip cheap
    const std::string pcd = travel_fuzz::tempPath(".scan") + ".rt.pcd";
    travel::writePcd(pcd, cloud, travel::PcdEncoding::BinaryCompressed);
    travel::readScan(pcd, copy);
    FUZZ_CHECK(sameBits(cloud.x, copy.x) && sameBits(cloud.y, copy.y) &&
               sameBits(cloud.z, copy.z) && sameBits(cloud.intensity, copy.intensity));
    FUZZ_CHECK(cloud.ring == copy.ring && sameBits(cloud.time, copy.time));
    const std::string ply = travel_fuzz::tempPath(".scan") + ".rt.ply";
    travel::writePly(ply, cloud, travel::PlyEncoding::Ascii);
    travel::readScan(ply, copy);
    FUZZ_CHECK(copy.size() == cloud.size());
    return 0;
}
