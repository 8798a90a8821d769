// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/ScanList.hpp"

#include <algorithm>
#include <filesystem>

#include "travel/Errors.hpp"
#include "travel/Text.hpp"

namespace travel {

namespace fs = std::filesystem;

namespace {

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

/// The extensions of `format` as ".bin, .pcd, .ply".
std::string extensionList(ScanFormat format) {
    std::string names;
    for (const std::string& extension : scanExtensions(format))
        names += (names.empty() ? "" : ", ") + extension;
    return names;
}

bool isDirectory(const fs::path& path) {
    std::error_code ec;
    return fs::is_directory(path, ec);
}

}  // namespace

void requireDirectory(const std::string& dir, const std::string& what) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw InputError(what + " " + inQuotes(dir) +
                         (fs::exists(dir, ec) ? " is not a directory" : " does not exist"));
}

std::vector<std::string> listFiles(const std::string& dir, const std::string& extension) {
    requireDirectory(dir, "directory");
    std::error_code ec;
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

std::string lowerCaseExtension(const std::string& path) {
    return toLower(fs::path(path).extension().string());
}

bool isScanPath(const std::string& path, ScanFormat format) {
    const std::vector<std::string> extensions = scanExtensions(format);
    return std::find(extensions.begin(), extensions.end(), lowerCaseExtension(path)) !=
           extensions.end();
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
    for (const std::string& file : listFiles(list.scans_dir, ""))  // sorted by name
        if (isScanPath(file, format)) list.files.push_back(file);
    // A scan's symlink whose target is gone is no regular file, so listFiles() leaves it out:
    // a frame missing from the sequence, said here rather than skipped.
    for (fs::directory_iterator it(list.scans_dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code link_ec;
        if (it->is_symlink(link_ec) && !fs::exists(it->path(), link_ec) &&
            isScanPath(it->path().string(), format))
            throw InputError(inQuotes(it->path().string()) + " is a symlink to a missing file (" +
                             inQuotes(fs::read_symlink(it->path(), link_ec).string()) + ")");
    }
    if (list.files.empty())
        throw InputError("no scans (" + extensionList(format) + ") in " + inQuotes(list.scans_dir));
    // Every output (a .label, a map frame) is named by the scan's stem: two scans with one stem
    // would silently overwrite each other's.
    std::vector<std::pair<std::string, std::string>> stems;  // (stem, file name)
    for (const std::string& file : list.files)
        stems.emplace_back(fs::path(file).stem().string(), fs::path(file).filename().string());
    std::sort(stems.begin(), stems.end());
    for (std::size_t i = 1; i < stems.size(); ++i)
        if (stems[i].first == stems[i - 1].first)
            throw InputError(inQuotes(list.scans_dir) + ": " + stems[i - 1].second + " and " +
                             stems[i].second + " are both scan " + inQuotes(stems[i].first) +
                             " (outputs are named by stem); choose one kind with --format (" +
                             scanFormatNames() + ") or move one away");
    return list;
}

}  // namespace travel
