// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TraversabilityMapOptions.hpp"

#include "ConfigText.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"

namespace travel_mrpt {

void TraversabilityMapOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                  const std::string& section) {
    loadFromConfigSections(source, {section});
}

void TraversabilityMapOptions::loadFromConfigSections(const mrpt::config::CConfigFileBase& source,
                                                      const std::vector<std::string>& sections) {
    TraversabilityMapOptions result = *this;
    std::vector<travel::SectionKey> keys;
    std::string names;
    for (const std::string& section : sections) {
        const auto section_keys = config_text::readSection(source, section);
        keys.insert(keys.end(), section_keys.begin(), section_keys.end());
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
