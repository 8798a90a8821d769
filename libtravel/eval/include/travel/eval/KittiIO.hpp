// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// SemanticKITTI .label files and KITTI sequence folders. Scans (KITTI / nuScenes .bin, PCD, PLY)
// are read by travel_io's readScan() and written by writeKittiBin(): travel/io/ScanIO.hpp,
// included here for the evaluation code that reads scans next to their labels. Labels are
// little-endian uint32. Read errors throw InputError naming the file; write errors throw
// std::runtime_error naming the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel/io/ScanList.hpp"  // listFiles, listScans

namespace travel {

/// Pass as expected_count to readLabelFile() to accept any number of labels.
constexpr std::size_t kAnyLabelCount = std::numeric_limits<std::size_t>::max();

/// Reads a SemanticKITTI .label: one uint32 per point. Throws InputError when the size is not a
/// multiple of 4 bytes, or when the count differs from expected_count (unless kAnyLabelCount).
std::vector<uint32_t> readLabelFile(const std::string& path, std::size_t expected_count);

/// Writes one uint32 per label.
void writeLabelFile(const std::string& path, const std::vector<uint32_t>& labels);

/// travel-kitti's .label encoding: the PointClass in the lower 16 bits, the cluster id in the
/// upper 16 bits (0 = no cluster). Ids above 0xFFFF wrap to ((id - 1) % 0xFFFF) + 1, so they
/// stay in [1, 0xFFFF] and never read back as "no cluster"; ids up to 0xFFFF are kept as is.
inline uint32_t encodeLabel(PointClass c, uint32_t cluster_id) {
    const uint32_t cluster = cluster_id == 0 ? 0 : ((cluster_id - 1) % 0xFFFFu) + 1;
    return (cluster << 16) | static_cast<uint32_t>(c);
}

/// The lower 16 bits: a PointClass value in travel-kitti output, the semantic class in
/// SemanticKITTI ground truth.
inline uint32_t labelClassBits(uint32_t label) {
    return label & 0xFFFFu;
}

/// The upper 16 bits: the cluster (instance) id, 0 = none.
inline uint32_t labelClusterId(uint32_t label) {
    return label >> 16;
}

}  // namespace travel
