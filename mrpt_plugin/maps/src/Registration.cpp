// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/Registration.hpp"

#include <mrpt/rtti/CObject.h>

#include <mutex>

#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"

namespace travel_mrpt {

void registerClasses() {
    static std::once_flag once;
    std::call_once(once, [] {
        mrpt::rtti::registerClass(CLASS_ID(CObservationTravelLabels));
        mrpt::rtti::registerClass(CLASS_ID(CTraversabilityMap));
    });
}

}  // namespace travel_mrpt
