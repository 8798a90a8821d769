// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// compare_travel_rawlogs A.rawlog B.rawlog: exit 0 when the two rawlogs hold the same records
// with the same content, the stage timings of the TRAVEL labels excepted (they are measured,
// so two runs never agree on them); else prints the first difference and exits 1.
// Used by apps.travel_rawlog_jobs (travel-rawlog -j N against -j 1).
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/Registration.hpp"

namespace {

void zeroTimings(mrpt::serialization::CSerializable& object) {
    if (auto* labels = dynamic_cast<travel_mrpt::CObservationTravelLabels*>(&object))
        labels->timings = {};
}

/// The record's serialized bytes, with the timings of its CObservationTravelLabels zeroed.
std::string bytesOf(mrpt::serialization::CSerializable& record) {
    zeroTimings(record);
    if (auto* sf = dynamic_cast<mrpt::obs::CSensoryFrame*>(&record))
        for (const auto& obs : *sf)
            if (obs) zeroTimings(*obs);
    mrpt::io::CMemoryStream stream;
    auto archive = mrpt::serialization::archiveFrom(stream);
    archive << record;
    return std::string(static_cast<const char*>(stream.getRawBufferData()),
                       static_cast<std::size_t>(stream.getTotalBytesCount()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s A.rawlog B.rawlog\n", argv[0]);
        return 2;
    }
    try {
        travel_mrpt::registerClasses();
        travel_mrpt::RawlogReader a(argv[1]), b(argv[2]);
        for (long record = 0;; ++record) {
            const auto ra = a.next();
            const auto rb = b.next();
            if (!ra || !rb) {
                if (ra || rb) {
                    std::printf("record %ld: only in %s\n", record, ra ? argv[1] : argv[2]);
                    return 1;
                }
                std::printf("same %ld records\n", record);
                return 0;
            }
            if (bytesOf(*ra) != bytesOf(*rb)) {
                std::printf("record %ld (%s) differs\n", record, ra->GetRuntimeClass()->className);
                return 1;
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "compare_travel_rawlogs: %s\n", e.what());
        return 2;
    }
}
