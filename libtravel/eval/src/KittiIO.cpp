// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/KittiIO.hpp"

#include "travel/Errors.hpp"
#include "travel/Text.hpp"
#include "travel/io/BinaryFile.hpp"

namespace travel {

namespace {

// One buffer per thread: a sequence of frames re-uses the same allocation.
std::vector<unsigned char>& scratchBuffer() {
    thread_local std::vector<unsigned char> buffer;
    return buffer;
}

}  // namespace

std::vector<uint32_t> readLabelFile(const std::string& path, std::size_t expected_count) {
    auto& buffer = scratchBuffer();
    readFileBytes(path, buffer);
    if (buffer.size() % 4 != 0) {
        throw InputError(inQuotes(path) + ": size " + std::to_string(buffer.size()) +
                         " bytes is not a multiple of 4 (labels are uint32); " +
                         std::to_string(buffer.size() % 4) + " bytes left over");
    }
    const std::size_t n = buffer.size() / 4;
    if (expected_count != kAnyLabelCount && n != expected_count) {
        throw InputError(inQuotes(path) + " has " + std::to_string(n) + " labels but " +
                         std::to_string(expected_count) + " were expected (one per point)");
    }
    std::vector<uint32_t> labels(n);
    for (std::size_t i = 0; i < n; ++i) labels[i] = le::load<uint32_t>(buffer.data() + 4 * i);
    return labels;
}

void writeLabelFile(const std::string& path, const std::vector<uint32_t>& labels) {
    auto& buffer = scratchBuffer();
    buffer.resize(labels.size() * 4);
    for (std::size_t i = 0; i < labels.size(); ++i) le::store(labels[i], buffer.data() + 4 * i);
    writeFileBytes(path, buffer.data(), buffer.size());
}

}  // namespace travel
