// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel_io's readScan(): every format on real files (skipped when ../shared/data is absent),
// the same points through every encoding, format detection, and each bad file's message.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "FileSizeLimit.hpp"
#include "TempDir.hpp"
#include "travel/Errors.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel/io/ScanIO.hpp"

namespace fs = std::filesystem;
using travel::InputError;
using travel::PointCloud;
using travel::readScan;
using travel::ScanFormat;

namespace {

const fs::path kData = fs::path(TRAVEL_DATA_DIR);

template <class F>
std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

using travel_test::TempDir;

template <class T>
std::string le(T v) {
    std::string s(sizeof(T), '\0');
    std::memcpy(s.data(), &v, sizeof(T));
    return s;
}

// POINTS from a PCD header, read independently of the library.
std::size_t pcdPoints(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("POINTS ", 0) == 0) return std::stoul(line.substr(7));
        if (line.rfind("DATA", 0) == 0) break;
    }
    return 0;
}

void expectSameCloud(const PointCloud& a, const PointCloud& b) {
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.z, b.z);
    EXPECT_EQ(a.intensity, b.intensity);
    EXPECT_EQ(a.ring, b.ring);
    EXPECT_EQ(a.time, b.time);
}

std::vector<fs::path> kittiRawPcds() {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(kData / "kitti_raw_pcd", ec))
        if (e.path().extension() == ".pcd") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

PointCloud smallCloud(bool ring_and_time) {
    PointCloud c;
    c.push_back(1.5f, -2.25f, 0.125f, 7.f);
    c.push_back(-40.f, 12.345678f, -1.73f, 0.f);
    c.push_back(0.1f, 0.2f, 0.3f, 255.f);
    if (ring_and_time) {
        c.ring = {0, 31, 63};
        c.time = {0.f, 0.05f, 0.0999f};
    }
    return c;
}

}  // namespace

TEST(ScanIO, FormatNames) {
    for (const char* name : {"auto", "kitti", "nuscenes", "pcd", "ply"})
        EXPECT_STREQ(travel::toString(travel::scanFormatFromString(name)), name);
    try {
        travel::scanFormatFromString("las");
        FAIL() << "no ConfigError";
    } catch (const travel::ConfigError& e) {
        EXPECT_STREQ(e.what(),
                     "unknown scan format 'las'; allowed: auto, kitti, nuscenes, pcd, ply");
    }
}

TEST(ScanIO, RealNuScenesIsDetectedAsNuScenes) {
    const fs::path file = kData / "nuscenes/hdl32_000000.bin";
    if (!fs::exists(file)) GTEST_SKIP() << "nuScenes scan not found: " << file;
    EXPECT_EQ(travel::detectScanFormat(file.string()), ScanFormat::NuScenesBin);
    PointCloud cloud;
    EXPECT_EQ(readScan(file.string(), cloud), ScanFormat::NuScenesBin);  // the format it read
    ASSERT_EQ(cloud.size(), 34688u);
    ASSERT_TRUE(cloud.hasRing());
    EXPECT_FALSE(cloud.hasTime());
    EXPECT_EQ(*std::max_element(cloud.ring.begin(), cloud.ring.end()), 31);
    // The same bytes under nuScenes names and folders; and explicitly.
    TempDir dir;
    for (const char* name : {"n008-2018-08-01-15-16-36-0400__LIDAR_TOP__1533151603547590.pcd.bin",
                             "samples/LIDAR_TOP/a.bin", "sweeps/LIDAR_TOP/b.bin", "plain.bin"}) {
        fs::copy_file(file, dir.file(name));
        EXPECT_EQ(travel::detectScanFormat(dir.file(name)), ScanFormat::NuScenesBin) << name;
    }
    PointCloud explicit_cloud;
    readScan(file.string(), explicit_cloud, ScanFormat::NuScenesBin);
    expectSameCloud(cloud, explicit_cloud);
}

TEST(ScanIO, RealKittiAndOusterAreDetectedAsKitti) {
    const fs::path velodyne = kData / "semantickitti/sequences/00/velodyne";
    const fs::path ouster = kData / "ouster128/000000.bin";
    if (!fs::exists(velodyne) || !fs::exists(ouster))
        GTEST_SKIP() << "KITTI / Ouster scans not found in " << kData;
    PointCloud cloud;
    TempDir dir;
    for (const auto& e : fs::directory_iterator(velodyne)) {
        const std::string path = e.path().string();
        EXPECT_EQ(travel::detectScanFormat(path), ScanFormat::KittiBin) << path;
        readScan(path, cloud);
        EXPECT_EQ(cloud.size() * 16, fs::file_size(e.path())) << path;
        EXPECT_FALSE(cloud.hasRing());
        // Outside a velodyne/ folder the values decide.
        const std::string copy = dir.file("loose_" + e.path().filename().string());
        fs::copy_file(e.path(), copy);
        EXPECT_EQ(travel::detectScanFormat(copy), ScanFormat::KittiBin) << copy;
        EXPECT_EQ(readScan(copy, cloud), ScanFormat::KittiBin) << copy;
    }
    EXPECT_EQ(travel::detectScanFormat(ouster.string()), ScanFormat::KittiBin);
    readScan(ouster.string(), cloud);
    EXPECT_EQ(cloud.size(), 205898u);
}

TEST(ScanIO, RealPcdsReadWithTheirPointCounts) {
    const std::vector<fs::path> files = kittiRawPcds();
    if (files.empty()) GTEST_SKIP() << "KITTI raw PCD frames not found in " << kData;
    EXPECT_EQ(files.size(), 22u);
    PointCloud cloud;
    for (const fs::path& f : files) {
        EXPECT_EQ(travel::detectScanFormat(f.string()), ScanFormat::Pcd);
        readScan(f.string(), cloud);
        EXPECT_EQ(cloud.size(), pcdPoints(f)) << f;
        EXPECT_GT(cloud.size(), 100000u) << f;
        EXPECT_FALSE(cloud.hasRing());
    }
}

TEST(ScanIO, RealPcdReadsBackIdenticallyInEveryEncoding) {
    const std::vector<fs::path> files = kittiRawPcds();
    if (files.empty()) GTEST_SKIP() << "KITTI raw PCD frames not found in " << kData;
    PointCloud original;
    readScan(files.front().string(), original);
    // A value cross-checked by hand: the first point's x from the file's raw bytes.
    {
        std::ifstream in(files.front(), std::ios::binary);
        std::string all((std::istreambuf_iterator<char>(in)), {});
        const std::size_t data = all.find("DATA binary\n") + 12;
        float x0, i1;
        std::memcpy(&x0, all.data() + data, 4);
        std::memcpy(&i1, all.data() + data + 16 + 12, 4);
        EXPECT_EQ(original.x[0], x0);
        EXPECT_EQ(original.intensity[1], i1);
    }
    TempDir dir;
    travel::writePcd(dir.file("a.pcd"), original, travel::PcdEncoding::Ascii);
    travel::writePcd(dir.file("b.pcd"), original, travel::PcdEncoding::Binary);
    travel::writePcd(dir.file("c.pcd"), original, travel::PcdEncoding::BinaryCompressed);
    travel::writePly(dir.file("d.ply"), original, travel::PlyEncoding::Ascii);
    travel::writePly(dir.file("e.ply"), original, travel::PlyEncoding::BinaryLittleEndian);
    travel::writeKittiBin(dir.file("velodyne/f.bin"), original);
    // The binary PCD rewritten by the library is the file, byte for byte, without the zero
    // bytes PCL's writer padded it with.
    {
        std::ifstream a(files.front(), std::ios::binary), b(dir.file("b.pcd"), std::ios::binary);
        const std::string original_bytes((std::istreambuf_iterator<char>(a)), {});
        const std::string written_bytes((std::istreambuf_iterator<char>(b)), {});
        ASSERT_LE(written_bytes.size(), original_bytes.size());
        EXPECT_TRUE(original_bytes.compare(0, written_bytes.size(), written_bytes) == 0);
        EXPECT_EQ(original_bytes.find_first_not_of('\0', written_bytes.size()), std::string::npos);
    }
    EXPECT_LT(fs::file_size(dir.file("c.pcd")), fs::file_size(files.front()));
    for (const char* name : {"a.pcd", "b.pcd", "c.pcd", "d.ply", "e.ply", "velodyne/f.bin"}) {
        SCOPED_TRACE(name);
        PointCloud copy;
        readScan(dir.file(name), copy);
        expectSameCloud(original, copy);
    }
}

TEST(ScanIO, RingAndTimeRoundTripThroughPcdAndPly) {
    const PointCloud cloud = smallCloud(true);
    TempDir dir;
    travel::writePcd(dir.file("a.pcd"), cloud, travel::PcdEncoding::Ascii);
    travel::writePcd(dir.file("b.pcd"), cloud, travel::PcdEncoding::BinaryCompressed);
    travel::writePly(dir.file("c.ply"), cloud, travel::PlyEncoding::Ascii);
    travel::writePly(dir.file("d.ply"), cloud, travel::PlyEncoding::BinaryLittleEndian);
    for (const char* name : {"a.pcd", "b.pcd", "c.ply", "d.ply"}) {
        SCOPED_TRACE(name);
        PointCloud copy;
        copy.ring = {9};  // stale fields are replaced
        readScan(dir.file(name), copy);
        expectSameCloud(cloud, copy);
    }
    // Without ring and time in the file, the cloud's are cleared.
    travel::writePcd(dir.file("e.pcd"), smallCloud(false), travel::PcdEncoding::Binary);
    PointCloud copy = smallCloud(true);
    readScan(dir.file("e.pcd"), copy);
    EXPECT_TRUE(copy.ring.empty());
    EXPECT_TRUE(copy.time.empty());
}

TEST(ScanIO, PcdAnyTypeAndSkippedFields) {
    TempDir dir;
    // Every PCD type; "normal" (COUNT 3) and "label" are skipped; an integer t is nanoseconds.
    const std::string header =
        "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z normal intensity ring t label\n"
        "SIZE 8 4 2 4 1 2 4 1\nTYPE F F I F U U U I\nCOUNT 1 1 1 3 1 1 1 1\n"
        "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n";
    dir.write("a.pcd", header +
                           "DATA ascii\n1.5 -2 3 0 0 1 200 7 50000000 -3\n"
                           "\n-4.25 5 -6 1 1 1 0 0 0 9\n");
    const std::string point1 = le<double>(1.5) + le<float>(-2.f) + le<int16_t>(3) + le<float>(0.f) +
                               le<float>(0.f) + le<float>(1.f) + le<uint8_t>(200) +
                               le<uint16_t>(7) + le<uint32_t>(50000000) + le<int8_t>(-3);
    const std::string point2 = le<double>(-4.25) + le<float>(5.f) + le<int16_t>(-6) +
                               le<float>(1.f) + le<float>(1.f) + le<float>(1.f) + le<uint8_t>(0) +
                               le<uint16_t>(0) + le<uint32_t>(0) + le<int8_t>(9);
    dir.write("b.pcd", header + "DATA binary\n" + point1 + point2);
    for (const char* name : {"a.pcd", "b.pcd"}) {
        SCOPED_TRACE(name);
        PointCloud c;
        readScan(dir.file(name), c);
        ASSERT_EQ(c.size(), 2u);
        EXPECT_EQ(c.x, (std::vector<float>{1.5f, -4.25f}));
        EXPECT_EQ(c.y, (std::vector<float>{-2.f, 5.f}));
        EXPECT_EQ(c.z, (std::vector<float>{3.f, -6.f}));
        EXPECT_EQ(c.intensity, (std::vector<float>{200.f, 0.f}));
        EXPECT_EQ(c.ring, (std::vector<uint16_t>{7, 0}));
        EXPECT_EQ(c.time, (std::vector<float>{0.05f, 0.f}));
    }
}

// KITTI's layout (binary float32 x, y, z, intensity) has a path of its own in the decoder; it
// gives the floats of the general float32 path (the same records with a fifth, skipped field in
// a PCD) bit for bit: signalling and quiet NaNs with payloads, -0, denormals, infinities, and a
// count that is not a multiple of the 4 records it splits at a time.
TEST(ScanIO, KittiLayoutDecodesAsTheGeneralPath) {
    const uint32_t values[] = {0x7f800001u, 0x7fa00005u, 0xffc12345u, 0x7fc00000u,
                               0x80000000u, 0x00000001u, 0x807fffffu, 0x7f800000u,
                               0xff800000u, 0xbf800000u, 0x41200000u};
    const std::size_t n = 11;
    std::string kitti = le<float>(1.f) + le<float>(2.f) + le<float>(3.f) + le<float>(4.f);
    std::string pcd = kitti + le<float>(0.f);
    for (std::size_t i = 1; i < n; ++i) {
        std::string record;
        for (std::size_t k = 0; k < 4; ++k) record += le<uint32_t>(values[(3 * i + 5 * k) % 11]);
        kitti += record;
        pcd += record + le<float>(0.f);
    }
    TempDir dir;
    dir.write("scan.bin", kitti);
    dir.write("scan.pcd",
              "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z intensity pad\nSIZE 4 4 4 4 4\n"
              "TYPE F F F F F\nCOUNT 1 1 1 1 1\nWIDTH 11\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
              "POINTS 11\nDATA binary\n" +
                  pcd);
    PointCloud fast, general;
    readScan(dir.file("scan.bin"), fast, ScanFormat::KittiBin);
    readScan(dir.file("scan.pcd"), general);
    ASSERT_EQ(fast.size(), n);
    ASSERT_EQ(general.size(), n);
    const auto bits = [](const std::vector<float>& v) {
        std::vector<uint32_t> out(v.size());
        std::memcpy(out.data(), v.data(), 4 * v.size());
        return out;
    };
    EXPECT_EQ(bits(fast.x), bits(general.x));
    EXPECT_EQ(bits(fast.y), bits(general.y));
    EXPECT_EQ(bits(fast.z), bits(general.z));
    EXPECT_EQ(bits(fast.intensity), bits(general.intensity));
}

TEST(ScanIO, PlySkipsOtherElementsAndReadsAnyType) {
    TempDir dir;
    const std::string header_tail =
        " 1.0\ncomment made by hand\nelement face 2\nproperty list uchar int vertex_indices\n"
        "element vertex 2\nproperty double x\nproperty float y\nproperty short z\n"
        "property uchar intensity\nproperty list uchar float extra\nproperty float time\n"
        "element edge 1\nproperty int a\nend_header\n";
    dir.write("a.ply", "ply\nformat ascii" + header_tail +
                           "3 0 1 2\n2 0 1\n1.5 -2 3 200 2 9 9 0.25\n-4.25 5 -6 0 0 0.5\n0\n");
    const std::string binary =
        le<uint8_t>(3) + le<int32_t>(0) + le<int32_t>(1) + le<int32_t>(2) + le<uint8_t>(0) +
        le<double>(1.5) + le<float>(-2.f) + le<int16_t>(3) + le<uint8_t>(200) + le<uint8_t>(1) +
        le<float>(9.f) + le<float>(0.25f) + le<double>(-4.25) + le<float>(5.f) + le<int16_t>(-6) +
        le<uint8_t>(0) + le<uint8_t>(0) + le<float>(0.5f) + le<int32_t>(0);
    dir.write("b.ply", "ply\nformat binary_little_endian" + header_tail + binary);
    for (const char* name : {"a.ply", "b.ply"}) {
        SCOPED_TRACE(name);
        PointCloud c;
        readScan(dir.file(name), c);
        ASSERT_EQ(c.size(), 2u);
        EXPECT_EQ(c.x, (std::vector<float>{1.5f, -4.25f}));
        EXPECT_EQ(c.z, (std::vector<float>{3.f, -6.f}));
        EXPECT_EQ(c.intensity, (std::vector<float>{200.f, 0.f}));
        EXPECT_EQ(c.time, (std::vector<float>{0.25f, 0.5f}));
        EXPECT_FALSE(c.hasRing());
    }
}

TEST(ScanIO, DetectionByNameAndContents) {
    TempDir dir;
    const PointCloud cloud = smallCloud(false);
    travel::writePcd(dir.file("scan.txt"), cloud, travel::PcdEncoding::Ascii);
    travel::writePly(dir.file("scan.dat"), cloud, travel::PlyEncoding::BinaryLittleEndian);
    EXPECT_EQ(travel::detectScanFormat(dir.file("scan.txt")), ScanFormat::Pcd);
    EXPECT_EQ(travel::detectScanFormat(dir.file("scan.dat")), ScanFormat::Ply);
    travel::writeKittiBin(dir.file("k.bin"), cloud);  // 48 bytes: a multiple of 16 only
    EXPECT_EQ(travel::detectScanFormat(dir.file("k.bin")), ScanFormat::KittiBin);
    // 4 KITTI points = 64 bytes; 5 = 80 bytes, also 4 nuScenes records, decided by the values.
    PointCloud five = cloud;
    five.push_back(3.3f, 4.4f, 5.5f, 0.5f);
    five.push_back(-7.7f, 8.8f, -0.9f, 0.25f);
    travel::writeKittiBin(dir.file("k5.bin"), five);
    EXPECT_EQ(travel::detectScanFormat(dir.file("k5.bin")), ScanFormat::KittiBin);
    dir.writeFloats("n.bin", {1.f,  2.f, 3.f, 4.f, 5.f, -6.f, 7.f,  -8.f, 9.f, 10.f,
                              -1.f, 2.f, 3.f, 4.f, 5.f, 6.f,  -7.f, 8.f,  9.f, 10.f});
    EXPECT_EQ(travel::detectScanFormat(dir.file("n.bin")), ScanFormat::NuScenesBin);
}

TEST(ScanIO, BadFilesNameTheFileAndTheProblem) {
    TempDir dir;
    PointCloud c;
    auto error = [&](const std::string& path, ScanFormat format = ScanFormat::Auto) {
        return inputErrorOf([&] { readScan(path, c, format); });
    };
    const std::string hint =
        "give the format with --format (kitti: x y z intensity, nuscenes: x y z intensity ring)";
    std::string p = dir.write("empty.bin", "");
    EXPECT_EQ(error(p), p + ": 0 bytes, not a scan");
    EXPECT_EQ(error(p, ScanFormat::NuScenesBin), p + ": 0 bytes, not a scan");
    p = dir.write("odd.bin", std::string(1234, 'a'));
    EXPECT_EQ(error(p),
              p + ": size 1234 is a multiple of neither 16 (KITTI) nor 20 (nuScenes) bytes");
    p = dir.write("zeros.bin", std::string(80, '\0'));
    EXPECT_EQ(error(p), p +
                            ": both KITTI (16-byte) and nuScenes (20-byte) records give plausible "
                            "points; " +
                            hint);
    EXPECT_EQ(inputErrorOf([&] { travel::detectScanFormat(p); }), error(p));
    std::string text = "This is a text file, padded to a multiple of 16 bytes.";
    text.resize(64, ' ');
    p = dir.write("text.bin", text);
    EXPECT_EQ(error(p), p +
                            ": not a scan: its KITTI (16-byte) records are not plausible points "
                            "(coordinates over 1 km or not finite, negative intensity or a "
                            "fractional ring); " +
                            hint);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    p = dir.writeFloats("all_nan.bin", std::vector<float>(20, nan));  // 80 bytes: 16 and 20 fit
    EXPECT_EQ(error(p), p +
                            ": not a scan: neither its KITTI (16-byte) nor its nuScenes (20-byte) "
                            "records are plausible points (coordinates over 1 km or not finite, "
                            "negative intensity or a fractional ring); " +
                            hint);
    p = dir.writeFloats("nan.bin", {nan, 0.f, 0.f, 1.f, 0.f, nan, 0.f, 1.f});
    EXPECT_EQ(error(p, ScanFormat::KittiBin), p + ": none of its 2 points has finite x, y, z");
    p = dir.writeFloats("short.bin", {1.f, 2.f, 3.f, 4.f, 5.f});
    EXPECT_EQ(error(p, ScanFormat::KittiBin),
              p + ": size 20 is not a multiple of 16 bytes (KITTI records are 4 float32: x, y, z, "
                  "intensity); 4 bytes left over");
    p = dir.writeFloats("ring.bin", {1.f, 2.f, 3.f, 4.f, 0.5f});
    EXPECT_EQ(error(p, ScanFormat::NuScenesBin),
              p + ": point 0 has ring 0.500000, expected an integer in [0, 65535]");
    p = dir.write("x.xyz", "1 2 3\n");
    EXPECT_EQ(error(p), p + ": cannot tell the scan format from the name or the first bytes; give "
                            "it with --format (auto, kitti, nuscenes, pcd, ply)");
    p = dir.file("missing.pcd");
    EXPECT_EQ(error(p), p + ": cannot open: No such file or directory");

    // PCD headers.
    const std::string head = "VERSION 0.7\nFIELDS x y z intensity\n";
    const std::string good = "SIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 1\nHEIGHT 1\n";
    struct Case {
        std::string text, message;
    };
    const Case pcd_cases[] = {
        {head + "SIZE 4 4 4\n", ":3: FIELDS has 4 names but SIZE has 3"},
        {"VERSION 0.5\n", ":1: VERSION '0.5' is not supported (expected 0.7)"},
        {"garbage here\n", ":1: 'garbage here' is not a PCD header line"},
        {head + "SIZE 4 4 4 3\nTYPE F F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 3 4\n",
         ":7: field 'intensity' has SIZE 3 TYPE 'F', not one of F4 F8 U1 U2 U4 I1 I2 I4"},
        {head + good + "POINTS 2\nDATA ascii\n1 2 3 4\n", ":8: POINTS 2 but WIDTH*HEIGHT = 1"},
        {head + good + "POINTS 1\n", ": the header ends without a DATA line"},
        {head + good + "DATA json\n", ":8: DATA 'json' is not ascii, binary or binary_compressed"},
        {"VERSION 0.7\nFIELDS x y i\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 "
         "3\n",
         ":7: FIELDS has no x, y and z"},
        {head + good + "DATA ascii\n1 2 3   \n",
         ":9: point 0 has fewer values than the header describes"},
        {head + good + "DATA ascii\n1 2 3 4 5\n",
         ":9: point 0 has more values than the header describes"},
        {head + good + "DATA ascii\n1 2 three 4\n", ":9: 'three' is not a number"},
        {head + good + "DATA ascii\n1 2 3 4\n5 6 7 8\n",
         ":10: more data after the last of 1 points"},
        {head + good + "DATA binary\n" + std::string(15, '\0'),
         ": DATA binary needs 1 points of 16 bytes but 15 bytes follow the header"},
        {head + good + "DATA binary_compressed\n" + le<uint32_t>(4) + le<uint32_t>(16) + "abcd",
         ": binary_compressed data is corrupt (LZF does not decode to 16 bytes)"},
        {head + good + "DATA binary_compressed\n" + le<uint32_t>(4) + le<uint32_t>(20) + "abcd",
         ": binary_compressed data unpacks to 20 bytes, but POINTS 1 of 16 bytes need 16"},
        {head + "SIZE 4 4 4 4\nTYPE F F F F\nWIDTH 0\nHEIGHT 1\nDATA ascii\n",
         ": 0 points, not a scan"},
    };
    int k = 0;
    for (const Case& cs : pcd_cases) {
        p = dir.write("bad" + std::to_string(k++) + ".pcd", cs.text);
        EXPECT_EQ(error(p), p + cs.message);
    }

    // PLY headers and data.
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n";
    const Case ply_cases[] = {
        {"ply\nformat binary_big_endian 1.0\n",
         ":2: format 'binary_big_endian' is not supported (ascii or binary_little_endian only)"},
        {ply + "property float y\nend_header\n1 2\n", ":6: element vertex has no x, y and z"},
        {"ply\nformat ascii 1.0\nelement face 0\nend_header\n",
         ":4: the header has no vertex element"},
        {ply + "property float y\nproperty float z\nend_header\n",
         ": the header announces 1 vertices but only 0 bytes of data follow"},
        {"ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n" +
             std::string(24, '\0'),
         ": the header announces 1000 vertices but only 24 bytes of data follow"},
        {"solid cube\n", ":1: 'solid cube' is not 'ply': not a PLY file"},
        // More vertex rows than announced, when the vertices are the last element: points the
        // header does not count were dropped without a word.
        {ply + "property float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n",
         ":9: more data after the last of 1 vertices"},
        {"ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n" +
             std::string(16, '\0'),
         ": 4 bytes after the last of 1 vertices"},
    };
    for (const Case& cs : ply_cases) {
        p = dir.write("bad" + std::to_string(k++) + ".ply", cs.text);
        EXPECT_EQ(error(p), p + cs.message);
    }
}

// travel::PartFile, the one home of "write beside, move in place": committed, the file is under
// its name and no part file is left; unwound before commit() (an error), neither is; a move that
// fails (the name is a folder) throws naming the file and removes the part file.
TEST(PartFile, MovesInPlaceOnCommitAndLeavesNothingOtherwise) {
    namespace fs = std::filesystem;
    const travel_test::TempDir tmp("travel_test_part_file");
    const std::string path = tmp.file("out.bin");
    {
        travel::PartFile file(path);
        EXPECT_EQ(file.part(), path + ".part");
        std::ofstream(file.part()) << "complete";
        file.commit();
    }
    EXPECT_TRUE(fs::is_regular_file(path));
    EXPECT_FALSE(fs::exists(path + ".part"));

    const std::string failed = tmp.file("failed.bin");
    try {
        travel::PartFile file(failed);
        std::ofstream(file.part()) << "half";
        throw std::runtime_error("write error");
    } catch (const std::runtime_error&) {
    }
    EXPECT_FALSE(fs::exists(failed));
    EXPECT_FALSE(fs::exists(failed + ".part"));

    const std::string folder = tmp.file("folder");
    fs::create_directories(folder + "/inside");
    travel::PartFile file(folder);
    std::ofstream(file.part()) << "complete";
    try {
        file.commit();
        ADD_FAILURE() << "moving onto a non-empty folder did not throw";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(folder + ": cannot write"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(folder + ".part"));
    EXPECT_TRUE(fs::is_directory(folder + "/inside"));
}

// writeThroughPartFile: a write cut by a file size limit (as by a full disk), at the close or
// before, is an error naming the file and the reason; the previous file stays as it was and no
// part file is left. An exception of the writer's goes on as it is.
TEST(PartFile, AFailedWriteKeepsThePreviousFile) {
    const TempDir tmp("travel_test_part_write");
    const std::string path = tmp.write("report.md", "previous\n");
    const auto contents = [&] {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const auto errorOf = [&](const std::function<void(std::ostream&)>& write) -> std::string {
        try {
            travel::writeThroughPartFile(path, write);
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "no error";
    };
    // 100 bytes stay in the stream's buffer until the close; 1 MiB fail while being written.
    for (const std::size_t size : {std::size_t(100), std::size_t(1) << 20}) {
        std::string message;
        {
            const travel_test::FileSizeLimit limit(10);
            message = errorOf([&](std::ostream& out) { out << std::string(size, 'x'); });
        }
        EXPECT_EQ(message, path + ": cannot write (File too large)") << size;
        EXPECT_EQ(contents(), "previous\n") << size;
        EXPECT_FALSE(fs::exists(path + ".part")) << size;
    }
    EXPECT_EQ(errorOf([](std::ostream& out) {
                  out << "half";
                  throw std::runtime_error("no more rows");
              }),
              "no more rows");
    EXPECT_EQ(contents(), "previous\n");
    EXPECT_FALSE(fs::exists(path + ".part"));
    EXPECT_EQ(errorOf([](std::ostream& out) { out << "complete\n"; }), "no error");
    EXPECT_EQ(contents(), "complete\n");
    EXPECT_FALSE(fs::exists(path + ".part"));
}

// Moving a file over a symbolic link replaces the link, over a device the device (as root,
// /dev/null for the whole machine): both are refused, and left as they were. A FIFO stands for
// the device here.
TEST(PartFile, LinksAndDevicesAreRefusedAndLeftAlone) {
    namespace fs = std::filesystem;
    const TempDir tmp("travel_test_part_links");
    const std::string target = tmp.file("target.csv"), link = tmp.file("link.csv");
    const std::string fifo = tmp.file("fifo"), dangling = tmp.file("dangling.csv");
    std::ofstream(target) << "previous\n";
    fs::create_symlink(target, link);
    fs::create_symlink(tmp.file("missing/x.csv"), dangling);
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const auto errorOf = [](const std::string& path) -> std::string {
        try {
            travel::writeThroughPartFile(path, [](std::ostream& out) { out << "new\n"; });
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "no error";
    };
    const std::string link_reason =
        ": cannot write (a symbolic link; give the name of the file "
        "it points at)";
    EXPECT_EQ(errorOf(link), link + link_reason);
    EXPECT_EQ(errorOf(dangling), dangling + link_reason);
    EXPECT_EQ(errorOf(fifo),
              fifo + ": cannot write (not a regular file (a device, FIFO or socket))");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_symlink(dangling));
    EXPECT_TRUE(fs::is_fifo(fifo));
    std::ifstream in(target);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
              "previous\n");
    for (const std::string& name : {link, dangling, fifo, target})
        EXPECT_FALSE(fs::exists(name + ".part")) << name;
}

// A picture's part file keeps the extension: OpenCV tells the format by it.
TEST(PartFile, PictureNamesKeepTheirExtension) {
    using Name = travel::PartFile::Name;
    EXPECT_EQ(travel::PartFile::partOf("/out/x.png", Name::BeforeExtension), "/out/x.part.png");
    EXPECT_EQ(travel::PartFile::partOf("/out.d/x", Name::BeforeExtension), "/out.d/x.part");
    EXPECT_EQ(travel::PartFile::partOf("/out/x.png"), "/out/x.png.part");
    const travel::PartFile file("/nowhere/x.jpg", Name::BeforeExtension);
    EXPECT_EQ(file.part(), "/nowhere/x.part.jpg");
}
