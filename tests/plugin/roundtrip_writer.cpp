// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Writer half of the plugin round trip:
//   travel_plugin_roundtrip_writer <config.yaml> <out.rawlog> <out.reference> <in.rawlog>...
// runs TRAVEL on every LiDAR observation of the input rawlogs and writes, per observation, the
// source observation followed by its CObservationTravelLabels, plus a label reference file
// (LabelReference.hpp). Exits 77 (CTest SKIP_RETURN_CODE) when no input rawlog exists.
#include <mrpt/io/CFileGZOutputStream.h>

#include <fstream>
#include <iostream>

#include "../../apps/LabelReference.hpp"
#include "SampleLabelling.hpp"

int main(int argc, char** argv) {
    if (argc < 5) {
        std::cerr << "usage: " << argv[0]
                  << " <config.yaml> <out.rawlog> <out.reference> <in.rawlog>...\n";
        return 2;
    }
    try {
        std::vector<std::string> inputs;
        for (int i = 4; i < argc; ++i)
            if (travel_test::fileExists(argv[i]))
                inputs.push_back(argv[i]);
            else
                std::cerr << "skipping missing input " << argv[i] << "\n";
        if (inputs.empty()) {
            std::cerr << "no input rawlog found (Debian package mrpt-common): skipped\n";
            return 77;
        }
        travel_test::SampleLabeller labeller(argv[1]);
        mrpt::io::CFileGZOutputStream out_file;
        if (!out_file.open(argv[2]))
            throw std::runtime_error(std::string("cannot write ") + argv[2]);
        auto out = mrpt::serialization::archiveFrom(out_file);
        std::ofstream reference(argv[3]);
        if (!reference) throw std::runtime_error(std::string("cannot write ") + argv[3]);
        travel::label_reference::writeHeader(reference);

        std::size_t frames = 0, points = 0;
        travel_mrpt::CObservationTravelLabels labels;
        for (const auto& path : inputs)
            travel_test::forEachObservation(path, [&](const mrpt::obs::CObservation::Ptr& obs) {
                if (!labeller.label(*obs, labels)) return;
                out << *obs << labels;
                travel::label_reference::writeFrame(reference, frames, labeller.result().labels,
                                                    labeller.result().cluster_id);
                ++frames;
                points += labels.size();
            });
        travel::label_reference::writeFooter(reference, frames);
        if (!reference) throw std::runtime_error(std::string("error writing ") + argv[3]);
        std::cout << "wrote " << frames << " labelled frames (" << points << " points) to "
                  << argv[2] << " and " << argv[3] << "\n";
        return frames > 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
