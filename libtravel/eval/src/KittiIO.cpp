// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/KittiIO.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "travel/Errors.hpp"

namespace travel {

namespace fs = std::filesystem;

namespace {

// The file formats are little-endian; only a big-endian host needs to swap.
#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__) && \
    __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostIsBigEndian = true;
#else
constexpr bool kHostIsBigEndian = false;
#endif

uint32_t byteSwap(uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0x0000FF00u) | ((v << 8) & 0x00FF0000u) | (v << 24);
}

// Little-endian file bytes <-> host value; memcpy because the bytes need not be aligned.
uint32_t loadU32(const unsigned char* bytes) {
    uint32_t v;
    std::memcpy(&v, bytes, sizeof(v));
    return kHostIsBigEndian ? byteSwap(v) : v;
}

float loadF32(const unsigned char* bytes) {
    const uint32_t bits = loadU32(bytes);
    float v;
    std::memcpy(&v, &bits, sizeof(v));
    return v;
}

void storeF32(float v, unsigned char* bytes) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof(bits));
    if (kHostIsBigEndian) bits = byteSwap(bits);
    std::memcpy(bytes, &bits, sizeof(bits));
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string inQuotes(const std::string& path) {
    return "'" + path + "'";
}

// Reads the whole file with a single fread into `buffer` (whose capacity is reused) and checks
// that its size is a multiple of record_size. `what` describes a record for the message.
void readWholeFile(const std::string& path, std::size_t record_size, const char* what,
                   std::vector<unsigned char>& buffer) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(inQuotes(path) + " is a directory");
    FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file) throw InputError("cannot open " + inQuotes(path) + ": " + std::strerror(errno));
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw InputError("cannot get the size of " + inQuotes(path) + ": " + ec.message());
    if (size % record_size != 0) {
        throw InputError(inQuotes(path) + ": size " + std::to_string(size) +
                         " bytes is not a multiple of " + std::to_string(record_size) + " (" +
                         what + "); " + std::to_string(size % record_size) + " bytes left over");
    }
    buffer.resize(static_cast<std::size_t>(size));
    if (size > 0 && std::fread(buffer.data(), 1, buffer.size(), file.get()) != buffer.size()) {
        throw InputError("cannot read " + inQuotes(path) + ": " +
                         (std::ferror(file.get()) ? std::strerror(errno) : "file shrank"));
    }
}

// One buffer per thread: a sequence of frames re-uses the same allocation.
std::vector<unsigned char>& scratchBuffer() {
    thread_local std::vector<unsigned char> buffer;
    return buffer;
}

void writeWholeFile(const std::string& path, const std::vector<unsigned char>& bytes) {
    FilePtr file(std::fopen(path.c_str(), "wb"));
    if (!file) {
        throw std::runtime_error("cannot write " + inQuotes(path) + ": " + std::strerror(errno));
    }
    const bool written =
        bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
    // fclose flushes: a full disk may only show up here.
    const bool closed = std::fclose(file.release()) == 0;
    if (!written || !closed) {
        throw std::runtime_error("cannot write " + inQuotes(path) + ": " + std::strerror(errno));
    }
}

void readFloatRecords(const std::string& path, std::size_t floats_per_record, const char* what,
                      PointCloud& cloud) {
    auto& buffer = scratchBuffer();
    const std::size_t record_size = floats_per_record * sizeof(float);
    readWholeFile(path, record_size, what, buffer);
    const std::size_t n = buffer.size() / record_size;
    cloud.ring.clear();
    cloud.time.clear();
    cloud.x.resize(n), cloud.y.resize(n), cloud.z.resize(n), cloud.intensity.resize(n);
    const unsigned char* record = buffer.data();
    for (std::size_t i = 0; i < n; ++i, record += record_size) {
        cloud.x[i] = loadF32(record);
        cloud.y[i] = loadF32(record + 4);
        cloud.z[i] = loadF32(record + 8);
        cloud.intensity[i] = loadF32(record + 12);
    }
}

}  // namespace

void readKittiBin(const std::string& path, PointCloud& cloud) {
    readFloatRecords(path, 4, "KITTI records are 4 float32: x, y, z, intensity", cloud);
}

void readBinXYZIR(const std::string& path, PointCloud& cloud) {
    readFloatRecords(path, 5, "records are 5 float32: x, y, z, intensity, ring", cloud);
    // The buffer still holds the file: take the fifth float of each record.
    const auto& buffer = scratchBuffer();
    const std::size_t n = cloud.size();
    cloud.ring.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const float ring = loadF32(buffer.data() + i * 20 + 16);
        // A non-integer ring means this is not the XYZIR layout (e.g. a time field).
        if (!(ring >= 0.f && ring <= 65535.f) || ring != std::floor(ring)) {
            throw InputError(inQuotes(path) + ": record " + std::to_string(i) + " has ring value " +
                             std::to_string(ring) + ", expected an integer in [0, 65535]");
        }
        cloud.ring[i] = static_cast<uint16_t>(ring);
    }
}

void writeKittiBin(const std::string& path, const PointCloud& cloud) {
    const std::size_t n = cloud.x.size();
    const bool has_intensity = !cloud.intensity.empty();
    if (cloud.y.size() != n || cloud.z.size() != n ||
        (has_intensity && cloud.intensity.size() != n)) {
        throw std::invalid_argument("writeKittiBin(" + inQuotes(path) +
                                    "): x, y, z and intensity sizes differ");
    }
    auto& buffer = scratchBuffer();
    buffer.resize(n * 16);
    unsigned char* record = buffer.data();
    for (std::size_t i = 0; i < n; ++i, record += 16) {
        storeF32(cloud.x[i], record);
        storeF32(cloud.y[i], record + 4);
        storeF32(cloud.z[i], record + 8);
        storeF32(has_intensity ? cloud.intensity[i] : 0.f, record + 12);
    }
    writeWholeFile(path, buffer);
}

std::vector<uint32_t> readLabelFile(const std::string& path, std::size_t expected_count) {
    auto& buffer = scratchBuffer();
    readWholeFile(path, 4, "labels are uint32", buffer);
    const std::size_t n = buffer.size() / 4;
    if (expected_count != kAnyLabelCount && n != expected_count) {
        throw InputError(inQuotes(path) + " has " + std::to_string(n) + " labels but " +
                         std::to_string(expected_count) + " were expected (one per point)");
    }
    std::vector<uint32_t> labels(n);
    for (std::size_t i = 0; i < n; ++i) labels[i] = loadU32(buffer.data() + 4 * i);
    return labels;
}

void writeLabelFile(const std::string& path, const std::vector<uint32_t>& labels) {
    auto& buffer = scratchBuffer();
    buffer.resize(labels.size() * 4);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const uint32_t v = kHostIsBigEndian ? byteSwap(labels[i]) : labels[i];
        std::memcpy(buffer.data() + 4 * i, &v, sizeof(v));
    }
    writeWholeFile(path, buffer);
}

std::vector<std::string> listFiles(const std::string& dir, const std::string& extension) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        throw InputError("directory " + inQuotes(dir) +
                         (fs::exists(dir, ec) ? " is not a directory" : " does not exist"));
    }
    const std::string wanted =
        extension.empty() || extension.front() == '.' ? extension : "." + extension;
    std::vector<std::string> files;
    fs::directory_iterator it(dir, ec);
    if (ec) throw InputError("cannot list " + inQuotes(dir) + ": " + ec.message());
    // increment() turns `it` into the end iterator on error; ec is checked after the loop.
    for (const fs::directory_iterator end; it != end; it.increment(ec)) {
        std::error_code type_ec;
        if (!it->is_regular_file(type_ec)) continue;  // follows symlinks, skips directories
        if (wanted.empty() || it->path().extension() == wanted) {
            files.push_back(it->path().string());
        }
    }
    if (ec) throw InputError("cannot list " + inQuotes(dir) + ": " + ec.message());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace travel
