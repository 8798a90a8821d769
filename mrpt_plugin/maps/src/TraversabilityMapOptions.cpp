// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TraversabilityMapOptions.hpp"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/format.h>
#include <mrpt/maps/metric_map_types.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>

#include "ConfigText.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/Text.hpp"

namespace travel_mrpt {

namespace {

/// The keys MRPT reads from every map's _creationOpts itself (TMapGenericParams), lower case
/// (MRPT's ini keys and sections are case-insensitive), asked from MRPT.
std::vector<std::string> mrptGenericMapKeys() {
    mrpt::config::CConfigFileMemory text;
    mrpt::maps::TMapGenericParams().saveToConfigFile(text, "generic");
    std::vector<std::string> keys;
    text.getAllKeys("generic", keys);
    // MRPT's writer pads the keys with spaces, and getAllKeys() keeps them.
    for (std::string& key : keys) key = travel::toLower(mrpt::system::trim(key));
    return keys;
}

/// Throws when `source` has a section of this map kind under the CMultiMetricMap section of
/// `prefix` ("<section>_traversabilityMap_NN") that CMultiMetricMap never reads, with keys in it.
void checkNoUnreadMapSections(const mrpt::config::CConfigFileBase& source,
                              const std::string& prefix) {
    static const std::string kKind = "_traversabilityMap_";
    const std::size_t at = prefix.rfind(kKind);
    if (at == std::string::npos) return;  // not a CMultiMetricMap prefix
    const std::string section = prefix.substr(0, at);
    const uint64_t count = source.read_uint64_t(section, "traversabilityMap_count", 0);
    std::vector<std::string> read;  // lower case
    for (uint64_t i = 0; i < count; ++i)
        for (const char* suffix : {"_creationOpts", "_insertOpts"})
            read.push_back(travel::toLower(
                mrpt::format("%s%s%02u%s", section.c_str(), kKind.c_str(), unsigned(i), suffix)));
    const std::string kind_prefix = travel::toLower(section + kKind);
    std::vector<std::string> sections;
    source.getAllSections(sections);
    for (const std::string& name : sections) {
        const std::string lower = travel::toLower(name);
        if (lower.rfind(kind_prefix, 0) != 0 ||
            std::find(read.begin(), read.end(), lower) != read.end())
            continue;
        std::vector<std::string> keys;
        source.getAllKeys(name, keys);
        if (keys.empty()) continue;
        std::string file;
        if (const auto* on_disk = dynamic_cast<const mrpt::config::CConfigFile*>(&source))
            file = on_disk->getAssociatedFile() + ": ";
        const std::string read_names =
            count > 1
                ? "'" + section + kKind + "NN_creationOpts' and '" + section + kKind +
                      "NN_insertOpts', NN from 00 to " + mrpt::format("%02u", unsigned(count - 1))
                : "'" + prefix + "_creationOpts' and '" + prefix + "_insertOpts'";
        throw travel::ConfigError(file + "section '" + name +
                                  "' is never read: CMultiMetricMap reads this map kind's keys "
                                  "from the sections " +
                                  read_names + " (traversabilityMap_count=" +
                                  std::to_string(count) + " in section '" + section + "')");
    }
}

}  // namespace

void TraversabilityMapOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                  const std::string& section) {
    loadFromSections(source, {section}, {});
}

void TraversabilityMapOptions::loadFromMapDefinition(const mrpt::config::CConfigFileBase& source,
                                                     const std::string& prefix) {
    checkNoUnreadMapSections(source, prefix);
    loadFromSections(source, {prefix + "_creationOpts", prefix + "_insertOpts"},
                     mrptGenericMapKeys());
}

void TraversabilityMapOptions::loadFromSections(const mrpt::config::CConfigFileBase& source,
                                                const std::vector<std::string>& sections,
                                                const std::vector<std::string>& mrpt_keys) {
    TraversabilityMapOptions result = *this;
    std::vector<travel::SectionKey> keys;
    std::string names;
    for (std::size_t s = 0; s < sections.size(); ++s) {
        const std::string& section = sections[s];
        for (travel::SectionKey& k : config_text::readSection(source, section)) {
            // MRPT's own keys, in the first section only (where MRPT reads them).
            if (s == 0 && std::find(mrpt_keys.begin(), mrpt_keys.end(), travel::toLower(k.key)) !=
                              mrpt_keys.end())
                continue;
            keys.push_back(std::move(k));
        }
        names += (names.empty() ? "'" : " + '") + section + "'";  // no brackets: keyLocation
    }
    travel::applySectionKeys(keys, result.travel.params, result.map(),
                             static_cast<travel::FilterSection&>(result.travel),
                             result.travel.tracking);
    try {
        result.validate();
    } catch (const travel::ConfigError& e) {
        throw travel::ConfigError("section " + names + ": " + e.what());
    }
    *this = std::move(result);
}

void TraversabilityMapOptions::saveToConfigFile(mrpt::config::CConfigFileBase& target,
                                                const std::string& section) const {
    travel.saveToConfigFile(target, section);
    config_text::writeSection(target, section, map());
}

void TraversabilityMapOptions::loadFromFile(const std::string& path) {
    travel::Config config;
    travel.toConfig(config);
    config.map = map();
    travel::applyConfigFile(path, config);
    travel.fromConfig(config);
    map() = config.map;
}

void TraversabilityMapOptions::validate() const {
    map().validate();
    travel.params.validate();
    travel.validate();
}

}  // namespace travel_mrpt
