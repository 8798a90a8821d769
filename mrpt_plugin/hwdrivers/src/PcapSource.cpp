// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/PcapSource.hpp"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CVelodyneScanner.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/VelodyneCalibration.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "travel/Errors.hpp"

namespace fs = std::filesystem;
using mrpt::obs::CObservationVelodyneScan;
using mrpt::obs::VelodyneCalibration;

namespace travel_mrpt {
namespace {

constexpr uint32_t kPcapMicro = 0xa1b2c3d4, kPcapNano = 0xa1b23c4d, kPcapNg = 0x0a0d0d0a;
constexpr uint32_t byteSwapped(uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

/// What a first pass over a classic libpcap file finds: whether it is one, the capture time of
/// its first packet (anchor of the frame timestamps when the capture has no GPS time), and how
/// many Velodyne data packets (Ethernet/IPv4/UDP to port 2368) it holds. MRPT's reader loops
/// forever on a capture without any, so they are counted before it starts.
struct PcapSummary {
    bool is_pcap = false, is_pcapng = false;
    uint32_t link_type = 0;
    std::optional<mrpt::system::TTimeStamp> first_packet_time;
    std::size_t packets = 0, velodyne_packets = 0;
};

constexpr uint32_t kLinkEthernet = 1;
constexpr uint16_t kVelodyneDataPort = 2368;

bool isVelodyneDataPacket(const unsigned char* p, std::size_t n) {
    std::size_t ip = 14;
    if (n < ip) return false;
    uint16_t ethertype = static_cast<uint16_t>(p[12] << 8 | p[13]);
    if (ethertype == 0x8100 && n >= 18) {  // one VLAN tag
        ethertype = static_cast<uint16_t>(p[16] << 8 | p[17]);
        ip = 18;
    }
    if (ethertype != 0x0800 || n < ip + 20 || p[ip + 9] != 17) return false;  // IPv4, UDP
    const std::size_t udp = ip + 4 * (p[ip] & 0x0Fu);
    if (n < udp + 8) return false;
    return static_cast<uint16_t>(p[udp + 2] << 8 | p[udp + 3]) == kVelodyneDataPort;
}

PcapSummary summarisePcap(const std::string& path, bool count_packets) {
    PcapSummary h;
    std::ifstream f(path, std::ios::binary);
    std::array<unsigned char, 24> file_header{};
    f.read(reinterpret_cast<char*>(file_header.data()), file_header.size());
    const auto got = static_cast<std::size_t>(f.gcount());
    if (got < 4) return h;
    uint32_t magic;
    std::memcpy(&magic, file_header.data(), 4);
    h.is_pcapng = magic == kPcapNg;
    const bool swapped = magic == byteSwapped(kPcapMicro) || magic == byteSwapped(kPcapNano);
    const uint32_t native = swapped ? byteSwapped(magic) : magic;
    h.is_pcap = native == kPcapMicro || native == kPcapNano;
    if (!h.is_pcap || got < file_header.size()) return h;
    const auto field = [&](const unsigned char* b) {
        uint32_t v;
        std::memcpy(&v, b, 4);
        return swapped ? byteSwapped(v) : v;
    };
    h.link_type = field(file_header.data() + 20) & 0xFFFFu;
    std::array<unsigned char, 16> record{};
    std::vector<unsigned char> data;
    while (f.read(reinterpret_cast<char*>(record.data()), record.size())) {
        const uint32_t sec = field(record.data()), frac = field(record.data() + 4);
        const uint32_t stored = field(record.data() + 8);
        if (!h.first_packet_time)
            h.first_packet_time =
                mrpt::Clock::fromDouble(sec + frac * (native == kPcapNano ? 1e-9 : 1e-6));
        ++h.packets;
        if (!count_packets) break;
        const std::size_t head = std::min<std::size_t>(stored, 64);  // headers only
        data.resize(head);
        if (!f.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(head)))
            break;
        f.seekg(static_cast<std::streamoff>(stored - head), std::ios::cur);
        if (h.link_type == kLinkEthernet && isVelodyneDataPacket(data.data(), head))
            ++h.velodyne_packets;
    }
    return h;
}

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
    std::string s;
    for (char c : name)
        if (std::isalnum(static_cast<unsigned char>(c)))
            s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const char* model : {"VLP16", "HDL32", "HDL64"})
        if (s.rfind(model, 0) == 0) return model;  // HDL32E, HDL64S2, VLP16HIRES, ...
    if (s == "PUCK") return "VLP16";
    return {};
}

bool isPcapFile(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".pcap" || ext == ".pcapng") return true;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return false;
    const PcapSummary h = summarisePcap(path, false);
    return h.is_pcap || h.is_pcapng;
}

struct PcapSource::Driver {
    mrpt::hwdrivers::CVelodyneScanner scanner;
    std::optional<mrpt::system::TTimeStamp> capture_start;
    std::optional<uint32_t> first_gps_us;  // the sensor clock at capture_start
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

    const PcapSummary summary = summarisePcap(path, true);
    if (summary.is_pcapng)
        throw travel::InputError(path +
                                 ": a pcapng capture; MRPT reads classic pcap only (convert it: "
                                 "editcap -F pcap IN.pcapng OUT.pcap)");
    if (!summary.is_pcap)
        throw travel::InputError(path +
                                 ": not a pcap capture (no libpcap magic number at its start)");
    if (summary.link_type != kLinkEthernet)
        throw travel::InputError(path + ": pcap link type " + std::to_string(summary.link_type) +
                                 ", not Ethernet: not a Velodyne capture MRPT can read");
    if (summary.velodyne_packets == 0)
        throw travel::InputError(path + ": no Velodyne data packets (UDP port 2368) in its " +
                                 std::to_string(summary.packets) + " packets");
    driver_->capture_start = summary.first_packet_time;

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
