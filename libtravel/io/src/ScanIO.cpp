// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/ScanIO.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "Readers.hpp"
#include "travel/EnumNames.hpp"
#include "travel/Errors.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/io/ScanList.hpp"  // lowerCaseExtension

namespace travel {

using namespace io_detail;
namespace fs = std::filesystem;

namespace {

constexpr EnumName<ScanFormat> kFormatNames[] = {{ScanFormat::Auto, "auto"},
                                                 {ScanFormat::KittiBin, "kitti"},
                                                 {ScanFormat::NuScenesBin, "nuscenes"},
                                                 {ScanFormat::Pcd, "pcd"},
                                                 {ScanFormat::Ply, "ply"}};
constexpr const char* kFormatHint =
    "give the format with --format (kitti: x y z intensity, nuscenes: x y z intensity ring)";

// One buffer per thread: a sequence of frames re-uses the same allocation.
std::vector<unsigned char>& scratchBuffer() {
    thread_local std::vector<unsigned char> buffer;
    return buffer;
}

std::vector<Field> binFields(ScanFormat format) {
    std::vector<Field> fields(format == ScanFormat::NuScenesBin ? 5 : 4);
    const Target targets[] = {Target::X, Target::Y, Target::Z, Target::Intensity, Target::Ring};
    for (std::size_t k = 0; k < fields.size(); ++k) fields[k].target = targets[k];
    return fields;
}

std::size_t recordSize(ScanFormat format) {
    return format == ScanFormat::NuScenesBin ? 20 : 16;
}

bool startsWith(const std::vector<unsigned char>& bytes, const char* prefix) {
    const std::size_t n = std::strlen(prefix);
    return bytes.size() >= n && std::memcmp(bytes.data(), prefix, n) == 0;
}

// PCD files start with a comment or VERSION line, PLY files with "ply".
ScanFormat formatFromContents(const std::vector<unsigned char>& bytes) {
    if (startsWith(bytes, "# .PCD") || startsWith(bytes, "VERSION")) return ScanFormat::Pcd;
    if (startsWith(bytes, "ply\n") || startsWith(bytes, "ply\r\n")) return ScanFormat::Ply;
    return ScanFormat::Auto;
}

// The dataset layouts that say which .bin layout a file has.
ScanFormat binFormatFromName(const fs::path& path) {
    const std::string name = path.filename().string();
    const std::string folder = path.parent_path().filename().string();
    const std::string grandparent = path.parent_path().parent_path().filename().string();
    if (name.find("__LIDAR_TOP__") != std::string::npos ||
        (folder == "LIDAR_TOP" && (grandparent == "samples" || grandparent == "sweeps")))
        return ScanFormat::NuScenesBin;
    if (folder == "velodyne") return ScanFormat::KittiBin;
    return ScanFormat::Auto;
}

// True when decoding `bytes` as `format` gives plausible points: coordinates finite and under
// 1 km, intensity finite in [0, 65535] and (nuScenes) ring an integer in [0, 255], for at least
// 99 % of the points with finite coordinates (non-finite ones are no-returns, not evidence).
bool plausibleAs(ScanFormat format, const std::vector<unsigned char>& bytes) {
    const std::size_t size = recordSize(format), n = bytes.size() / size;
    std::size_t finite = 0, bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char* r = bytes.data() + i * size;
        const float x = le::load<float>(r), y = le::load<float>(r + 4), z = le::load<float>(r + 8);
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) continue;
        ++finite;
        const float intensity = le::load<float>(r + 12);
        bool ok = std::fabs(x) < 1000.f && std::fabs(y) < 1000.f && std::fabs(z) < 1000.f &&
                  intensity >= 0.f && intensity <= 65535.f;
        if (format == ScanFormat::NuScenesBin) {
            const float ring = le::load<float>(r + 16);
            ok = ok && ring >= 0.f && ring <= 255.f && ring == std::floor(ring);
        }
        bad += !ok;
    }
    return finite > 0 && bad * 100 <= finite;
}

ScanFormat binFormatFromContents(const std::string& path, const std::vector<unsigned char>& bytes) {
    const std::size_t size = bytes.size();
    const bool kitti_size = size % 16 == 0, nuscenes_size = size % 20 == 0;
    if (!kitti_size && !nuscenes_size) {
        fail(path, "size " + std::to_string(size) +
                       " is a multiple of neither 16 (KITTI) nor 20 (nuScenes) bytes");
    }
    const bool kitti = kitti_size && plausibleAs(ScanFormat::KittiBin, bytes);
    const bool nuscenes = nuscenes_size && plausibleAs(ScanFormat::NuScenesBin, bytes);
    if (kitti && nuscenes) {
        fail(path, "both KITTI (16-byte) and nuScenes (20-byte) records give plausible points; " +
                       std::string(kFormatHint));
    }
    if (kitti) return ScanFormat::KittiBin;
    if (nuscenes) return ScanFormat::NuScenesBin;
    const std::string records =
        kitti_size && nuscenes_size
            ? "neither its KITTI (16-byte) nor its nuScenes (20-byte) records are"
            : std::string("its ") + (kitti_size ? "KITTI (16-byte)" : "nuScenes (20-byte)") +
                  " records are not";
    fail(path, "not a scan: " + records +
                   " plausible points (coordinates over 1 km or not finite, "
                   "negative intensity or a fractional ring); " +
                   kFormatHint);
}

// The format of the file `path`, whose contents are `bytes`.
ScanFormat detectFormat(const std::string& path, const std::vector<unsigned char>& bytes) {
    if (bytes.empty()) fail(path, "0 bytes, not a scan");
    const fs::path p(path);
    const std::string ext = lowerCaseExtension(path);
    if (ext == ".pcd") return ScanFormat::Pcd;
    if (ext == ".ply") return ScanFormat::Ply;
    const ScanFormat by_contents = formatFromContents(bytes);
    if (by_contents != ScanFormat::Auto) return by_contents;
    if (ext != ".bin") {
        fail(path,
             "cannot tell the scan format from the name or the first bytes; give it with "
             "--format (" +
                 std::string(scanFormatNames()) + ")");
    }
    const ScanFormat by_name = binFormatFromName(p);
    if (by_name != ScanFormat::Auto) return by_name;
    return binFormatFromContents(path, bytes);
}

void readBin(const std::string& path, const std::vector<unsigned char>& bytes, ScanFormat format,
             PointCloud& cloud) {
    const std::size_t size = recordSize(format);
    const char* layout = format == ScanFormat::NuScenesBin
                             ? "nuScenes records are 5 float32: x, y, z, intensity, ring"
                             : "KITTI records are 4 float32: x, y, z, intensity";
    if (bytes.empty()) fail(path, "0 bytes, not a scan");
    if (bytes.size() % size != 0) {
        fail(path, "size " + std::to_string(bytes.size()) + " is not a multiple of " +
                       std::to_string(size) + " bytes (" + layout + "); " +
                       std::to_string(bytes.size() % size) + " bytes left over");
    }
    ValueSource src(path, false, bytes.data(), bytes.data() + bytes.size(), 0);
    decodeRecords(path, binFields(format), bytes.size() / size, src, cloud, "point");
}

}  // namespace

const char* toString(ScanFormat format) {
    return nameOf(kFormatNames, format);
}

const char* scanFormatNames() {
    static const std::string names = namesOf(kFormatNames, ", ", ", ");
    return names.c_str();
}

ScanFormat scanFormatFromString(const std::string& name) {
    if (const auto format = findByName(kFormatNames, name)) return *format;
    throw ConfigError("unknown scan format '" + name + "'; allowed: " + scanFormatNames());
}

ScanFormat detectScanFormat(const std::string& path) {
    auto& bytes = scratchBuffer();
    readFileBytes(path, bytes);
    return detectFormat(path, bytes);
}

ScanFormat readScan(const std::string& path, PointCloud& cloud, ScanFormat format) {
    auto& bytes = scratchBuffer();
    readFileBytes(path, bytes);
    if (format == ScanFormat::Auto) format = detectFormat(path, bytes);
    switch (format) {
        case ScanFormat::KittiBin:
        case ScanFormat::NuScenesBin:
            readBin(path, bytes, format, cloud);
            break;
        case ScanFormat::Pcd:
            readPcd(path, bytes, cloud);
            break;
        case ScanFormat::Ply:
            readPly(path, bytes, cloud);
            break;
        case ScanFormat::Auto:
            break;
    }
    const std::size_t n = cloud.size();
    if (n == 0) fail(path, "0 points, not a scan");
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(cloud.x[i]) && std::isfinite(cloud.y[i]) && std::isfinite(cloud.z[i]))
            return format;
    fail(path, "none of its " + std::to_string(n) + " points has finite x, y, z");
}

}  // namespace travel
