// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// TravelFilter: configuration (YAML, ini, files, presets, errors, round trip), equivalence with
// travel::Pipeline on MRPT's VLP-16 sample, buffer reuse, label selection, and the motion
// inputs (IMU, odometry, robot poses) turned into attitude and sensor-frame velocities.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/containers/yaml.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel_mrpt/Attitude.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace {

using travel_mrpt::TravelFilter;
using travel_mrpt::TravelFilterOptions;
using travel_mrpt::VelocitySource;

constexpr double kDeg = M_PI / 180.0;
const std::string kSampleRawlog = TRAVEL_MRPT_SAMPLE_VLP16_FOR_FILTER;
const std::string kSampleConfig =
    std::string(TRAVEL_SHARE_DIR_FOR_TESTS) + "/configs/mrpt_sample_vlp16.yaml";

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TravelFilterOptions fromYaml(const std::string& text) {
    TravelFilterOptions o;
    o.loadFromYaml(mrpt::containers::yaml::FromText(text));
    return o;
}

TravelFilterOptions fromIni(const std::string& text) {
    TravelFilterOptions o;
    mrpt::config::CConfigFileMemory ini(text);
    o.loadFromConfigFile(ini, "travel");
    return o;
}

std::string tempPath(const std::string& suffix) {
    return mrpt::system::getTempFileName() + suffix;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

Eigen::Matrix3d ypr(double yaw, double pitch, double roll) {
    return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

/// Roll/pitch only (yaw removed), to compare attitudes whose world yaw differs.
Eigen::Matrix3d levelPart(const Eigen::Matrix3d& R) {
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    return Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * R;
}

/// A filter configured like the README's demo (share/configs/mrpt_sample_vlp16.yaml), quiet.
void configureForSample(TravelFilter& filter) {
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    filter.loadConfigFile(kSampleConfig);
}

#define SKIP_WITHOUT_SAMPLE()                     \
    if (!mrpt::system::fileExists(kSampleRawlog)) \
    GTEST_SKIP() << kSampleRawlog << " not found (Debian package mrpt-common)"

mrpt::obs::CObservation::Ptr firstLidarOf(const std::string& path) {
    mrpt::io::CFileGZInputStream file(path);
    auto archive = mrpt::serialization::archiveFrom(file);
    mrpt::obs::CActionCollection::Ptr actions;
    mrpt::obs::CSensoryFrame::Ptr sf;
    mrpt::obs::CObservation::Ptr obs;
    std::size_t entry = 0;
    while (mrpt::obs::CRawlog::getActionObservationPairOrObservation(archive, actions, sf, obs,
                                                                     entry)) {
        if (obs && travel_mrpt::isLidarObservation(*obs)) return obs;
        if (sf)
            for (const auto& o : *sf)
                if (o && travel_mrpt::isLidarObservation(*o)) return o;
    }
    return nullptr;
}

/// A small VLP-16 range image (every return at 10 m) with per-point times.
mrpt::obs::CObservationRotatingScan::Ptr smallRotatingScan(const mrpt::poses::CPose3D& pose,
                                                           double t) {
    auto scan = mrpt::obs::CObservationRotatingScan::Create();
    scan->sensorLabel = "LIDAR";
    scan->lidarModel = "VLP16";
    scan->rowCount = 16;
    scan->columnCount = 64;
    scan->rangeResolution = 0.002;
    scan->rangeImage.setConstant(16, 64, 5000);
    scan->startAzimuth = 0;
    scan->azimuthSpan = 2 * M_PI;
    scan->sweepDuration = 0.1;
    scan->sensorPose = pose;
    scan->timestamp = mrpt::Clock::fromDouble(t);
    return scan;
}

// ---------------------------------------------------------------- configuration

TEST(TravelFilterOptions, LoadsYamlText) {
    const TravelFilterOptions o = fromYaml(
        "preset: vlp16\nsensor_height: 2.24\nground_dist: 0.2\nfilter:\n  sensor_label: VELO.*\n"
        "  use_sensor_pose: false\n  use_robot_attitude: no\n  velocity_source: imu\n"
        "  max_motion_age: 0.25\n");
    EXPECT_EQ(o.params.num_rings, 16);  // from the preset
    EXPECT_DOUBLE_EQ(o.params.sensor_height, 2.24);
    EXPECT_DOUBLE_EQ(o.params.ground_dist, 0.2);
    EXPECT_EQ(o.sensor_label, "VELO.*");
    EXPECT_FALSE(o.use_sensor_pose);
    EXPECT_FALSE(o.use_robot_attitude);
    EXPECT_EQ(o.velocity_source, VelocitySource::Imu);
    EXPECT_DOUBLE_EQ(o.max_motion_age, 0.25);
    // The same keys under a `travel:` map.
    const TravelFilterOptions wrapped = fromYaml("travel:\n  sensor_height: 1.1\n");
    EXPECT_DOUBLE_EQ(wrapped.params.sensor_height, 1.1);
    // Values that YAML would read as something else when unquoted keep their text.
    EXPECT_EQ(fromYaml("filter:\n  sensor_label: \"[A-Z]+: it's *\"\n").sensor_label,
              "[A-Z]+: it's *");
}

TEST(TravelFilterOptions, LoadsIniText) {
    const TravelFilterOptions o = fromIni(
        "[travel]\npreset = vlp16\nsensor_height = 2.24\nring_source = table\n"
        "velocity_source = poses\nuse_sensor_pose = false\n");
    EXPECT_EQ(o.params.num_rings, 16);
    EXPECT_DOUBLE_EQ(o.params.sensor_height, 2.24);
    EXPECT_EQ(o.params.ring_source, "table");
    EXPECT_EQ(o.velocity_source, VelocitySource::Poses);
    EXPECT_FALSE(o.use_sensor_pose);
}

TEST(TravelFilterOptions, PresetComesFirstWhereverWritten) {
    const travel::Params vlp16 = travel::loadPreset("vlp16");
    // The preset is written last but applied first: the explicit key wins.
    const TravelFilterOptions o = fromIni("[travel]\ntgf_resolution = 3.0\npreset = vlp16\n");
    EXPECT_DOUBLE_EQ(o.params.tgf_resolution, 3.0);
    EXPECT_DOUBLE_EQ(o.params.max_range, vlp16.max_range);  // untouched preset value
    EXPECT_EQ(o.params.elevation_table, "vlp16");
    // An MRPT YAML map has no key order: its preset is applied first too.
    const TravelFilterOptions y = fromYaml("tgf_resolution: 3.0\npreset: vlp16\n");
    EXPECT_EQ(travel::paramsToYaml(y.params), travel::paramsToYaml(o.params));
    EXPECT_NE(errorOf([] { fromYaml("preset: no_such_sensor\n"); }).find("no_such_sensor"),
              std::string::npos);
}

TEST(TravelFilterOptions, RejectsUnknownKeysNamingKeyAndSection) {
    const std::string yaml_error = errorOf([] { fromYaml("sensor_hieght: 2.0\n"); });
    EXPECT_NE(yaml_error.find("sensor_hieght"), std::string::npos) << yaml_error;
    EXPECT_NE(yaml_error.find("YAML"), std::string::npos) << yaml_error;
    const std::string ini_error = errorOf([] {
        TravelFilterOptions o;
        mrpt::config::CConfigFileMemory ini("[lidar_front]\nsensor_hieght = 2.0\n");
        o.loadFromConfigFile(ini, "lidar_front");
    });
    EXPECT_NE(ini_error.find("sensor_hieght"), std::string::npos) << ini_error;
    EXPECT_NE(ini_error.find("section 'lidar_front': "), std::string::npos) << ini_error;
    EXPECT_THROW(fromYaml("sensor_hieght: 2.0\n"), travel::ConfigError);
    // A filter key at the root (travel's keys) is named with its section.
    const std::string misplaced = errorOf([] { fromYaml("velocity_source: imu\n"); });
    EXPECT_NE(misplaced.find("is a key of section 'filter'"), std::string::npos) << misplaced;
}

TEST(TravelFilterOptions, RejectsBadValues) {
    const std::string range = errorOf([] { fromYaml("sensor_height: -1\n"); });
    EXPECT_NE(range.find("sensor_height"), std::string::npos) << range;
    const std::string cross = errorOf([] { fromYaml("min_range: 50\nmax_range: 10\n"); });
    EXPECT_NE(cross.find("min_range"), std::string::npos) << cross;
    const std::string choice = errorOf([] { fromYaml("filter:\n  velocity_source: fast\n"); });
    EXPECT_NE(choice.find("auto|imu|poses|none"), std::string::npos) << choice;
    const std::string regex = errorOf([] { fromYaml("filter:\n  sensor_label: \"(\"\n"); });
    EXPECT_NE(regex.find("sensor_label"), std::string::npos) << regex;
    EXPECT_NE(errorOf([] { fromIni("[travel]\nuse_sensor_pose = maybe\n"); }).find("maybe"),
              std::string::npos);
    // A failed load leaves the options as they were.
    TravelFilterOptions o;
    o.params.sensor_height = 1.23;
    EXPECT_ANY_THROW(
        o.loadFromYaml(mrpt::containers::yaml::FromText("sensor_height: 2.0\nbogus: 1\n")));
    EXPECT_DOUBLE_EQ(o.params.sensor_height, 1.23);
}

TEST(TravelFilterOptions, SaveThenLoadRoundTripsEveryKey) {
    TravelFilterOptions o;
    o.params = travel::loadPreset("vlp16");
    o.params.sensor_height = 2.24;
    o.params.tgf_resolution = 3.3;
    o.params.ground_dist = 0.1 + 0.02;  // not exactly representable as printed with %f
    o.params.ring_source = "table";
    o.params.ttmf = false;
    o.params.min_cluster_size = 17;
    o.sensor_label = "VLP.*";
    o.use_sensor_pose = false;
    o.use_robot_attitude = false;
    o.velocity_source = VelocitySource::Poses;
    o.max_motion_age = 0.25;
    o.track_objects = true;
    o.tracking.gate_distance = 3.5;
    o.tracking.max_misses = 7;

    mrpt::config::CConfigFileMemory written;
    o.saveToConfigFile(written, "travel");
    // Round trip through the text (reading the written object itself returns defaults).
    const std::string text = written.getContent();
    TravelFilterOptions back = fromIni(text);
    EXPECT_EQ(travel::paramsToYaml(back.params), travel::paramsToYaml(o.params));
    EXPECT_EQ(back.params.ground_dist, o.params.ground_dist);
    EXPECT_EQ(back.sensor_label, o.sensor_label);
    EXPECT_EQ(back.use_sensor_pose, o.use_sensor_pose);
    EXPECT_EQ(back.use_robot_attitude, o.use_robot_attitude);
    EXPECT_EQ(back.velocity_source, o.velocity_source);
    EXPECT_EQ(back.max_motion_age, o.max_motion_age);
    EXPECT_EQ(back.track_objects, o.track_objects);
    EXPECT_EQ(back.tracking.gate_distance, o.tracking.gate_distance);
    EXPECT_EQ(back.tracking.max_misses, o.tracking.max_misses);
    // Every libtravel key is written, plus the filter and tracking keys.
    std::vector<std::string> keys;
    mrpt::config::CConfigFileMemory(text).getAllKeys("travel", keys);
    std::size_t num_params = 0, num_filter = 0, num_tracking = 0;
    travel::visitParams(o.params, [&](auto&&...) { ++num_params; });
    travel::visitFields(static_cast<const travel::FilterSection&>(o),
                        [&](auto&&...) { ++num_filter; });
    travel::visitFields(o.tracking, [&](auto&&...) { ++num_tracking; });
    EXPECT_EQ(num_filter, 6u);
    EXPECT_EQ(keys.size(), num_params + num_filter + num_tracking);
}

TEST(TravelFilterOptions, LoadsFilesByExtensionAndNamesTheFile) {
    const std::string yaml = tempPath(".yaml"), ini = tempPath(".ini"), txt = tempPath(".txt");
    writeText(yaml, "preset: vlp16\nsensor_height: 2.24\nfilter:\n  sensor_label: VEL.*\n");
    writeText(ini,
              "[travel]\npreset = vlp16\nsensor_height = 2.24\n[filter]\nsensor_label = VEL.*\n");
    writeText(txt, "sensor_height: 2.24\n");
    TravelFilter from_yaml, from_ini;
    from_yaml.loadConfigFile(yaml);
    from_ini.loadConfigFile(ini);
    EXPECT_EQ(travel::paramsToYaml(from_yaml.options().params),
              travel::paramsToYaml(from_ini.options().params));
    EXPECT_EQ(from_yaml.options().sensor_label, "VEL.*");
    EXPECT_EQ(from_ini.options().sensor_label, "VEL.*");
    TravelFilter f;
    f.loadConfigFile(txt);  // the format is told by the contents, not the extension
    EXPECT_DOUBLE_EQ(f.options().params.sensor_height, 2.24);
    const std::string missing = tempPath("_missing.yaml");
    EXPECT_NE(errorOf([&] { f.loadConfigFile(missing); }).find(missing), std::string::npos);
    writeText(yaml, "sensor_height: 2.24\nnot_a_key: 1\n");
    const std::string bad = errorOf([&] { f.loadConfigFile(yaml); });
    EXPECT_NE(bad.find(yaml), std::string::npos) << bad;
    EXPECT_NE(bad.find("not_a_key"), std::string::npos) << bad;
    // initialize(yaml): the FilterBase idiom, same rules.
    EXPECT_THROW(f.initialize(mrpt::containers::yaml::FromText("not_a_key: 1\n")),
                 travel::ConfigError);
    f.initialize(mrpt::containers::yaml::FromText("sensor_height: 1.5\n"));
    EXPECT_DOUBLE_EQ(f.options().params.sensor_height, 1.5);
    for (const auto& p : {yaml, ini, txt}) std::remove(p.c_str());
}

// ---------------------------------------------------------------- LiDAR frames

TEST(TravelFilter, MatchesThePipelineOnTheVlp16Sample) {
    SKIP_WITHOUT_SAMPLE();
    const auto obs = firstLidarOf(kSampleRawlog);
    ASSERT_TRUE(obs);

    TravelFilter filter;
    configureForSample(filter);
    travel_mrpt::TravelFrame frame;
    std::string why;
    ASSERT_TRUE(filter.filter(*obs, frame, &why)) << why;
    EXPECT_FALSE(frame.levelled);  // no motion data in this rawlog
    EXPECT_FALSE(frame.deskewed);

    travel::Params params;
    travel::applyParamsFile(kSampleConfig, params);
    travel::PointCloud cloud;
    mrpt::poses::CPose3D sensor_pose;
    ASSERT_TRUE(travel_mrpt::toTravelCloud(*obs, cloud, sensor_pose));
    travel_mrpt::setMountFromSensorPose(sensor_pose, params);
    travel::Pipeline pipeline(params);
    travel::Result direct;
    pipeline.process(cloud, {}, direct);

    ASSERT_EQ(frame.result.labels.size(), direct.labels.size());
    EXPECT_EQ(frame.result.labels, direct.labels);
    EXPECT_EQ(frame.result.cluster_id, direct.cluster_id);
    EXPECT_EQ(frame.cloud.size(), 11305u);
    // Velodyne point times are seconds after obs.timestamp, within one sweep: the filter's
    // reference_time 0 (motion evaluated at obs.timestamp) matches them.
    ASSERT_TRUE(frame.cloud.hasTime());
    const auto [t_min, t_max] =
        std::minmax_element(frame.cloud.time.begin(), frame.cloud.time.end());
    std::printf("VLP-16 sample point times: %.4f .. %.4f s after obs.timestamp\n", *t_min, *t_max);
    EXPECT_GE(*t_min, -1e-3f);
    EXPECT_LE(*t_max, 0.25f);
    EXPECT_GT(frame.result.count(travel::PointClass::Ground), 2000u);
    ASSERT_NE(frame.aligned, nullptr);
    EXPECT_EQ(frame.aligned, &filter.aligned(obs->sensorLabel));
    EXPECT_EQ(frame.aligned->x.size(), frame.cloud.size());
    EXPECT_TRUE(frame.alignedRotation.isApprox(pipeline.aligned().rotation));
    EXPECT_THROW(filter.aligned("no such sensor"), std::out_of_range);
}

TEST(TravelFilter, ReusesItsBuffersFrameAfterFrame) {
    SKIP_WITHOUT_SAMPLE();
    const auto obs = firstLidarOf(kSampleRawlog);
    ASSERT_TRUE(obs);
    TravelFilter filter;
    configureForSample(filter);
    travel_mrpt::TravelFrame frame;
    ASSERT_TRUE(filter.filter(*obs, frame));
    ASSERT_TRUE(filter.filter(*obs, frame));  // warm
    const float* x = frame.cloud.x.data();
    const auto* labels = frame.result.labels.data();
    const auto* clusters = frame.result.cluster_id.data();
    const float* aligned_x = frame.aligned->x.data();
    const std::size_t capacity = frame.cloud.x.capacity();
    const auto first_labels = frame.result.labels;
    ASSERT_TRUE(filter.filter(*obs, frame));
    EXPECT_EQ(frame.cloud.x.data(), x);
    EXPECT_EQ(frame.result.labels.data(), labels);
    EXPECT_EQ(frame.result.cluster_id.data(), clusters);
    EXPECT_EQ(frame.aligned->x.data(), aligned_x);
    EXPECT_EQ(frame.cloud.x.capacity(), capacity);
    EXPECT_EQ(frame.result.labels, first_labels);  // and the same result
}

// One filter per thread (the supported way to use several cores or sensors): every thread gets
// the single-threaded labels and cluster ids, frame after frame. The observation is shared
// read-only. (ThreadSanitizer runs the libtravel version of this test in CI; MRPT's libraries
// are not instrumented, so this one runs in the plain and ASan builds.)
TEST(TravelFilter, OneFilterPerThreadGivesIdenticalResults) {
    SKIP_WITHOUT_SAMPLE();
    const auto obs = firstLidarOf(kSampleRawlog);
    ASSERT_TRUE(obs);
    TravelFilter reference_filter;
    configureForSample(reference_filter);
    travel_mrpt::TravelFrame reference;
    ASSERT_TRUE(reference_filter.filter(*obs, reference));

    constexpr int kThreads = 4, kFrames = 5;
    std::vector<int> identical(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            TravelFilter filter;
            configureForSample(filter);
            travel_mrpt::TravelFrame frame;
            for (int k = 0; k < kFrames; ++k)
                if (filter.filter(*obs, frame) && frame.result.labels == reference.result.labels &&
                    frame.result.cluster_id == reference.result.cluster_id)
                    ++identical[t];
        });
    for (auto& thread : threads) thread.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(identical[t], kFrames) << "thread " << t;
}

TEST(TravelFilter, SelectsSensorsByLabelRegex) {
    TravelFilterOptions o;
    o.sensor_label = "LIDAR_.*";
    TravelFilter filter(o);
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    travel_mrpt::TravelFrame frame;
    std::string why;
    auto scan = smallRotatingScan(mrpt::poses::CPose3D(), 100.0);
    scan->sensorLabel = "VELODYNE";
    EXPECT_FALSE(filter.filter(*scan, frame, &why));
    EXPECT_NE(why.find("does not match"), std::string::npos) << why;
    EXPECT_NE(why.find("VELODYNE"), std::string::npos) << why;
    scan->sensorLabel = "LIDAR_FRONT";
    EXPECT_TRUE(filter.filter(*scan, frame, &why)) << why;
    EXPECT_EQ(frame.sensorLabel, "LIDAR_FRONT");
    EXPECT_EQ(frame.cloud.size(), 16u * 64u);
    // Partial matches do not count: the whole label must match.
    scan->sensorLabel = "MY_LIDAR_FRONT";
    EXPECT_FALSE(filter.filter(*scan, frame, &why));
}

// A level sensor 1.73 m over flat ground whose sensorPose claims an 8 deg pitch: the mount
// angles come from that sensorPose, so the mismatch note must point there, not to
// mount_roll_deg / mount_pitch_deg (which the sensorPose overrides).
TEST(TravelFilter, TiltMismatchNamesTheSensorPose) {
    travel::PointCloud ground;
    for (float x = -30.f; x <= 30.f; x += 0.25f)
        for (float y = -30.f; y <= 30.f; y += 0.25f)
            ground.x.push_back(x), ground.y.push_back(y), ground.z.push_back(-1.73f);
    const auto noteFor = [&](bool use_sensor_pose) {
        TravelFilterOptions o;
        o.use_sensor_pose = use_sensor_pose;
        o.params.sensor_height = travel::AutoReal::makeAuto(0.5);  // fallback far off
        TravelFilter filter(o);
        filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
        travel_mrpt::TravelFrame frame;
        filter.filter(ground, mrpt::poses::CPose3D(0, 0, 0, 0, 8 * kDeg, 0), mrpt::Clock::now(),
                      "VELO", frame);
        // The result carries the estimated height (what the map fuses with), not 0.5.
        EXPECT_NEAR(frame.result.sensor_height, 1.73, 0.05);
        return frame.result.mount;
    };
    const travel::MountNote note = noteFor(true);
    EXPECT_NE(note.message.find("the sensorPose of 'VELO'"), std::string::npos) << note.message;
    EXPECT_NE(note.message.find("--ignore-sensor-pose"), std::string::npos) << note.message;
    EXPECT_EQ(note.message.find("set mount_roll_deg:"), std::string::npos) << note.message;
    // Ignoring the sensorPose: the level configured angles fit, nothing to say about them.
    EXPECT_EQ(noteFor(false).message.find("tilted"), std::string::npos);
}

TEST(TravelFilter, RefusesNonLidarAndEmptyObservations) {
    TravelFilter filter;
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    travel_mrpt::TravelFrame frame;
    std::string why;
    mrpt::obs::CObservationIMU imu;
    imu.sensorLabel = "IMU";
    EXPECT_FALSE(filter.filter(imu, frame, &why));
    EXPECT_NE(why.find("not a 3-D LiDAR"), std::string::npos) << why;
    EXPECT_NE(why.find("CObservationIMU"), std::string::npos) << why;
    auto empty = smallRotatingScan(mrpt::poses::CPose3D(), 1.0);
    empty->rangeImage.setZero(16, 64);
    EXPECT_FALSE(filter.filter(*empty, frame, &why));
    EXPECT_NE(why.find("without any return"), std::string::npos) << why;
    EXPECT_FALSE(filter.filter(imu, frame));  // why_not is optional
}

// A sensorPose with a NaN (a corrupt record, a driver's bug) is the observation's fault: refused
// with its label and why (the rawlog tools skip it and name the record), not a configuration
// error about mount_pitch_deg that ends the run.
TEST(TravelFilter, RefusesObservationsWithANonFiniteSensorPose) {
    TravelFilter filter;
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    travel_mrpt::TravelFrame frame;
    std::string why;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const mrpt::poses::CPose3D& pose :
         {mrpt::poses::CPose3D(0, 0, 1.8, nan, 0, 0), mrpt::poses::CPose3D(nan, 0, 1.8, 0, 0, 0)}) {
        auto scan = smallRotatingScan(pose, 1.0);
        EXPECT_FALSE(filter.filter(*scan, frame, &why));
        EXPECT_NE(why.find("'" + scan->sensorLabel + "': its sensorPose is not finite"),
                  std::string::npos)
            << why;
    }
    auto good = smallRotatingScan(mrpt::poses::CPose3D(0, 0, 1.8, 0, 0, 0), 1.0);
    EXPECT_TRUE(filter.filter(*good, frame, &why)) << why;
}

// travel-rawlog writes per-class clouds beside its labels ("<label>_ground" ...): reading such a
// rawlog back, they are no LiDAR frames (isLidarObservation, hence the filter and the map).
TEST(TravelFilter, SkipsTravelOutputClouds) {
    TravelFilter filter;
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    travel_mrpt::TravelFrame frame;
    std::string why;
    auto cloud = mrpt::obs::CObservationPointCloud::Create();
    cloud->pointcloud = mrpt::maps::CSimplePointsMap::Create();
    for (float x = -20.f; x <= 20.f; x += 0.5f)
        for (float y = -20.f; y <= 20.f; y += 0.5f) cloud->pointcloud->insertPoint(x, y, -1.73f);
    for (const char* label : {"velodyne_ground", "velodyne_nonground", "velodyne_outlier"}) {
        cloud->sensorLabel = label;
        EXPECT_FALSE(travel_mrpt::isLidarObservation(*cloud)) << label;
        EXPECT_FALSE(filter.filter(*cloud, frame, &why)) << label;
        EXPECT_NE(why.find("is a TRAVEL output"), std::string::npos) << why;
        EXPECT_NE(why.find(label), std::string::npos) << why;
    }
    cloud->sensorLabel = "velodyne";  // the same points from a sensor
    EXPECT_TRUE(travel_mrpt::isLidarObservation(*cloud));
    EXPECT_TRUE(filter.filter(*cloud, frame, &why)) << why;
}

// ---------------------------------------------------------------- motion inputs

// An IMU mounted yawed 90 deg on the robot: its quaternion and gyro are moved to the robot
// frame.
TEST(TravelFilterMotion, ImuAttitudeAndGyroInTheRobotFrame) {
    TravelFilter filter;
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    const double t = 50.0;
    const Eigen::Matrix3d world_R_robot = ypr(40 * kDeg, -3 * kDeg, 5 * kDeg);
    const Eigen::Matrix3d robot_R_imu = ypr(90 * kDeg, 0, 0);
    const Eigen::Vector3d w_robot(0.1, -0.2, 0.3);

    mrpt::obs::CObservationIMU imu;
    imu.timestamp = mrpt::Clock::fromDouble(t);
    imu.sensorPose = mrpt::poses::CPose3D(0.2, 0, 0.1, 90 * kDeg, 0, 0);
    const Eigen::Quaterniond q(world_R_robot * robot_R_imu);
    imu.set(mrpt::obs::IMU_ORI_QUAT_X, q.x());
    imu.set(mrpt::obs::IMU_ORI_QUAT_Y, q.y());
    imu.set(mrpt::obs::IMU_ORI_QUAT_Z, q.z());
    imu.set(mrpt::obs::IMU_ORI_QUAT_W, q.w());
    const Eigen::Vector3d w_imu = robot_R_imu.transpose() * w_robot;
    imu.set(mrpt::obs::IMU_WX, w_imu.x());
    imu.set(mrpt::obs::IMU_WY, w_imu.y());
    imu.set(mrpt::obs::IMU_WZ, w_imu.z());
    filter.processImu(imu);

    const auto m = filter.motionAt(mrpt::Clock::fromDouble(t));
    ASSERT_TRUE(m.attitude && m.angular_velocity);
    EXPECT_TRUE(levelPart(*m.attitude).isApprox(levelPart(world_R_robot), 1e-9));
    EXPECT_TRUE(m.angular_velocity->isApprox(w_robot, 1e-12));
    EXPECT_FALSE(m.linear_velocity);  // an IMU alone gives no linear velocity

    // Roll/pitch fields without yaw give the same roll/pitch.
    TravelFilter other;
    mrpt::obs::CObservationIMU rp;
    rp.timestamp = imu.timestamp;
    rp.set(mrpt::obs::IMU_ROLL, 5 * kDeg);
    rp.set(mrpt::obs::IMU_PITCH, -3 * kDeg);
    other.processImu(rp);
    const auto m2 = other.motionAt(imu.timestamp);
    ASSERT_TRUE(m2.attitude);
    EXPECT_TRUE(levelPart(*m2.attitude).isApprox(levelPart(world_R_robot), 1e-9));

    // Stale after max_motion_age (0.5 s); the attitude is carried by the gyro meanwhile.
    EXPECT_FALSE(filter.motionAt(mrpt::Clock::fromDouble(t + 0.6)).attitude);
    const auto later = filter.motionAt(mrpt::Clock::fromDouble(t + 0.1));
    ASSERT_TRUE(later.attitude);
    const Eigen::Matrix3d expected =
        world_R_robot * Eigen::AngleAxisd(0.1 * w_robot.norm(), w_robot.normalized());
    EXPECT_TRUE(later.attitude->isApprox(expected, 1e-9));
    filter.reset();
    EXPECT_FALSE(filter.motionAt(mrpt::Clock::fromDouble(t)).attitude);
}

// Odometry v = 10 m/s, yaw rate 0.5 rad/s; sensor at (1, 0.5, 1.8), yawed 90 deg:
// v_s = R^T (v + w x t) = Rz(90)^T (9.75, 0.5, 0) = (0.5, -9.75, 0), w_s = (0, 0, 0.5).
TEST(TravelFilterMotion, OdometryGivesSensorVelocityWithLeverArm) {
    TravelFilter filter;
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    const double t = 10.0;
    mrpt::obs::CObservationOdometry odometry;
    odometry.timestamp = mrpt::Clock::fromDouble(t - 0.01);
    odometry.odometry = mrpt::poses::CPose2D(3, 4, 0.2);
    odometry.hasVelocities = true;
    odometry.velocityLocal = mrpt::math::TTwist2D(10.0, 0.0, 0.5);
    filter.processOdometry(odometry);

    const mrpt::poses::CPose3D mount(1.0, 0.5, 1.8, 90 * kDeg, 0, 0);
    auto scan = smallRotatingScan(mount, t);
    travel_mrpt::TravelFrame frame;
    std::string why;
    ASSERT_TRUE(filter.filter(*scan, frame, &why)) << why;
    EXPECT_TRUE(frame.deskewed);
    EXPECT_FALSE(frame.levelled);  // odometry is planar: no attitude
    EXPECT_TRUE(frame.sensorLinearVelocity.isApprox(Eigen::Vector3d(0.5, -9.75, 0), 1e-9))
        << frame.sensorLinearVelocity.transpose();
    EXPECT_TRUE(frame.sensorAngularVelocity.isApprox(Eigen::Vector3d(0, 0, 0.5), 1e-9))
        << frame.sensorAngularVelocity.transpose();

    // A frame 1 s later: the odometry is stale, no deskew.
    auto late = smallRotatingScan(mount, t + 1.0);
    ASSERT_TRUE(filter.filter(*late, frame, &why)) << why;
    EXPECT_FALSE(frame.deskewed);
    // velocity_source none: never deskewed.
    TravelFilterOptions o;
    o.velocity_source = VelocitySource::None;
    TravelFilter none(o);
    none.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    none.processOdometry(odometry);
    ASSERT_TRUE(none.filter(*scan, frame, &why)) << why;
    EXPECT_FALSE(frame.deskewed);
}

// Two robot poses 0.1 s apart: velocity 10 m/s along the robot's x, yaw rate 0.5 rad/s, and the
// pose's roll/pitch as attitude; the IMU, when present, wins for the rates in `auto`.
TEST(TravelFilterMotion, RobotPosesGiveVelocityAndAttitude) {
    TravelFilterOptions o;
    o.velocity_source = VelocitySource::Poses;
    TravelFilter filter(o);
    filter.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    const double yaw0 = 0.3, roll = 4 * kDeg, pitch = -2 * kDeg;
    const mrpt::poses::CPose3D p0(0, 0, 0, yaw0, pitch, roll);
    // Move 1 m along the (levelled) robot x and yaw by 0.05 rad.
    const mrpt::poses::CPose3D p1(std::cos(yaw0), std::sin(yaw0), 0, yaw0 + 0.05, pitch, roll);
    filter.setRobotPose(p0, mrpt::Clock::fromDouble(20.0));
    filter.setRobotPose(p1, mrpt::Clock::fromDouble(20.1));
    const auto m = filter.motionAt(mrpt::Clock::fromDouble(20.1));
    ASSERT_TRUE(m.linear_velocity && m.angular_velocity && m.attitude);
    const Eigen::Matrix3d R1 = p1.getRotationMatrix().asEigen();
    const Eigen::Vector3d expected_v =
        R1.transpose() * Eigen::Vector3d(std::cos(yaw0), std::sin(yaw0), 0) / 0.1;
    EXPECT_TRUE(m.linear_velocity->isApprox(expected_v, 1e-9));
    EXPECT_NEAR(m.linear_velocity->norm(), 10.0, 1e-9);
    // A pure yaw change of 0.05 rad about world z, seen in the tilted robot frame.
    const Eigen::Vector3d expected_w =
        p1.getRotationMatrix().asEigen().transpose() * Eigen::Vector3d(0, 0, 0.5);
    EXPECT_TRUE(m.angular_velocity->isApprox(expected_w, 1e-3)) << m.angular_velocity->transpose();
    EXPECT_TRUE(levelPart(*m.attitude).isApprox(levelPart(R1), 1e-9));

    // The attitude from the pose levels the frame.
    auto scan = smallRotatingScan(mrpt::poses::CPose3D(), 20.1);
    travel_mrpt::TravelFrame frame;
    ASSERT_TRUE(filter.filter(*scan, frame));
    EXPECT_TRUE(frame.levelled);
    EXPECT_TRUE(frame.deskewed);
    EXPECT_TRUE(frame.alignedRotation.isApprox(levelPart(R1).cast<float>(), 1e-5f));
    // use_robot_attitude = false: not levelled.
    o.use_robot_attitude = false;
    TravelFilter flat(o);
    flat.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    flat.setRobotPose(p0, mrpt::Clock::fromDouble(20.0));
    flat.setRobotPose(p1, mrpt::Clock::fromDouble(20.1));
    ASSERT_TRUE(flat.filter(*scan, frame));
    EXPECT_FALSE(frame.levelled);
    EXPECT_TRUE(frame.alignedRotation.isIdentity(1e-6f));
}

}  // namespace

namespace {

// The shipped examples load and agree with each other.
TEST(TravelFilterOptions, ExampleConfigsLoadAndAgree) {
    const std::string dir = std::string(TRAVEL_SHARE_DIR_FOR_TESTS) + "/configs/";
    TravelFilter yaml, ini;
    yaml.loadConfigFile(dir + "travel_filter_example.yaml");
    ini.loadConfigFile(dir + "travel_filter_example.ini");
    EXPECT_EQ(travel::paramsToYaml(yaml.options().params),
              travel::paramsToYaml(ini.options().params));
    EXPECT_EQ(yaml.options().sensor_label, ".*");
    EXPECT_EQ(ini.options().sensor_label, ".*");
    EXPECT_DOUBLE_EQ(ini.options().params.sensor_height, 0.8);
    EXPECT_EQ(ini.options().velocity_source, VelocitySource::Auto);
    for (const TravelFilter* f : {&yaml, &ini}) {
        EXPECT_FALSE(f->options().track_objects);
        EXPECT_EQ(f->options().tracking.confirm_hits, 1);
        EXPECT_DOUBLE_EQ(f->options().tracking.gate_distance, 2.0);
    }
}

}  // namespace
