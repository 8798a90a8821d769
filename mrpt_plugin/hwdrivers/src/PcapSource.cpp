// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/PcapSource.hpp"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CVelodyneScanner.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/VelodyneCalibration.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "travel/Errors.hpp"
#include "travel/io/OpenFileOffset.hpp"
#include "travel/io/PcapFile.hpp"
#include "travel/io/VelodyneModels.hpp"

namespace fs = std::filesystem;
using mrpt::obs::CObservationVelodyneScan;
using mrpt::obs::VelodyneCalibration;

namespace travel_mrpt {
namespace {

/// Degrees (x100) swept by the frame's blocks: a full rotation is ~36000.
long azimuthCoverage(const CObservationVelodyneScan& scan) {
    long covered = 0;
    std::optional<uint16_t> previous;
    for (const auto& packet : scan.scan_packets)
        for (const auto& block : packet.blocks) {
            const uint16_t a = block.rotation();
            if (previous) covered += (a + 36000 - *previous) % 36000;
            previous = a;
        }
    return covered;
}

// A frame sweeping at least 350 degrees is a full rotation (the gap is one packet's sweep).
constexpr long kFullRotationCoverage = 35000;
constexpr double kMicrosecondsPerHour = 3600e6;

}  // namespace

std::string velodyneModelName(const std::string& name) {
    const auto model = travel::io::velodyneModelFor(name, 0);  // by name only
    return model ? model->name : std::string();
}

bool isPcapFile(const std::string& path) {
    return travel::io::isPcapFile(path);
}

struct PcapSource::Driver {
    mrpt::hwdrivers::CVelodyneScanner scanner;
    std::optional<mrpt::system::TTimeStamp> capture_start;
    std::optional<uint32_t> first_gps_us;              // the sensor clock at capture_start
    std::optional<travel::io::OpenFileOffset> offset;  // libpcap's, once it opened the file
};

PcapSource::PcapSource(const std::string& path, const PcapSourceOptions& options)
    : path_(path), options_(options), driver_(std::make_unique<Driver>()) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw travel::InputError(path + ": no such file");
    if (fs::is_directory(path, ec)) throw travel::InputError(path + ": is a directory, not a pcap");

    model_ = velodyneModelName(options.model);
    if (options.model.empty())
        throw travel::InputError(path + ": the Velodyne model of the capture is needed (" +
                                 kVelodynePcapModels + ")");
    if (model_.empty())
        throw travel::InputError(path + ": unknown Velodyne model '" + options.model +
                                 "' (allowed: " + kVelodynePcapModels + ")");

    VelodyneCalibration calibration;
    if (!options.calibration_file.empty()) {
        if (!fs::exists(options.calibration_file, ec))
            throw travel::InputError(options.calibration_file + ": no such file");
        if (!calibration.loadFromXMLFile(options.calibration_file) || calibration.empty())
            throw travel::InputError(options.calibration_file +
                                     ": cannot read as a Velodyne calibration XML (db.xml)");
    } else {
        // MRPT 2.5.8's HDL64 default is broken (an empty table and a stack trace on stderr):
        // not asked for.
        if (model_ != "HDL64") calibration = VelodyneCalibration::LoadDefaultCalibration(model_);
        if (calibration.empty())
            throw travel::InputError(
                path + ": no default calibration for " + model_ +
                " (MRPT 2.5.8's built-in HDL64 table is empty): give the sensor's own "
                "calibration XML (Velodyne db.xml)");
    }

    const travel::io::PcapSummary summary = travel::io::summarisePcap(path, true);
    if (summary.is_pcapng)
        throw travel::InputError(path +
                                 ": a pcapng capture; MRPT reads classic pcap only (convert it: "
                                 "editcap -F pcap IN.pcapng OUT.pcap)");
    if (!summary.is_pcap)
        throw travel::InputError(path +
                                 ": not a pcap capture (no libpcap magic number at its start)");
    if (summary.link_type != travel::io::kPcapLinkEthernet)
        throw travel::InputError(path + ": pcap link type " + std::to_string(summary.link_type) +
                                 ", not Ethernet: not a Velodyne capture MRPT can read");
    if (summary.velodyne_packets == 0)
        throw travel::InputError(path + ": no Velodyne data packets (UDP port 2368) in its " +
                                 std::to_string(summary.packets) + " packets");
    if (summary.first_packet_time)
        driver_->capture_start = mrpt::Clock::fromDouble(*summary.first_packet_time);

    auto& scanner = driver_->scanner;
    mrpt::config::CConfigFileMemory config;
    const std::string section = "pcap";
    config.write(section, "model", model_);
    config.write(section, "pcap_input", path);
    config.write(section, "pcap_read_once", true);  // no looping at the end
    config.write(section, "pcap_read_fast", true);  // no real-time delays
    config.write(section, "pcap_read_full_scan_delay_ms", 0);
    config.write(section, "sensorLabel", options.sensor_label);
    try {
        scanner.loadConfig(config, section);
        // The driver keeps the calibration chosen at construction (VLP16's) whatever the
        // model key says: set it explicitly.
        scanner.setCalibration(calibration);
        scanner.setPCAPVerbosity(false);
        scanner.initialize();
    } catch (const std::exception& e) {
        std::string what = e.what();
        // MRPT's messages carry a stack trace: keep the first line that says something.
        const auto eol = what.find('\n');
        throw travel::InputError(path + ": cannot open as a pcap capture: " +
                                 (eol == std::string::npos ? what : what.substr(0, eol)));
    }
    driver_->offset.emplace(path);
}

double PcapSource::fractionRead() const {
    return driver_->offset->fraction();
}

PcapSource::~PcapSource() = default;

CObservationVelodyneScan::Ptr PcapSource::next() {
    auto& d = *driver_;
    for (;;) {
        CObservationVelodyneScan::Ptr scan;
        mrpt::obs::CObservationGPS::Ptr gps;  // position packets: MRPT uses them for the time
        bool more = false;
        try {
            more = d.scanner.getNextObservation(scan, gps);
        } catch (const std::exception& e) {
            std::string what = e.what();
            throw travel::InputError(path_ + ": cannot read: " + what.substr(0, what.find('\n')));
        }
        if (scan && !scan->scan_packets.empty()) {
            ++scans_seen_;
            const uint32_t gps_us = scan->scan_packets.front().gps_timestamp();
            if (!d.first_gps_us) {
                d.first_gps_us = gps_us;
                if (!d.capture_start) d.capture_start = scan->timestamp;
            }
            if (!options_.keep_partial_frames && azimuthCoverage(*scan) < kFullRotationCoverage) {
                ++dropped_;
                continue;
            }
            if (!scan->has_satellite_timestamp) {
                // MRPT stamps such frames with the replay's wall clock; use the capture's time
                // plus the sensor's microsecond clock (it wraps every hour).
                const double us =
                    std::fmod(static_cast<double>(gps_us) - *d.first_gps_us + kMicrosecondsPerHour,
                              kMicrosecondsPerHour);
                scan->timestamp = mrpt::system::timestampAdd(*d.capture_start, us * 1e-6);
                scan->originalReceivedTimestamp = scan->timestamp;
            }
            scan->sensorLabel = options_.sensor_label;
            ++frames_;
            return scan;
        }
        if (!more) break;
    }
    if (frames_ == 0)
        throw travel::InputError(path_ + ": no full rotation of the sensor in the capture (" +
                                 std::to_string(dropped_) + " partial frames)");
    return nullptr;
}

}  // namespace travel_mrpt
