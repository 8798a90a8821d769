// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// MRPT's RTTI registry knows a class by name only after registerClass(): IMPLEMENTS_SERIALIZABLE
// alone does not register it, and reading an unregistered class from a rawlog fails. Programs
// linking travel_mrpt call registerClasses() once before reading; MRPT apps load
// libtravel_mrpt_plugin.so (rawlog-edit -p, RawLogViewer -l), which calls it at load time.
#pragma once

namespace travel_mrpt {

/// Registers every serializable class of travel_mrpt (CObservationTravelLabels, and the map
/// layer CTraversabilityMap with its CMultiMetricMap factory entry) with
/// mrpt::rtti. Idempotent and thread-safe.
void registerClasses();

}  // namespace travel_mrpt
