// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Params-only entry points, kept for the callers that need only the ground segmentation: each
// goes through the one Config loader (ConfigIO.cpp). Also where shared data is found.
#include "travel/ParamsIO.hpp"

#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "travel/ConfigFields.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/Text.hpp"

namespace travel {

namespace fs = std::filesystem;

namespace {

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

bool isValidPresetName(const std::string& name) {
    // Names, not paths: keeps `preset:` from reaching outside the presets directories.
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

}  // namespace

bool isAllowedChoice(const std::string& value, const char* choices) {
    return fields::isAllowedChoice(value, choices);
}

void applyParamsText(const std::string& text, const std::string& source_name, Params& params) {
    Config config;
    config.travel = params;
    applyConfigText(text, source_name, config);
    params = config.travel;
}

void applyParamsFile(const std::string& path, Params& params) {
    Config config;
    config.travel = params;
    applyConfigFile(path, config);
    params = config.travel;
}

Params loadPreset(const std::string& name) {
    return loadPresetConfig(name).travel;
}

/// <prefix>/<datadir>/travel when this code runs in a binary installed in <prefix>/<bindir>,
/// <libdir> or the Python package's directory, wherever <prefix> is now (`cmake --install
/// --prefix`, DESTDIR, a moved prefix), existing or not; empty otherwise (the build tree).
static std::string installedShareDirNextToBinary() {
#if defined(TRAVEL_INSTALL_DATADIR) && defined(TRAVEL_INSTALL_BINARY_DIRS)
    // The executable, plugin or Python extension this code was linked into.
    Dl_info info{};
    link_map* map = nullptr;
    if (dladdr1(reinterpret_cast<void*>(&installedShareDirNextToBinary), &info,
                reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) == 0) {
        return {};
    }
    const bool is_executable = map == nullptr || map->l_name == nullptr || *map->l_name == '\0';
    std::error_code ec;
    const fs::path binary =
        fs::canonical(is_executable ? "/proc/self/exe" : info.dli_fname, ec).parent_path();
    if (ec) return {};
    // <prefix>/<one of the install dirs of binaries>/binary -> <prefix>/<datadir>/travel.
    std::string dirs = TRAVEL_INSTALL_BINARY_DIRS;
#ifdef TRAVEL_INSTALL_PYTHON_PACKAGE_DIR
    dirs += std::string(":") + TRAVEL_INSTALL_PYTHON_PACKAGE_DIR;
#endif
    for (const std::string& dir : splitList(dirs, ':')) {
        const fs::path relative = fs::path(dir).lexically_normal();
        if (relative.empty() || relative.is_absolute()) continue;
        fs::path prefix = binary;
        bool matches = true;
        for (auto part = relative.end(); part != relative.begin();) {
            --part;
            if (part->empty()) continue;  // a trailing '/'
            matches = matches && prefix.filename() == *part;
            prefix = prefix.parent_path();
        }
        if (matches) return (prefix / TRAVEL_INSTALL_DATADIR).string();
    }
#endif
    return {};
}

std::vector<std::string> shareSearchDirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("TRAVEL_SHARE_DIR"); env && *env) dirs.emplace_back(env);
    dirs.push_back(installedShareDirNextToBinary());
#ifdef TRAVEL_SOURCE_SHARE_DIR
    dirs.emplace_back(TRAVEL_SOURCE_SHARE_DIR);
#endif
#ifdef TRAVEL_INSTALL_SHARE_DIR
    dirs.emplace_back(TRAVEL_INSTALL_SHARE_DIR);
#endif
    dirs.erase(std::remove(dirs.begin(), dirs.end(), std::string()), dirs.end());
    return dirs;
}

std::string findShareDir() {
    std::error_code ec;
    const auto dirs = shareSearchDirs();
    for (const auto& dir : dirs) {
        if (fs::is_directory(dir, ec)) return dir;
    }
    throw ConfigError("no travel share directory found (searched: " + joined(dirs, ", ") +
                      "); set TRAVEL_SHARE_DIR");
}

std::vector<std::string> availablePresets() {
    std::vector<std::string> names;
    for (const auto& dir : shareSearchDirs()) {
        std::error_code ec;
        for (fs::directory_iterator it(fs::path(dir) / "presets", ec), end; !ec && it != end;
             it.increment(ec)) {
            const fs::path& path = it->path();
            if (path.extension() == ".yaml" && it->is_regular_file(ec)) {
                names.push_back(path.stem().string());
            }
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::string findPresetFile(const std::string& name) {
    const auto dirs = shareSearchDirs();
    if (isValidPresetName(name)) {
        for (const auto& dir : dirs) {
            const fs::path candidate = fs::path(dir) / "presets" / (name + ".yaml");
            std::error_code ec;
            if (fs::is_regular_file(candidate, ec)) return candidate.string();
        }
    }
    std::vector<std::string> searched;
    for (const auto& dir : dirs) searched.push_back((fs::path(dir) / "presets").string());
    const auto available = availablePresets();
    throw ConfigError(std::string("preset '") + name + "'" + " not found; available presets: " +
                      (available.empty() ? "(none)" : joined(available, ", ")) +
                      "; searched: " + (searched.empty() ? "(nothing)" : joined(searched, ", ")) +
                      " (set TRAVEL_SHARE_DIR to add a directory)");
}

void applyOverride(const std::string& key_equals_value, Params& params) {
    const std::string prefix = "override '" + key_equals_value + "': ";
    const std::string scoped = "travel." + key_equals_value;
    Config config;
    config.travel = params;
    try {
        if (key_equals_value.find('=') == std::string::npos) {
            throw ConfigError("override '': expected key=value");
        }
        applyConfigOverride(scoped, config);
    } catch (const ConfigError& e) {
        // The same message, quoting what the caller wrote.
        const std::string what = e.what();
        const std::size_t colon = what.find("': ");
        throw ConfigError(prefix + (colon == std::string::npos ? what : what.substr(colon + 3)));
    }
    params = config.travel;
}

std::string paramsToYaml(const Params& params) {
    return "# TRAVEL ground segmentation parameters. Every key is optional: a missing key keeps\n"
           "# its default. A first line `preset: NAME` starts from share/presets/NAME.yaml.\n" +
           sectionToYaml(params, "");
}

}  // namespace travel
