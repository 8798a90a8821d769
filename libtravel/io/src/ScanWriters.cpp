// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "Readers.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/io/ScanIO.hpp"

namespace travel {

using namespace io_detail;

namespace {

// The columns a writer stores: x, y, z, intensity, then ring and time when the cloud has them.
struct Columns {
    std::size_t n;
    bool intensity, ring, time;
};

Columns columnsOf(const char* writer, const std::string& path, const PointCloud& cloud) {
    const std::size_t n = cloud.x.size();
    Columns c{n, !cloud.intensity.empty(), cloud.hasRing(), cloud.hasTime()};
    if (cloud.y.size() != n || cloud.z.size() != n || (c.intensity && cloud.intensity.size() != n))
        throw std::invalid_argument(std::string(writer) + "('" + path +
                                    "'): x, y, z and intensity sizes differ");
    return c;
}

// Point i packed as little-endian F4 x y z intensity [U2 ring] [F4 time]; returns the bytes.
std::size_t packPoint(const PointCloud& cloud, const Columns& c, std::size_t i,
                      unsigned char* out) {
    le::store(cloud.x[i], out);
    le::store(cloud.y[i], out + 4);
    le::store(cloud.z[i], out + 8);
    le::store(c.intensity ? cloud.intensity[i] : 0.f, out + 12);
    std::size_t size = 16;
    if (c.ring) le::store(cloud.ring[i], out + size), size += 2;
    if (c.time) le::store(cloud.time[i], out + size), size += 4;
    return size;
}

std::size_t rowSize(const Columns& c) {
    return 16 + (c.ring ? 2 : 0) + (c.time ? 4 : 0);
}

// Point i as ASCII: floats with 9 significant digits, so they read back bit for bit.
void appendAscii(const PointCloud& cloud, const Columns& c, std::size_t i, std::string& out) {
    char buf[128];
    int len = std::snprintf(buf, sizeof(buf), "%.9g %.9g %.9g %.9g", cloud.x[i], cloud.y[i],
                            cloud.z[i], c.intensity ? cloud.intensity[i] : 0.f);
    out.append(buf, static_cast<std::size_t>(len));
    if (c.ring) out += " " + std::to_string(cloud.ring[i]);
    if (c.time) {
        len = std::snprintf(buf, sizeof(buf), " %.9g", cloud.time[i]);
        out.append(buf, static_cast<std::size_t>(len));
    }
    out += '\n';
}

// `header`, then one text line per point (the ascii encodings of PCD and PLY).
void writeAscii(const std::string& path, std::string header, const PointCloud& cloud,
                const Columns& c) {
    for (std::size_t i = 0; i < c.n; ++i) appendAscii(cloud, c, i, header);
    writeFileBytes(path, reinterpret_cast<const unsigned char*>(header.data()), header.size());
}

// `header`, then every point as one packed row (KITTI .bin, binary PCD and PLY).
std::vector<unsigned char> packRows(const std::string& header, const PointCloud& cloud,
                                    const Columns& c) {
    const std::size_t row = rowSize(c);
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.resize(header.size() + c.n * row);
    for (std::size_t i = 0; i < c.n; ++i)
        packPoint(cloud, c, i, bytes.data() + header.size() + i * row);
    return bytes;
}

}  // namespace

void writeKittiBin(const std::string& path, const PointCloud& cloud) {
    const Columns c = columnsOf("writeKittiBin", path, cloud);
    const std::vector<unsigned char> bytes = packRows({}, cloud, {c.n, c.intensity, false, false});
    writeFileBytes(path, bytes.data(), bytes.size());
}

void writePcd(const std::string& path, const PointCloud& cloud, PcdEncoding encoding) {
    const Columns c = columnsOf("writePcd", path, cloud);
    const char* data = encoding == PcdEncoding::Ascii    ? "ascii"
                       : encoding == PcdEncoding::Binary ? "binary"
                                                         : "binary_compressed";
    std::string header = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n";
    header += std::string("FIELDS x y z intensity") + (c.ring ? " ring" : "") +
              (c.time ? " time" : "") + "\n";
    header += std::string("SIZE 4 4 4 4") + (c.ring ? " 2" : "") + (c.time ? " 4" : "") + "\n";
    header += std::string("TYPE F F F F") + (c.ring ? " U" : "") + (c.time ? " F" : "") + "\n";
    header += std::string("COUNT 1 1 1 1") + (c.ring ? " 1" : "") + (c.time ? " 1" : "") + "\n";
    header += "WIDTH " + std::to_string(c.n) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
              std::to_string(c.n) + "\nDATA " + data + "\n";
    if (encoding == PcdEncoding::Ascii) return writeAscii(path, header, cloud, c);
    if (encoding == PcdEncoding::Binary) {
        const std::vector<unsigned char> bytes = packRows(header, cloud, c);
        writeFileBytes(path, bytes.data(), bytes.size());
        return;
    }
    // Field after field (all x, then all y, ...), as PCL does before compressing.
    const std::vector<unsigned char> packed = packRows({}, cloud, c);
    const std::size_t row = rowSize(c);
    const std::size_t widths[] = {4, 4, 4, 4, c.ring ? 2u : 0u, c.time ? 4u : 0u};
    std::vector<unsigned char> soa(packed.size());
    std::size_t column = 0, offset = 0;
    for (const std::size_t w : widths) {
        for (std::size_t i = 0; i < c.n; ++i)
            std::memcpy(soa.data() + column + i * w, packed.data() + i * row + offset, w);
        column += c.n * w, offset += w;
    }
    const std::vector<unsigned char> lzf = lzfCompress(soa.data(), soa.size());
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.resize(header.size() + 8 + lzf.size());
    le::store(static_cast<uint32_t>(lzf.size()), bytes.data() + header.size());
    le::store(static_cast<uint32_t>(soa.size()), bytes.data() + header.size() + 4);
    std::copy(lzf.begin(), lzf.end(),
              bytes.begin() + static_cast<std::ptrdiff_t>(header.size() + 8));
    writeFileBytes(path, bytes.data(), bytes.size());
}

void writePly(const std::string& path, const PointCloud& cloud, PlyEncoding encoding) {
    const Columns c = columnsOf("writePly", path, cloud);
    std::string header = std::string("ply\nformat ") +
                         (encoding == PlyEncoding::Ascii ? "ascii" : "binary_little_endian") +
                         " 1.0\nelement vertex " + std::to_string(c.n) +
                         "\nproperty float x\nproperty float y\nproperty float z\n"
                         "property float intensity\n";
    if (c.ring) header += "property ushort ring\n";
    if (c.time) header += "property float time\n";
    header += "end_header\n";
    if (encoding == PlyEncoding::Ascii) return writeAscii(path, header, cloud, c);
    const std::vector<unsigned char> bytes = packRows(header, cloud, c);
    writeFileBytes(path, bytes.data(), bytes.size());
}

}  // namespace travel
