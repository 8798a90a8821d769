// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A temporary directory for one GoogleTest test, removed at its end. The name holds the test's
// name and the object's address, so parallel ctest processes and nested dirs never collide.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace travel_test {

struct TempDir {
    std::filesystem::path path;

    explicit TempDir(const std::string& prefix = "travel_test") {
        path = std::filesystem::temp_directory_path() /
               (prefix + "_" + std::to_string(reinterpret_cast<std::uintptr_t>(this)) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    /// The path of `name` inside the directory (its parent folders are created).
    std::string file(const std::string& name) const {
        std::filesystem::create_directories((path / name).parent_path());
        return (path / name).string();
    }
    /// Writes `bytes` as they are to `name`; returns its path.
    std::string write(const std::string& name, const std::string& bytes) const {
        std::ofstream out(file(name), std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return file(name);
    }
    std::string writeBytes(const std::string& name, const std::vector<unsigned char>& bytes) const {
        return write(name, std::string(bytes.begin(), bytes.end()));
    }
    /// Host-order floats: the tests run on little-endian hosts, like the file formats.
    std::string writeFloats(const std::string& name, const std::vector<float>& values) const {
        std::string bytes(values.size() * sizeof(float), '\0');
        std::memcpy(bytes.data(), values.data(), bytes.size());
        return write(name, bytes);
    }
};

}  // namespace travel_test
