// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Velodyne .pcap captures (the sensor's UDP packets as libpcap saved them) replayed through
// MRPT's CVelodyneScanner, one CObservationVelodyneScan per full rotation:
//
//   travel_mrpt::PcapSource pcap("capture.pcap", {"HDL32"});
//   while (auto scan = pcap.next()) { ... }   // null at the end of the file
//
// Every error is a travel::InputError naming the file (missing file, not a pcap, no Velodyne
// packets, unknown model). Frames keep their packets: TravelFilter / velodyneToTravelCloud
// decode them with per-point times (deskew) and rings in elevation order.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <mrpt/obs/CObservationVelodyneScan.h>

namespace travel_mrpt {

/// The models CVelodyneScanner decodes, as their canonical names.
inline constexpr const char* kVelodynePcapModels = "VLP16, HDL32, HDL64";

/// "vlp16", "VLP-16", "hdl32", "HDL-32E", "hdl64" ... -> "VLP16" / "HDL32" / "HDL64"; empty when
/// `name` (a model or a preset name) is none of them.
std::string velodyneModelName(const std::string& name);

/// True when `path` ends in .pcap (any case) or starts with a libpcap magic number.
bool isPcapFile(const std::string& path);

struct PcapSourceOptions {
    /// VLP16, HDL32 or HDL64 (any spelling velodyneModelName() accepts).
    std::string model;
    /// The sensor's own calibration (Velodyne's db.xml). Empty: the model's default, which
    /// MRPT 2.5.8 has for VLP16 and HDL32 only (its HDL64 default is empty).
    std::string calibration_file;
    /// sensorLabel of the frames.
    std::string sensor_label = "VELODYNE";
    /// The capture starts and ends mid-rotation: those partial frames are dropped unless set.
    bool keep_partial_frames = false;
};

class PcapSource {
  public:
    /// Opens the capture. Throws InputError "<path>: no such file", "<path>: not a pcap
    /// capture ...", "<path>: unknown Velodyne model 'X' (allowed: VLP16, HDL32, HDL64)",
    /// "<path>: no calibration ...".
    PcapSource(const std::string& path, const PcapSourceOptions& options);
    ~PcapSource();
    PcapSource(const PcapSource&) = delete;
    PcapSource& operator=(const PcapSource&) = delete;

    /// The next full rotation, or null at the end of the capture. Throws InputError
    /// "<path>: no Velodyne data packets (UDP port 2368) ..." when the file ends without any.
    /// Timestamps: GPS time when the capture has position packets with a fix, otherwise the
    /// capture time of the first packet plus the sensor's own microsecond clock.
    mrpt::obs::CObservationVelodyneScan::Ptr next();

    /// Bytes of the capture read so far over its size, in [0, 1]; -1 when unknown.
    double fractionRead() const;
    /// Frames returned so far, and partial rotations dropped.
    std::size_t frames() const { return frames_; }
    std::size_t droppedPartialFrames() const { return dropped_; }
    const std::string& path() const { return path_; }
    const std::string& model() const { return model_; }

  private:
    struct Driver;
    std::string path_, model_;
    PcapSourceOptions options_;
    std::unique_ptr<Driver> driver_;
    std::size_t frames_ = 0, dropped_ = 0, scans_seen_ = 0;
};

}  // namespace travel_mrpt
