// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One record stream for an MRPT rawlog or a Velodyne .pcap capture, so that a tool reading
// rawlogs reads captures too:
//
//   travel_mrpt::RecordReader input(path, pcap_options);  // .pcap (name or magic) or rawlog
//   while (auto record = input.next()) { ... }             // a capture gives one
//                                                          // CObservationVelodyneScan per rotation
#pragma once

#include <memory>
#include <string>

#include "travel_mrpt/PcapSource.hpp"
#include "travel_mrpt/RawlogReader.hpp"

namespace mrpt::serialization {
class CSerializable;
}

namespace travel_mrpt {

class RecordReader {
  public:
    /// A pcap when isPcapFile(path), else a rawlog; `pcap` is used for captures only. Throws
    /// the InputError of PcapSource / RawlogReader.
    RecordReader(const std::string& path, const PcapSourceOptions& pcap);

    /// The next record (rawlog) or rotation (capture), or null at the end.
    std::shared_ptr<mrpt::serialization::CSerializable> next();

    /// Bytes read over the input's size, in [0, 1]; -1 when unknown.
    double fractionRead() const { return pcap_ ? pcap_->fractionRead() : rawlog_->fractionRead(); }
    /// Records read so far.
    long index() const { return pcap_ ? static_cast<long>(pcap_->frames()) : rawlog_->index(); }
    bool isPcap() const { return pcap_ != nullptr; }

  private:
    std::unique_ptr<PcapSource> pcap_;
    std::unique_ptr<RawlogReader> rawlog_;
};

}  // namespace travel_mrpt
