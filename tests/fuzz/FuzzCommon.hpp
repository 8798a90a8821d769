// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// Helpers shared by the libFuzzer targets.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "travel/Pipeline.hpp"

namespace travel_fuzz {

/// Fails the run (libFuzzer reports it as a crash) when `cond` is false.
#define FUZZ_CHECK(cond)                                                                        \
    do {                                                                                        \
        if (!(cond)) {                                                                          \
            std::fprintf(stderr, "FUZZ_CHECK failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
            std::abort();                                                                       \
        }                                                                                       \
    } while (0)

/// One temp file per process (libFuzzer -jobs/-fork run several processes), rewritten per input.
inline const std::string& tempPath(const char* suffix) {
    static const std::string path = [&] {
        const char* dir = std::getenv("TMPDIR");
        return std::string(dir && *dir ? dir : "/tmp") + "/travel_fuzz_" +
               std::to_string(::getpid()) + suffix;
    }();
    return path;
}

inline void writeFile(const std::string& path, const uint8_t* data, std::size_t size) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) std::abort();
    if (size && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
}

/// The invariants every Pipeline result must satisfy.
inline void checkResult(const travel::PointCloud& cloud, const travel::Params& params,
                        const travel::Result& r) {
    using travel::PointClass;
    const std::size_t n = cloud.size();
    FUZZ_CHECK(r.labels.size() == n);
    std::size_t counts[4] = {0, 0, 0, 0};
    for (auto c : r.labels) {
        FUZZ_CHECK(static_cast<unsigned>(c) <= 3u);
        ++counts[static_cast<unsigned>(c)];
    }
    for (int c = 0; c < 4; ++c) FUZZ_CHECK(r.class_counts[c] == counts[c]);
    if (!params.cluster_objects) return;
    FUZZ_CHECK(r.cluster_id.size() == n);
    std::vector<uint32_t> members(r.clusters.size() + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t id = r.cluster_id[i];
        FUZZ_CHECK(id <= r.clusters.size());
        if (id != 0) {
            FUZZ_CHECK(r.labels[i] == PointClass::NonGround);
            ++members[id];
        }
    }
    for (std::size_t k = 0; k < r.clusters.size(); ++k) {
        FUZZ_CHECK(r.clusters[k].id == k + 1);
        FUZZ_CHECK(r.clusters[k].num_points == members[k + 1]);
    }
}

}  // namespace travel_fuzz
