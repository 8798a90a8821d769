// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/PcapFile.hpp"

#include "travel/io/ScanList.hpp"  // lowerCaseExtension

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace fs = std::filesystem;

namespace travel::io {
namespace {

constexpr uint32_t kPcapMicro = 0xa1b2c3d4, kPcapNano = 0xa1b23c4d, kPcapNg = 0x0a0d0d0a;
constexpr uint32_t byteSwapped(uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

}  // namespace

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
            h.first_packet_time = sec + frac * (native == kPcapNano ? 1e-9 : 1e-6);
        ++h.packets;
        if (!count_packets) break;
        const std::size_t head = std::min<std::size_t>(stored, 64);  // headers only
        data.resize(head);
        if (!f.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(head)))
            break;
        f.seekg(static_cast<std::streamoff>(stored - head), std::ios::cur);
        if (h.link_type == kPcapLinkEthernet && isVelodyneDataPacket(data.data(), head))
            ++h.velodyne_packets;
    }
    return h;
}

bool isPcapFile(const std::string& path) {
    const std::string ext = travel::lowerCaseExtension(path);
    if (ext == ".pcap" || ext == ".pcapng") return true;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return false;
    const PcapSummary h = summarisePcap(path, false);
    return h.is_pcap || h.is_pcapng;
}

}  // namespace travel::io
