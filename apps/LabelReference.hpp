// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Label reference files: the labels and cluster ids of every labelled frame, written by the
// program that ran TRAVEL and compared by a reader of the output (e.g. a plugin-only reader of
// CObservationTravelLabels). Header-only, libtravel types only (no MRPT).
//
// Format (text, one token group per line, '\n' line ends):
//   travel-label-reference 1               magic and format version
//   frame <k> <n>                          k = 0, 1, 2 ...: the k-th labelled frame, n points
//   <label> <cluster id>                   n lines: travel::PointClass value 0..3, id (0 = none)
//   ...                                    (next frame)
//   end <number of frames>
// Points are in the order of the source cloud (every point, invalid ones included).
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"

namespace travel::label_reference {

inline constexpr const char* kMagic = "travel-label-reference";
inline constexpr int kVersion = 1;

struct Frame {
    std::vector<uint8_t> labels;
    std::vector<uint32_t> cluster_id;
};

inline void writeHeader(std::ostream& out) {
    out << kMagic << ' ' << kVersion << '\n';
}

/// Writes frame `k`. `cluster_id` is empty (all 0) or as long as `labels`.
inline void writeFrame(std::ostream& out, std::size_t k, const std::vector<PointClass>& labels,
                       const std::vector<uint32_t>& cluster_id) {
    if (!cluster_id.empty() && cluster_id.size() != labels.size())
        throw std::invalid_argument("label reference: " + std::to_string(labels.size()) +
                                    " labels but " + std::to_string(cluster_id.size()) +
                                    " cluster ids");
    out << "frame " << k << ' ' << labels.size() << '\n';
    for (std::size_t i = 0; i < labels.size(); ++i)
        out << static_cast<int>(labels[i]) << ' ' << (cluster_id.empty() ? 0u : cluster_id[i])
            << '\n';
}

inline void writeFooter(std::ostream& out, std::size_t num_frames) {
    out << "end " << num_frames << '\n';
}

/// Reads a whole reference; throws std::runtime_error naming `source` and what was expected.
inline std::vector<Frame> read(std::istream& in, const std::string& source) {
    const auto fail = [&source](const std::string& what) {
        throw std::runtime_error(source + ": not a valid label reference: " + what);
    };
    std::string word;
    int version = 0;
    if (!(in >> word >> version) || word != kMagic)
        fail(std::string("expected '") + kMagic + " " + std::to_string(kVersion) + "' first");
    if (version != kVersion) fail("unsupported version " + std::to_string(version));
    std::vector<Frame> frames;
    for (;;) {
        if (!(in >> word)) fail("missing 'end' line");
        if (word == "end") {
            std::size_t declared = 0;
            if (!(in >> declared) || declared != frames.size())
                fail("'end' declares a different number of frames than were read");
            return frames;
        }
        std::size_t k = 0, n = 0;
        if (word != "frame" || !(in >> k >> n) || k != frames.size())
            fail("expected 'frame " + std::to_string(frames.size()) + " <points>'");
        if (n > 50'000'000)
            fail("frame " + std::to_string(k) + " claims " + std::to_string(n) + " points");
        Frame f;
        f.labels.reserve(n);
        f.cluster_id.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            unsigned label = 0;
            uint32_t id = 0;
            if (!(in >> label >> id) || label > 3)
                fail("frame " + std::to_string(k) + " point " + std::to_string(i) +
                     ": expected '<label 0..3> <cluster id>'");
            f.labels.push_back(static_cast<uint8_t>(label));
            f.cluster_id.push_back(id);
        }
        frames.push_back(std::move(f));
    }
}

}  // namespace travel::label_reference
