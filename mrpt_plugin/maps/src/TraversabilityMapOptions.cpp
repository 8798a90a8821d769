// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TraversabilityMapOptions.hpp"

#include <mrpt/config/CConfigFileMemory.h>
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

}  // namespace

void TraversabilityMapOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                  const std::string& section) {
    loadFromSections(source, {section}, {});
}

void TraversabilityMapOptions::loadFromMapDefinition(const mrpt::config::CConfigFileBase& source,
                                                     const std::string& prefix) {
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
