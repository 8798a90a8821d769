// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The apps' outputs: AppError (a failure naming the file it concerns), the folders outputs go
// to, created here with one message for every app ("cannot create folder X: reason"), and the
// check that no output is an input or another output.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

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

/// Throws AppError unless `folder` is a folder or can be created: its nearest existing ancestor
/// is a folder this process may write in. An app checks its output folder with this before a
/// long run and creates it only when it writes, so that a run failing on its input leaves no
/// empty folder behind.
inline void requireCreatableFolder(const std::string& folder) {
    namespace fs = std::filesystem;
    if (folder.empty()) return;
    std::error_code ec;
    fs::path existing = fs::absolute(folder, ec);
    while (!fs::exists(existing, ec) && existing.has_relative_path())
        existing = existing.parent_path();
    if (!fs::is_directory(existing, ec))
        throw AppError("cannot create folder " + folder + ": " + existing.string() +
                       " is not a folder");
    if (::access(existing.c_str(), W_OK | X_OK) != 0)
        throw AppError("cannot create folder " + folder + ": " + existing.string() + ": " +
                       std::strerror(errno));
}

/// Creates the folder that will hold the file `path`.
inline void createParentFolder(const std::string& path) {
    createFolder(std::filesystem::path(path).parent_path().string());
}

/// Throws AppError unless `path`, given with `flag`, can name a file to write: not an existing
/// folder, not ending in '/'.
inline void requireFileName(const std::string& flag, const std::string& path) {
    std::error_code ec;
    if (!path.empty() && (path.back() == '/' || std::filesystem::is_directory(path, ec)))
        throw AppError(flag + " " + path + ": a folder; give the name of the file to write");
}

/// Whether `a` and `b` name the same file or folder: the same file-system entry when both exist
/// (hard links too); never when only one exists; else the same absolute path once symlinks,
/// ".", ".." and a trailing '/' are resolved.
inline bool samePath(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool a_exists = fs::exists(a, ec), b_exists = fs::exists(b, ec);
    if (a_exists != b_exists) return false;  // a path to an existing entry would exist
    if (a_exists) {
        const bool same = fs::equivalent(a, b, ec);
        if (!ec) return same;
    }
    const auto resolved = [](const std::string& path) {
        // Symlinks before "..": link/../x is beside the link's target, not beside the link.
        std::error_code error;
        const fs::path absolute = fs::absolute(path, error);
        fs::path p = fs::weakly_canonical(absolute, error);
        if (error) p = absolute.lexically_normal();
        if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();  // "dir/"
        return p;
    };
    return resolved(a) == resolved(b);
}

/// A path given on the command line and the flag (or role) that gave it, for messages.
struct NamedPath {
    std::string flag, path;
};

/// Before anything is written: throws AppError when an output is one of the inputs (writing it
/// would destroy the input) or the same file as another output. Empty paths are not given.
inline void checkOutputsApart(const std::vector<NamedPath>& inputs,
                              const std::vector<NamedPath>& outputs) {
    for (std::size_t k = 0; k < outputs.size(); ++k) {
        const NamedPath& out = outputs[k];
        if (out.path.empty()) continue;
        for (const NamedPath& in : inputs)
            if (!in.path.empty() && samePath(out.path, in.path))
                throw AppError(out.flag + " " + out.path + ": the same path as " + in.flag + " " +
                               in.path + ", an input (writing it would destroy it)");
        for (std::size_t j = 0; j < k; ++j)
            if (!outputs[j].path.empty() && samePath(out.path, outputs[j].path))
                throw AppError(out.flag + " " + out.path + ": the same path as " + outputs[j].flag +
                               " " + outputs[j].path + " (give each output its own path)");
    }
}

}  // namespace travel::apps
