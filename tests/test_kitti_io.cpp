// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "TempDir.hpp"
#include "travel/Errors.hpp"
#include "travel/eval/KittiIO.hpp"

namespace fs = std::filesystem;
using travel::InputError;
using travel::PointClass;
using travel::PointCloud;

namespace {

template <class F>
std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

#define EXPECT_CONTAINS(haystack, needle) \
    EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

using travel_test::TempDir;

PointCloud sampleCloud() {
    PointCloud c;
    c.push_back(1.f, 2.f, 3.f, 0.5f);
    c.push_back(-10.25f, 0.f, -1.73f, 0.f);
    c.push_back(1e-3f, 80.f, 1e6f, 1.f);
    return c;
}

}  // namespace

TEST(KittiIO, BinRoundTrip) {
    TempDir dir;
    const PointCloud written = sampleCloud();
    travel::writeKittiBin(dir.file("a.bin"), written);
    EXPECT_EQ(fs::file_size(dir.file("a.bin")), 3u * 16u);

    PointCloud read;
    read.ring = {1, 2, 3};  // stale optional fields are cleared
    read.time = {0.f, 0.f, 0.f};
    travel::readScan(dir.file("a.bin"), read, travel::ScanFormat::KittiBin);
    EXPECT_EQ(read.x, written.x);
    EXPECT_EQ(read.y, written.y);
    EXPECT_EQ(read.z, written.z);
    EXPECT_EQ(read.intensity, written.intensity);
    EXPECT_TRUE(read.ring.empty());
    EXPECT_TRUE(read.time.empty());
}

TEST(KittiIO, LittleEndianLayout) {
    TempDir dir;
    const std::string path = dir.writeFloats("b.bin", {1.f, 2.f, 3.f, 4.f, 5.f, 6.f, 7.f, 8.f});
    PointCloud c;
    travel::readScan(path, c, travel::ScanFormat::KittiBin);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c.x[1], 5.f);
    EXPECT_EQ(c.y[1], 6.f);
    EXPECT_EQ(c.z[1], 7.f);
    EXPECT_EQ(c.intensity[1], 8.f);
}

TEST(KittiIO, ReusesCloudForSmallerFrames) {
    TempDir dir;
    travel::writeKittiBin(dir.file("big.bin"), sampleCloud());
    PointCloud small;
    small.push_back(0.f, 0.f, 0.f);
    travel::writeKittiBin(dir.file("small.bin"), small);
    PointCloud c;
    travel::readScan(dir.file("big.bin"), c, travel::ScanFormat::KittiBin);
    travel::readScan(dir.file("small.bin"), c, travel::ScanFormat::KittiBin);
    EXPECT_EQ(c.size(), 1u);
    EXPECT_EQ(c.intensity.size(), 1u);
}

TEST(KittiIO, SizeNotMultipleOf16) {
    TempDir dir;
    const std::string path = dir.writeBytes("bad.bin", std::vector<unsigned char>(33, 0));
    PointCloud c;
    const std::string msg =
        inputErrorOf([&] { travel::readScan(path, c, travel::ScanFormat::KittiBin); });
    EXPECT_CONTAINS(msg, path);
    EXPECT_CONTAINS(msg, "33");
    EXPECT_CONTAINS(msg, "16");
    EXPECT_CONTAINS(msg, "1 bytes left over");
}

TEST(KittiIO, EmptyFileIsAnError) {
    TempDir dir;
    const std::string path = dir.writeBytes("empty.bin", {});
    PointCloud c = sampleCloud();
    EXPECT_EQ(inputErrorOf([&] { travel::readScan(path, c, travel::ScanFormat::KittiBin); }),
              path + ": 0 bytes, not a scan");
}

TEST(KittiIO, MissingFileOrDirectory) {
    TempDir dir;
    PointCloud c;
    const std::string missing = dir.file("missing.bin");
    EXPECT_CONTAINS(
        inputErrorOf([&] { travel::readScan(missing, c, travel::ScanFormat::KittiBin); }), missing);
    EXPECT_CONTAINS(
        inputErrorOf([&] { travel::readScan(dir.path.string(), c, travel::ScanFormat::KittiBin); }),
        "directory");
    EXPECT_CONTAINS(inputErrorOf([&] { travel::readLabelFile(missing, 0); }), missing);
}

TEST(KittiIO, XYZIRReadsRing) {
    TempDir dir;
    const std::string path =
        dir.writeFloats("n.bin", {1.f, 2.f, 3.f, 4.f, 0.f, 5.f, 6.f, 7.f, 8.f, 31.f});
    PointCloud c;
    c.time = {1.f};
    travel::readScan(path, c, travel::ScanFormat::NuScenesBin);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_TRUE(c.hasRing());
    EXPECT_TRUE(c.time.empty());
    EXPECT_EQ(c.ring[0], 0);
    EXPECT_EQ(c.ring[1], 31);
    EXPECT_EQ(c.intensity[1], 8.f);

    // KITTI files (16-byte records) are rejected unless the size happens to fit.
    const std::string kitti = dir.writeFloats("k.bin", {1.f, 2.f, 3.f, 4.f});
    EXPECT_CONTAINS(
        inputErrorOf([&] { travel::readScan(kitti, c, travel::ScanFormat::NuScenesBin); }), "20");
    const std::string bad_ring = dir.writeFloats("r.bin", {1.f, 2.f, 3.f, 4.f, 0.25f});
    EXPECT_CONTAINS(
        inputErrorOf([&] { travel::readScan(bad_ring, c, travel::ScanFormat::NuScenesBin); }),
        "ring");
}

TEST(KittiIO, LabelsRoundTripAndCount) {
    TempDir dir;
    const std::vector<uint32_t> labels = {0u, 40u, 72u | (7u << 16), 0xFFFFFFFFu};
    travel::writeLabelFile(dir.file("a.label"), labels);
    EXPECT_EQ(travel::readLabelFile(dir.file("a.label"), 4), labels);
    EXPECT_EQ(travel::readLabelFile(dir.file("a.label"), travel::kAnyLabelCount), labels);

    const std::string msg = inputErrorOf([&] { travel::readLabelFile(dir.file("a.label"), 5); });
    EXPECT_CONTAINS(msg, dir.file("a.label"));
    EXPECT_CONTAINS(msg, "4 labels");
    EXPECT_CONTAINS(msg, "5");

    const std::string odd = dir.writeBytes("odd.label", {1, 2, 3, 4, 5, 6});
    const std::string odd_msg = inputErrorOf([&] { travel::readLabelFile(odd, 1); });
    EXPECT_CONTAINS(odd_msg, odd);
    EXPECT_CONTAINS(odd_msg, "multiple of 4");

    travel::writeLabelFile(dir.file("empty.label"), {});
    EXPECT_TRUE(travel::readLabelFile(dir.file("empty.label"), 0).empty());
}

TEST(KittiIO, WriteFailureThrows) {
    TempDir dir;
    const fs::path missing = dir.path / "no/such/dir";  // dir.file() would create it
    EXPECT_THROW(travel::writeLabelFile((missing / "a.label").string(), {1u}), std::runtime_error);
    EXPECT_THROW(travel::writeKittiBin((missing / "a.bin").string(), sampleCloud()),
                 std::runtime_error);
    PointCloud inconsistent = sampleCloud();
    inconsistent.z.pop_back();
    EXPECT_THROW(travel::writeKittiBin(dir.file("x.bin"), inconsistent), std::invalid_argument);
}

TEST(KittiIO, EncodeLabel) {
    EXPECT_EQ(travel::encodeLabel(PointClass::Ground, 0), 1u);
    EXPECT_EQ(travel::encodeLabel(PointClass::Outlier, 5), (5u << 16) | 3u);
    EXPECT_EQ(travel::encodeLabel(PointClass::NonGround, 0xFFFF), (0xFFFFu << 16) | 2u);
    // Large ids wrap into [1, 0xFFFF], never to 0 (= no cluster).
    EXPECT_EQ(travel::labelClusterId(travel::encodeLabel(PointClass::NonGround, 0x10000)), 1u);
    EXPECT_EQ(travel::labelClusterId(travel::encodeLabel(PointClass::NonGround, 0x1FFFE)), 0xFFFFu);
    EXPECT_EQ(travel::labelClusterId(travel::encodeLabel(PointClass::NonGround, 0xFFFFFFFF)),
              ((0xFFFFFFFFu - 1u) % 0xFFFFu) + 1u);
    EXPECT_NE(travel::labelClusterId(travel::encodeLabel(PointClass::NonGround, 0x1FFFF)), 0u);
    EXPECT_EQ(travel::labelClassBits(travel::encodeLabel(PointClass::Invalid, 0x12345)), 0u);
}

TEST(KittiIO, ListFiles) {
    TempDir dir;
    for (const char* name : {"000002.bin", "000000.bin", "000001.bin", "000000.label", "notes"}) {
        dir.writeBytes(name, {});
    }
    fs::create_directories(dir.path / "sub.bin");  // directories are skipped
    const auto bins = travel::listFiles(dir.path.string(), "bin");
    ASSERT_EQ(bins.size(), 3u);
    EXPECT_EQ(bins[0], dir.file("000000.bin"));
    EXPECT_EQ(bins[2], dir.file("000002.bin"));
    EXPECT_EQ(travel::listFiles(dir.path.string(), ".label").size(), 1u);
    EXPECT_EQ(travel::listFiles(dir.path.string(), "").size(), 5u);
    EXPECT_CONTAINS(inputErrorOf([&] { travel::listFiles(dir.file("nope"), "bin"); }),
                    dir.file("nope"));
    EXPECT_CONTAINS(inputErrorOf([&] { travel::listFiles(dir.file("notes"), "bin"); }),
                    "not a directory");
}

TEST(ScanList, FileFolderAndSequence) {
    TempDir dir;
    fs::create_directories(dir.path / "seq" / "velodyne");
    fs::create_directories(dir.path / "seq" / "labels");
    fs::create_directories(dir.path / "pcds");
    for (const char* name : {"seq/velodyne/000001.bin", "seq/velodyne/000000.bin", "pcds/b.ply",
                             "pcds/a.pcd", "pcds/notes.txt"})
        dir.writeBytes(name, {});
    // A sequence folder: its velodyne/ scans, in order, and its labels/.
    const travel::ScanList seq = travel::listScans(dir.file("seq"));
    ASSERT_EQ(seq.files.size(), 2u);
    EXPECT_EQ(seq.files[0], dir.file("seq/velodyne/000000.bin"));
    EXPECT_EQ(seq.labels_dir, dir.file("seq/labels"));
    EXPECT_EQ(seq.sequence_dir, dir.file("seq"));
    // Its velodyne/ folder or one scan of it: the same labels.
    EXPECT_EQ(travel::listScans(dir.file("seq/velodyne")).labels_dir, dir.file("seq/labels"));
    const travel::ScanList one = travel::listScans(dir.file("seq/velodyne/000001.bin"));
    ASSERT_EQ(one.files.size(), 1u);
    EXPECT_EQ(one.labels_dir, dir.file("seq/labels"));
    // A folder of PCD and PLY scans: both with auto, one kind with a format; no labels.
    const travel::ScanList pcds = travel::listScans(dir.file("pcds"));
    ASSERT_EQ(pcds.files.size(), 2u);
    EXPECT_EQ(pcds.files[0], dir.file("pcds/a.pcd"));
    EXPECT_TRUE(pcds.labels_dir.empty());
    EXPECT_EQ(travel::listScans(dir.file("pcds"), travel::ScanFormat::Ply).files.size(), 1u);
    // Nothing to read: the error names the folder or path.
    EXPECT_CONTAINS(inputErrorOf([&] { travel::listScans(dir.file("seq/labels")); }),
                    "no scans (.bin, .pcd, .ply)");
    EXPECT_CONTAINS(inputErrorOf([&] { travel::listScans(dir.file("nope")); }), dir.file("nope"));
    // A scan's symlink to a missing file is named (it was skipped: a frame silently missing);
    // a dangling link that is no scan is left alone.
    fs::create_symlink(dir.file("elsewhere/notes.md"), dir.path / "pcds" / "README.md");
    EXPECT_EQ(travel::listScans(dir.file("pcds")).files.size(), 2u);
    fs::create_symlink(dir.file("elsewhere/000002.bin"),
                       dir.path / "seq" / "velodyne" / "000002.bin");
    const std::string dangling = inputErrorOf([&] { travel::listScans(dir.file("seq")); });
    EXPECT_CONTAINS(dangling, "000002.bin' is a symlink to a missing file");
    EXPECT_CONTAINS(dangling, "elsewhere/000002.bin");
}

TEST(ScanList, ExtensionRuleIsCaseInsensitive) {
    EXPECT_TRUE(travel::isScanPath("a/000000.bin"));
    EXPECT_TRUE(travel::isScanPath("a/000000.BIN"));
    EXPECT_TRUE(travel::isScanPath("scan.Pcd"));
    EXPECT_TRUE(travel::isScanPath("scan.ply", travel::ScanFormat::Ply));
    EXPECT_FALSE(travel::isScanPath("scan.ply", travel::ScanFormat::KittiBin));
    EXPECT_FALSE(travel::isScanPath("drive.rawlog"));
    EXPECT_FALSE(travel::isScanPath("sequences/00"));
    TempDir dir;
    fs::create_directories(dir.path / "upper");
    dir.writeBytes("upper/000000.BIN", {});
    dir.writeBytes("upper/000001.bin", {});
    EXPECT_EQ(travel::listScans(dir.file("upper")).files.size(), 2u);
}

// Outputs are named by stem: 000000.bin and 000000.pcd in one folder would both write
// 000000.label; auto stops and suggests --format, a format picks one kind.
TEST(ScanList, DuplicateStemIsAnError) {
    TempDir dir;
    fs::create_directories(dir.path / "mixed");
    for (const char* name : {"mixed/000000.bin", "mixed/000000.pcd", "mixed/000001.bin"})
        dir.writeBytes(name, {});
    const std::string error = inputErrorOf([&] { travel::listScans(dir.file("mixed")); });
    EXPECT_CONTAINS(error, "000000.bin and 000000.pcd");
    EXPECT_CONTAINS(error, "--format");
    EXPECT_CONTAINS(error, dir.file("mixed"));
    EXPECT_EQ(travel::listScans(dir.file("mixed"), travel::ScanFormat::KittiBin).files.size(), 2u);
    EXPECT_EQ(travel::listScans(dir.file("mixed"), travel::ScanFormat::Pcd).files.size(), 1u);
}
