// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/ScanList.hpp"

#include <algorithm>
#include <filesystem>

#include "travel/Errors.hpp"

namespace travel {

namespace fs = std::filesystem;

namespace {

std::string inQuotes(const std::string& path) {
    return "'" + path + "'";
}

/// The extensions of the scan files `format` reads.
std::vector<std::string> scanExtensions(ScanFormat format) {
    switch (format) {
        case ScanFormat::KittiBin:
        case ScanFormat::NuScenesBin:
            return {".bin"};
        case ScanFormat::Pcd:
            return {".pcd"};
        case ScanFormat::Ply:
            return {".ply"};
        case ScanFormat::Auto:
            break;
    }
    return {".bin", ".pcd", ".ply"};
}

bool isDirectory(const fs::path& path) {
    std::error_code ec;
    return fs::is_directory(path, ec);
}

}  // namespace

std::vector<std::string> listFiles(const std::string& dir, const std::string& extension) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        throw InputError("directory " + inQuotes(dir) +
                         (fs::exists(dir, ec) ? " is not a directory" : " does not exist"));
    }
    const std::string wanted =
        extension.empty() || extension.front() == '.' ? extension : "." + extension;
    std::vector<std::string> files;
    fs::directory_iterator it(dir, ec);
    if (ec) throw InputError("cannot list " + inQuotes(dir) + ": " + ec.message());
    // increment() turns `it` into the end iterator on error; ec is checked after the loop.
    for (const fs::directory_iterator end; it != end; it.increment(ec)) {
        std::error_code type_ec;
        if (!it->is_regular_file(type_ec)) continue;  // follows symlinks, skips directories
        if (wanted.empty() || it->path().extension() == wanted) {
            files.push_back(it->path().string());
        }
    }
    if (ec) throw InputError("cannot list " + inQuotes(dir) + ": " + ec.message());
    std::sort(files.begin(), files.end());
    return files;
}

ScanList listScans(const std::string& path, ScanFormat format) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(inQuotes(path) + " does not exist");
    ScanList list;
    fs::path scans = path;
    if (!isDirectory(scans)) {
        list.files = {path};
        scans = scans.parent_path();
    } else if (isDirectory(scans / "velodyne")) {
        scans /= "velodyne";
    }
    scans = scans.lexically_normal();
    if (scans.filename().empty()) scans = scans.parent_path();  // "dir/" -> "dir"
    list.scans_dir = scans.string();
    // SemanticKITTI layout: sequences/NN/{velodyne,labels}/<stem>.{bin,label}.
    if (scans.filename() == "velodyne") {
        const fs::path sequence = scans.has_parent_path() ? scans.parent_path() : fs::path(".");
        list.sequence_dir = sequence.string();
        if (isDirectory(sequence / "labels")) list.labels_dir = (sequence / "labels").string();
    }
    if (!list.files.empty()) return list;
    for (const std::string& extension : scanExtensions(format)) {
        const auto files = listFiles(list.scans_dir, extension);
        list.files.insert(list.files.end(), files.begin(), files.end());
    }
    std::sort(list.files.begin(), list.files.end());
    if (list.files.empty()) {
        std::string names;
        for (const std::string& extension : scanExtensions(format))
            names += (names.empty() ? "" : ", ") + extension;
        throw InputError("no scans (" + names + ") in " + inQuotes(list.scans_dir));
    }
    return list;
}

}  // namespace travel
