// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel_mrpt::RawlogReader and RawlogMotion, the rawlog reading of travel-rawlog and
// travel-map: records of both formats, the exact error messages (file, record, what), and the
// robot pose from odometry actions and odometry observations.
#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "travel/Errors.hpp"
#include "travel/io/BinaryFile.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/GzFileOutput.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/Registration.hpp"
#include "travel_mrpt/TravelFilter.hpp"
#include "travel_mrpt/TravelLabelsReader.hpp"

namespace fs = std::filesystem;

namespace travel_mrpt {
namespace {

// One directory per process: ctest runs the tests of this file in parallel processes.
std::string testPath(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("travel_test_rawlog_reader_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return (dir / name).string();
}

mrpt::obs::CObservationOdometry::Ptr odometry(double x) {
    auto odo = mrpt::obs::CObservationOdometry::Create();
    odo->odometry = mrpt::poses::CPose2D(x, 0, 0);
    odo->sensorLabel = "odometry";
    return odo;
}

mrpt::obs::CActionCollection::Ptr moveBy(double dx, mrpt::Clock::time_point t = INVALID_TIMESTAMP) {
    mrpt::obs::CActionRobotMovement2D move;
    move.computeFromOdometry(mrpt::poses::CPose2D(dx, 0, 0),
                             mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
    move.timestamp = t;
    auto actions = mrpt::obs::CActionCollection::Create();
    actions->insert(move);
    return actions;
}

/// An observation-format rawlog of three odometry records (plain, not gzip); returns the file
/// offset where each record ends.
std::vector<std::size_t> writeOdometryRawlog(const std::string& path) {
    std::vector<std::size_t> ends;
    mrpt::io::CFileOutputStream file(path);
    auto out = mrpt::serialization::archiveFrom(file);
    for (int k = 0; k < 3; ++k) {
        out << *odometry(k);
        ends.push_back(file.getPosition());
    }
    return ends;
}

std::string errorOf(const std::string& path) {
    try {
        RawlogReader reader(path);
        while (reader.next()) {
        }
    } catch (const travel::InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(RawlogReader, ReadsEveryRecordThenEndOfFile) {
    const std::string path = testPath("odometry.rawlog");
    writeOdometryRawlog(path);
    RawlogReader reader(path);
    for (int k = 0; k < 3; ++k) {
        const auto record = reader.next();
        ASSERT_TRUE(record) << k;
        EXPECT_TRUE(std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(record));
        EXPECT_EQ(reader.index(), k + 1);
    }
    EXPECT_FALSE(reader.next());
    EXPECT_EQ(reader.index(), 3);
}

TEST(RawlogReader, TruncatedRecordIsNamed) {
    const std::string path = testPath("odometry.rawlog");
    const std::vector<std::size_t> ends = writeOdometryRawlog(path);
    const std::string cut = testPath("cut.rawlog");
    fs::copy_file(path, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, (ends[1] + ends[2]) / 2);  // inside record 2
    EXPECT_EQ(errorOf(cut), cut + ": record 2: truncated (end of file inside the record)");
}

/// A labelled gzip rawlog as travel-rawlog writes them: an odometry record, then a SensoryFrame
/// holding a CObservationTravelLabels of n points, then a bare one.
void writeLabelledRawlog(const std::string& path, std::size_t n) {
    registerClasses();
    mrpt::io::CFileGZOutputStream file(path);
    auto out = mrpt::serialization::archiveFrom(file);
    out << *odometry(0);
    auto labels = CObservationTravelLabels::Create();
    labels->sensorLabel = "lidar_travel";
    for (std::size_t i = 0; i < n; ++i) {
        // Varied values: the gzip stream must stay long enough to be cut inside the object.
        labels->x.push_back(0.37f * static_cast<float>(i % 977));
        labels->y.push_back(0.11f * static_cast<float>(i % 331));
        labels->z.push_back(0.01f * static_cast<float>(i % 97));
        labels->intensity.push_back(static_cast<float>(i % 251));
        labels->labels.push_back(static_cast<uint8_t>(i % 4));
        labels->clusterId.push_back(0);
    }
    mrpt::obs::CSensoryFrame sf;
    sf.insert(labels);
    out << sf;
    auto second = CObservationTravelLabels::Create();
    second->sensorLabel = "lidar2_travel";
    out << *second;
}

TEST(TravelLabelsReader, ReadsLabelsFromBothFormats) {
    const std::string path = testPath("labelled.rawlog");
    writeLabelledRawlog(path, 100);
    TravelLabelsReader reader(path);
    const auto first = reader.next();
    ASSERT_TRUE(first);
    EXPECT_EQ(first->sensorLabel, "lidar_travel");
    EXPECT_EQ(first->size(), 100u);
    const auto second = reader.next();
    ASSERT_TRUE(second);
    EXPECT_EQ(second->sensorLabel, "lidar2_travel");
    EXPECT_FALSE(reader.next());
    EXPECT_EQ(reader.count(), 2u);
}

TEST(RawlogReader, TruncatedLabelledGzipRecordIsNamed) {
    // The labels object reads its own bytes: a cut inside it is still "truncated".
    const std::string path = testPath("labelled_full.rawlog");
    writeLabelledRawlog(path, 200000);
    const std::string cut = testPath("labelled_cut.rawlog");
    fs::copy_file(path, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, fs::file_size(path) / 2);
    EXPECT_EQ(errorOf(cut), cut + ": record 1: truncated (end of file inside the record)");
}

TEST(RawlogReader, NotARawlog) {
    const std::string path = testPath("text.rawlog");
    std::ofstream(path) << "hello, I am text\n";
    const std::string error = errorOf(path);
    const std::string expected = path + ": record 0: cannot read (is it an MRPT rawlog?): ";
    EXPECT_EQ(error.substr(0, expected.size()), expected) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;  // MRPT's message on one line
}

// A corrupt record's class name (MRPT quotes it) with a terminal escape sequence in it: the
// message carries \x1B for the escape byte, not the sequence (ESC [2J clears the screen).
TEST(RawlogReader, ControlCharactersReadFromTheFileAreNotPassedOn) {
    const std::string path = testPath("escape.rawlog");
    // MRPT's object header: 0x80 | length of the class name, the name, then the object.
    std::ofstream(path, std::ios::binary) << std::string(
                                                 "\x85"
                                                 "A\x1b[2J") +
                                                 std::string(11, '\0');
    const std::string error = errorOf(path);
    EXPECT_NE(error.find("class 'A\\x1B[2J'"), std::string::npos) << error;
    EXPECT_EQ(error.find('\x1b'), std::string::npos) << error;
}

// The writer of every gzip output (rawlogs, .travelmap, .gridmap.gz, .travelgrid): a write
// that fails and a file cut short at close (zlib flushes its last bytes there; MRPT's
// CFileGZOutputStream ignores that failure, so a full disk gave a truncated file and no error)
// are errors naming the file. /dev/full fails every write with ENOSPC.
TEST(GzFileOutput, FailuresOfAFullDiskNameTheFile) {
    // Written and read back; the gzip trailer holds the uncompressed size.
    const std::string path = testPath("gz_output.bin");
    {
        travel_mrpt::GzFileOutput out(path);
        auto archive = mrpt::serialization::archiveFrom(out);
        archive << std::string("TRAVEL") << uint32_t(7);
        out.close();
        EXPECT_TRUE(travel::gzipEndsWithSize(path, out.getPosition()));
        EXPECT_FALSE(travel::gzipEndsWithSize(path, out.getPosition() + 1));
    }
    {
        mrpt::io::CFileGZInputStream in(path);
        std::string text;
        uint32_t value = 0;
        auto archive = mrpt::serialization::archiveFrom(in);
        archive >> text >> value;
        EXPECT_EQ(text, "TRAVEL");
        EXPECT_EQ(value, 7u);
    }
    if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    const auto errorOf = [](std::size_t bytes) -> std::string {
        try {
            travel_mrpt::GzFileOutput out("/dev/full", "site.travelgrid");
            const std::vector<uint32_t> data(bytes / 4, 0x12345u);
            for (uint32_t k = 0; k < data.size(); ++k) {
                const uint32_t v = data[k] * k;  // not all alike: zlib has to write
                out.Write(&v, sizeof(v));
            }
            out.close();
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "no error";
    };
    // A few bytes stay in zlib's buffer until close(); many fail while being written.
    EXPECT_EQ(errorOf(100),
              "site.travelgrid: cannot write (the file ends before its gzip "
              "trailer: disk full?)");
    EXPECT_EQ(errorOf(4 << 20), "site.travelgrid: cannot write (No space left on device)");
}

TEST(RawlogReader, EmptyFile) {
    const std::string path = testPath("empty.rawlog");
    std::ofstream{path};
    EXPECT_EQ(errorOf(path), path + ": empty file, not a rawlog");
}

TEST(RawlogReader, MissingFileAndDirectory) {
    const std::string missing = testPath("missing.rawlog");
    EXPECT_EQ(errorOf(missing), missing + ": no such file");
    const std::string dir = fs::path(testPath("x")).parent_path().string();
    EXPECT_EQ(errorOf(dir), dir + ": is a directory, not a rawlog");
}

TEST(RawlogMotion, PoseFromActionsElseOdometry) {
    TravelFilter filter;
    RawlogMotion motion(filter);
    EXPECT_FALSE(motion.robotPose());
    EXPECT_FALSE(motion.process(mrpt::obs::CSensoryFrame()));  // not a motion record

    EXPECT_TRUE(motion.process(*odometry(2.0)));
    ASSERT_TRUE(motion.robotPose());
    EXPECT_NEAR(motion.robotPose()->x(), 2.0, 1e-9);
    EXPECT_TRUE(motion.hasOdometry());

    // Odometry actions take precedence once there are any: composed from the identity.
    EXPECT_TRUE(motion.process(*moveBy(0.5)));
    EXPECT_TRUE(motion.process(*moveBy(0.25)));
    EXPECT_EQ(motion.actions(), 2u);
    EXPECT_NEAR(motion.robotPose()->x(), 0.75, 1e-6);
}

// A point cloud stored outside the rawlog, in "<name>_Images/" (as MRPT's tools write it): read
// from there whatever the working directory, and a missing file names itself and the folder.
TEST(RawlogReader, ExternallyStoredCloudsAreReadFromTheImagesFolder) {
    const std::string path = testPath("ext.rawlog");
    const std::string images = testPath("ext_Images");
    fs::create_directories(images);
    {
        mrpt::img::CImage::setImagesPathBase(images);
        auto cloud = mrpt::obs::CObservationPointCloud::Create();
        cloud->sensorLabel = "EXT";
        cloud->pointcloud = mrpt::maps::CSimplePointsMap::Create();
        for (int k = 0; k < 10; ++k) cloud->pointcloud->insertPoint(float(k), 1.f, -1.f);
        cloud->setAsExternalStorage(
            "cloud.bin",
            mrpt::obs::CObservationPointCloud::ExternalStorageFormat::MRPT_Serialization);
        cloud->unload();
        mrpt::io::CFileGZOutputStream file(path);
        mrpt::serialization::archiveFrom(file) << *cloud;
    }
    mrpt::img::CImage::setImagesPathBase("/nonexistent");  // what a fresh process has: "."
    const auto read = [&](std::string& why) {
        RawlogReader reader(path);
        const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(reader.next());
        EXPECT_TRUE(obs);
        travel::PointCloud points;
        mrpt::poses::CPose3D sensor_pose;
        return obs && toTravelCloud(*obs, points, sensor_pose, &why) ? points.size() : 0u;
    };
    std::string why;
    EXPECT_EQ(read(why), 10u) << why;
    fs::remove(fs::path(images) / "cloud.bin");
    EXPECT_EQ(read(why), 0u);
    EXPECT_NE(why.find("externally stored"), std::string::npos) << why;
    EXPECT_NE(why.find("ext_Images"), std::string::npos) << why;
    EXPECT_NE(why.find("cloud.bin"), std::string::npos) << why;
}

// SensoryFrame rawlogs: timed odometry actions (increments without velocities, as most
// odometry gives) are a velocity source by pose differences, as CObservationOdometry records.
TEST(RawlogMotion, TimedActionsGiveVelocityByPoseDifferences) {
    TravelFilterOptions o;
    o.velocity_source = VelocitySource::Poses;
    TravelFilter filter(o);
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    RawlogMotion motion(filter);
    EXPECT_TRUE(motion.process(*moveBy(0.0, mrpt::Clock::fromDouble(10.0))));
    EXPECT_TRUE(motion.process(*moveBy(1.0, mrpt::Clock::fromDouble(10.1))));
    const auto m = filter.motionAt(mrpt::Clock::fromDouble(10.1));
    ASSERT_TRUE(m.linear_velocity);
    EXPECT_TRUE(m.linear_velocity->isApprox(Eigen::Vector3d(10, 0, 0), 1e-6))
        << m.linear_velocity->transpose();
    // Untimed actions still give the pose, never a velocity.
    TravelFilter untimed_filter(o);
    RawlogMotion untimed(untimed_filter);
    untimed.process(*moveBy(0.0));
    untimed.process(*moveBy(1.0));
    EXPECT_NEAR(untimed.robotPose()->x(), 1.0, 1e-6);
    EXPECT_FALSE(untimed_filter.motionAt(mrpt::Clock::fromDouble(10.1)).linear_velocity);
}

}  // namespace
}  // namespace travel_mrpt
