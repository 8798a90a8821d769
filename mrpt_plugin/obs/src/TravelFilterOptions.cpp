// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/TravelFilterOptions.hpp"

#include <mrpt/containers/yaml.h>

#include <sstream>

#include "ConfigText.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"

namespace travel_mrpt {
namespace {

/// A scalar as text, whatever type it holds (parsed files hold strings; maps built in code may
/// hold numbers or booleans), single-quoted for YAML so that it reads back as the same text.
std::string quotedScalar(const mrpt::containers::yaml::node_t& node, const std::string& key) {
    if (!node.isScalar())
        throw travel::ConfigError("YAML: '" + key + "': expected a single value, got a " +
                                  node.typeName());
    const std::any& any = node.asScalar();
    std::string text;
    if (const auto* s = std::any_cast<std::string>(&any))
        text = *s;
    else if (const auto* b = std::any_cast<bool>(&any))
        text = *b ? "true" : "false";
    else if (const auto* d = std::any_cast<double>(&any))
        text = travel::fields::format(*d);
    else if (const auto* f = std::any_cast<float>(&any))
        text = travel::fields::format(*f);
    else
        text = node.as<std::string>();
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
}

/// The map as YAML text for travel::applyConfigText: one level of sections, every value
/// quoted. mrpt::containers::yaml keeps a map's keys sorted, not in file order, so `preset`
/// (root or under `travel:`) is written first, where the loader wants it.
std::string yamlText(const mrpt::containers::yaml& cfg) {
    if (!cfg.isMap()) throw travel::ConfigError("YAML: expected a map of key: value");
    std::string preset, rest;
    for (const auto& [key_node, value] : cfg.asMap()) {
        const std::string key = key_node.as<std::string>();
        if (value.isMap()) {
            rest += key + ":\n";
            for (const auto& [sub_key_node, sub_value] : value.asMap()) {
                const std::string sub_key = sub_key_node.as<std::string>();
                const std::string line = sub_key + ": " + quotedScalar(sub_value, sub_key) + "\n";
                if (key == "travel" && sub_key == "preset")
                    preset = line;
                else
                    rest += "  " + line;
            }
        } else if (value.isNullNode()) {
            rest += key + ":\n";
        } else {
            const std::string line = key + ": " + quotedScalar(value, key) + "\n";
            (key == "preset" ? preset : rest) += line;
        }
    }
    return preset + rest;
}

}  // namespace

void TravelFilterOptions::fromConfig(const travel::Config& config) {
    params = config.travel;
    static_cast<travel::FilterSection&>(*this) = config.filter;
    tracking = config.tracking;
}

void TravelFilterOptions::toConfig(travel::Config& config) const {
    config.travel = params;
    config.filter = *this;
    config.tracking = tracking;
}

void TravelFilterOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                             const std::string& section) {
    TravelFilterOptions result = *this;
    const auto keys = config_text::readSection(source, section);
    travel::applySectionKeys(keys, result.params, static_cast<travel::FilterSection&>(result),
                             result.tracking);
    try {
        result.params.validate();
        result.validate();
    } catch (const std::exception& e) {
        throw travel::ConfigError("section '" + section + "': " + e.what());
    }
    *this = std::move(result);
}

void TravelFilterOptions::saveToConfigFile(mrpt::config::CConfigFileBase& target,
                                           const std::string& section) const {
    config_text::writeSection(target, section, params,
                              static_cast<const travel::FilterSection&>(*this), tracking);
}

void TravelFilterOptions::loadFromYaml(const mrpt::containers::yaml& cfg) {
    travel::Config config;
    toConfig(config);
    if (!cfg.isNullNode() && !(cfg.isMap() && cfg.asMap().empty())) {
        travel::applyConfigText(yamlText(cfg), "YAML", config);
    }
    try {
        config.validate();
    } catch (const std::exception& e) {
        throw travel::ConfigError(std::string("YAML: ") + e.what());
    }
    fromConfig(config);
}

void TravelFilterOptions::loadFromFile(const std::string& path) {
    travel::Config config;
    toConfig(config);
    travel::applyConfigFile(path, config);
    fromConfig(config);
}

}  // namespace travel_mrpt
