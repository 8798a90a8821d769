// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes -> file -> readLabelFile with an expected count derived from the input.
#include <cstdint>

#include "FuzzCommon.hpp"
#include "travel/Errors.hpp"
#include "travel/eval/KittiIO.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string& path = travel_fuzz::tempPath(".label");
    travel_fuzz::writeFile(path, data, size);
    // The expected count: the true count, off by one either way, or "any", chosen by the first
    // byte (the file content is the whole input).
    const std::size_t n = size / 4;
    const uint8_t mode = size ? data[0] % 4 : 0;
    const std::size_t expected = mode == 0   ? n
                                 : mode == 1 ? n + 1
                                 : mode == 2 ? (n ? n - 1 : 0)
                                             : travel::kAnyLabelCount;
    try {
        const auto labels = travel::readLabelFile(path, expected);
        FUZZ_CHECK(size % 4 == 0);
        FUZZ_CHECK(labels.size() == n);
        FUZZ_CHECK(expected == travel::kAnyLabelCount || expected == n);
        for (std::size_t i = 0; i < n; ++i) {
            const uint32_t v = uint32_t(data[4 * i]) | uint32_t(data[4 * i + 1]) << 8 |
                               uint32_t(data[4 * i + 2]) << 16 | uint32_t(data[4 * i + 3]) << 24;
            FUZZ_CHECK(labels[i] == v);  // little-endian
            FUZZ_CHECK(travel::labelClassBits(labels[i]) == (v & 0xFFFFu));
        }
    } catch (const travel::InputError&) {
        FUZZ_CHECK(size % 4 != 0 || expected != n);
    }
    return 0;
}
