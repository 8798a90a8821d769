// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The apps' outputs: AppError (a failure naming the file it concerns) and the folders outputs go
// to, created here with one message for every app ("cannot create folder X: reason").
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace travel::apps {

/// A failure with the file (and record) it concerns; runMain() prints it on one line.
struct AppError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Creates `folder` and its parents (nothing to do when it exists or is "").
inline void createFolder(const std::string& folder) {
    if (folder.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw AppError("cannot create folder " + folder + ": " + ec.message());
}

/// Creates the folder that will hold the file `path`.
inline void createParentFolder(const std::string& path) {
    createFolder(std::filesystem::path(path).parent_path().string());
}

}  // namespace travel::apps
