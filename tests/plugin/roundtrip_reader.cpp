// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Reader half of the plugin round trip, in a process that does NOT link travel_mrpt:
//   travel_plugin_roundtrip_reader <plugin.so> <rawlog> <reference>
// The class becomes known only by loading the plugin module; objects are then read with MRPT's
// ordinary machinery and their public data members compared with the reference file. The class
// header is included only to static_cast and read members (no constructor call, so no
// reference to the class's vtable: linking this program proves it). Exits 0 only if every
// label and cluster id matched and at least one frame was compared.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/registerAllClasses.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/os.h>

#include <fstream>
#include <iostream>

#include "../../apps/LabelReference.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"

namespace {

constexpr const char* kClass = travel_mrpt::CObservationTravelLabels::className;

int fail(const std::string& why) {
    std::cerr << "roundtrip_reader: FAILED: " << why << "\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: " << argv[0] << " <plugin.so> <rawlog> <reference>\n";
        return 2;
    }
    try {
        // Like any MRPT app (rawlog-edit links every MRPT library): the source observations in
        // a rawlog may be of classes from mrpt-maps (CObservationRotatingScan,
        // CObservationPointCloud), which register when that library is used.
        mrpt::maps::registerAllClasses_mrpt_maps();
        if (mrpt::rtti::findRegisteredClass(kClass) != nullptr)
            return fail(std::string(kClass) + " is registered before loading the plugin");
        std::string errors;
        if (!mrpt::system::loadPluginModules(argv[1], errors))
            return fail(std::string("cannot load plugin ") + argv[1] + ": " + errors);
        if (mrpt::rtti::findRegisteredClass(kClass) == nullptr)
            return fail(std::string("the plugin did not register ") + kClass);

        std::ifstream reference_file(argv[3]);
        if (!reference_file) return fail(std::string("cannot open reference ") + argv[3]);
        const auto reference = travel::label_reference::read(reference_file, argv[3]);

        mrpt::io::CFileGZInputStream file;
        if (!file.open(argv[2])) return fail(std::string("cannot open rawlog ") + argv[2]);
        auto archive = mrpt::serialization::archiveFrom(file);
        std::size_t frames = 0, points = 0, mismatches = 0, objects = 0;
        for (;;) {
            mrpt::serialization::CSerializable::Ptr object;
            try {
                object = archive.ReadObject();
            } catch (const mrpt::serialization::CExceptionEOF&) {
                break;
            }
            ++objects;
            // Labels stand alone (observations format) or inside a SensoryFrame.
            std::vector<const mrpt::serialization::CSerializable*> candidates{object.get()};
            if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
                candidates.clear();
                for (const auto& obs : *sf) candidates.push_back(obs.get());
            }
            for (const auto* candidate : candidates) {
                if (!candidate || std::string(candidate->GetRuntimeClass()->className) != kClass)
                    continue;
                const auto& labels =
                    static_cast<const travel_mrpt::CObservationTravelLabels&>(*candidate);
                if (frames >= reference.size())
                    return fail("more labelled frames in the rawlog than in the reference (" +
                                std::to_string(reference.size()) + ")");
                const auto& expected = reference[frames];
                if (labels.labels.size() != expected.labels.size() ||
                    labels.clusterId.size() != expected.cluster_id.size())
                    return fail("frame " + std::to_string(frames) + ": " +
                                std::to_string(labels.labels.size()) + " points, reference has " +
                                std::to_string(expected.labels.size()));
                for (std::size_t i = 0; i < expected.labels.size(); ++i)
                    if (labels.labels[i] != expected.labels[i] ||
                        labels.clusterId[i] != expected.cluster_id[i]) {
                        if (mismatches++ < 10)
                            std::cerr << "frame " << frames << " point " << i << ": label "
                                      << int(labels.labels[i]) << " cluster " << labels.clusterId[i]
                                      << ", reference " << int(expected.labels[i]) << " / "
                                      << expected.cluster_id[i] << "\n";
                    }
                points += expected.labels.size();
                ++frames;
            }
        }
        std::cout << "roundtrip_reader: " << objects << " objects read, " << frames
                  << " labelled frames and " << points << " points compared, " << mismatches
                  << " mismatches\n";
        if (frames != reference.size())
            return fail(std::to_string(frames) + " labelled frames in the rawlog, " +
                        std::to_string(reference.size()) + " in the reference");
        if (frames == 0) return fail("no labelled frame to compare");
        return mismatches == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
