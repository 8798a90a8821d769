// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TravelFilterOptions.hpp"

#include <mrpt/containers/yaml.h>

#include <sstream>

#include "ConfigText.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"

namespace travel_mrpt {
namespace {

void commit(const travel::Config& config, TravelFilterOptions& options) {
    options.params = config.travel;
    static_cast<travel::FilterSection&>(options) = config.filter;
}

travel::Config toConfig(const TravelFilterOptions& options) {
    travel::Config config;
    config.travel = options.params;
    config.filter = options;
    return config;
}

// mrpt::containers::yaml keeps a map's keys sorted, not in file order: a `preset:` line (root or
// under `travel:`) is moved to the top, where the loader wants it.
std::string presetFirst(const std::string& text) {
    std::istringstream lines(text);
    std::string preset, rest;
    for (std::string line; std::getline(lines, line);) {
        const std::size_t start = line.find_first_not_of(' ');
        if (preset.empty() && start != std::string::npos && start <= 2 &&
            line.compare(start, 7, "preset:") == 0) {
            preset = "preset:" + line.substr(start + 7) + "\n";
        } else {
            rest += line + "\n";
        }
    }
    return preset + rest;
}

}  // namespace

void TravelFilterOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                             const std::string& section) {
    TravelFilterOptions result = *this;
    const auto keys = config_text::readSection(source, section);
    config_text::applySection(keys, result.params, static_cast<travel::FilterSection&>(result));
    try {
        result.params.validate();
        result.validate();
    } catch (const std::exception& e) {
        throw travel::ConfigError("section [" + section + "]: " + e.what());
    }
    *this = std::move(result);
}

void TravelFilterOptions::saveToConfigFile(mrpt::config::CConfigFileBase& target,
                                           const std::string& section) const {
    config_text::writeSection(target, section, params,
                              static_cast<const travel::FilterSection&>(*this));
}

void TravelFilterOptions::loadFromYaml(const mrpt::containers::yaml& cfg) {
    travel::Config config = toConfig(*this);
    if (!cfg.isNullNode() && !(cfg.isMap() && cfg.asMap().empty())) {
        std::ostringstream printed;
        cfg.printAsYAML(printed);
        travel::applyConfigText(presetFirst(printed.str()), "YAML", config);
    }
    try {
        config.validate();
    } catch (const std::exception& e) {
        throw travel::ConfigError(std::string("YAML: ") + e.what());
    }
    commit(config, *this);
}

void TravelFilterOptions::loadFromFile(const std::string& path) {
    travel::Config config = toConfig(*this);
    travel::applyConfigFile(path, config);
    commit(config, *this);
}

}  // namespace travel_mrpt
