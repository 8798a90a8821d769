// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Classic libpcap capture files, read just enough to check one before a driver replays it:
// whether it is one, its link type, the capture time of its first packet, and how many Velodyne
// data packets (Ethernet / IPv4 / UDP to port 2368) it holds. MRPT's CVelodyneScanner loops
// forever on a capture without any, so the MRPT layer counts them first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace travel::io {

constexpr uint32_t kPcapLinkEthernet = 1;
constexpr uint16_t kVelodyneDataPort = 2368;

struct PcapSummary {
    bool is_pcap = false;    ///< classic libpcap (micro- or nanosecond, either byte order)
    bool is_pcapng = false;  ///< the newer pcapng format (not read by MRPT 2.5)
    uint32_t link_type = 0;
    std::optional<double> first_packet_time;  ///< [s] since the epoch
    std::size_t packets = 0, velodyne_packets = 0;
};

/// Reads the file header and, with count_packets, every packet's headers (the first packet's
/// time only otherwise). A file that is not a capture gives is_pcap = is_pcapng = false.
PcapSummary summarisePcap(const std::string& path, bool count_packets);

/// True for a .pcap / .pcapng file name, or a regular file that starts like a capture.
bool isPcapFile(const std::string& path);

/// Ethernet frame (optionally one VLAN tag) carrying IPv4 / UDP to kVelodyneDataPort.
bool isVelodyneDataPacket(const unsigned char* frame, std::size_t size);

}  // namespace travel::io
