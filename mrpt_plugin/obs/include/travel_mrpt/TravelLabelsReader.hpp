// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The CObservationTravelLabels of a labelled rawlog (one that travel-rawlog wrote), in file
// order, from both rawlog formats (inside SensoryFrames too); every other record is passed over.
// A labels object IS a travel::LabelledFrame (it derives it): that is the whole conversion to
// libtravel. Reading goes through the one RawlogReader, with its errors ("<file>: record <n>:
// truncated (end of file inside the record)", ...). Call travel_mrpt::registerClasses() first.
//
//   travel_mrpt::TravelLabelsReader golden("golden.rawlog");
//   while (auto labels = golden.next()) compare(static_cast<travel::LabelledFrame&>(*labels));
#pragma once

#include <deque>
#include <memory>
#include <string>

#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/RawlogReader.hpp"

namespace travel_mrpt {

class TravelLabelsReader {
  public:
    explicit TravelLabelsReader(const std::string& path) : reader_(path) {}

    /// The next labels object, or null at the end of the file.
    std::shared_ptr<CObservationTravelLabels> next();
    /// Labels objects read so far.
    std::size_t count() const { return count_; }
    const RawlogReader& reader() const { return reader_; }

  private:
    RawlogReader reader_;
    std::deque<std::shared_ptr<CObservationTravelLabels>> queued_;  // rest of a SensoryFrame
    std::size_t count_ = 0;
};

}  // namespace travel_mrpt
