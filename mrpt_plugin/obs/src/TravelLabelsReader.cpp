// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TravelLabelsReader.hpp"

#include <mrpt/obs/CSensoryFrame.h>

namespace travel_mrpt {

std::shared_ptr<CObservationTravelLabels> TravelLabelsReader::next() {
    while (queued_.empty()) {
        const auto record = reader_.next();
        if (!record) return nullptr;
        if (auto labels = std::dynamic_pointer_cast<CObservationTravelLabels>(record)) {
            queued_.push_back(std::move(labels));
        } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(record)) {
            for (const auto& obs : *sf)
                if (auto labels = std::dynamic_pointer_cast<CObservationTravelLabels>(obs))
                    queued_.push_back(std::move(labels));
        }
    }
    auto labels = std::move(queued_.front());
    queued_.pop_front();
    ++count_;
    return labels;
}

}  // namespace travel_mrpt
