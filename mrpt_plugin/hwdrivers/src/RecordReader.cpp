// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/RecordReader.hpp"

#include <mrpt/serialization/CSerializable.h>

namespace travel_mrpt {

RecordReader::RecordReader(const std::string& path, const PcapSourceOptions& pcap) {
    if (isPcapFile(path))
        pcap_ = std::make_unique<PcapSource>(path, pcap);
    else
        rawlog_ = std::make_unique<RawlogReader>(path);
}

std::shared_ptr<mrpt::serialization::CSerializable> RecordReader::next() {
    if (pcap_) return pcap_->next();
    return rawlog_->next();
}

}  // namespace travel_mrpt
