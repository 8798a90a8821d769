// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The keys of one section of an MRPT CConfigFileBase (as in CMultiMetricMap .ini files), each
// with where it was written: "<file>:<line>:<col>: section [<name>]: " when the source is a
// CConfigFile, "section [<name>]: " otherwise. Values are applied by travel::assignFlatKey
// (travel/ConfigFields.hpp): the same parsing and messages as every other loader.
#pragma once

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

#include "travel/ConfigFields.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace travel_mrpt::config_text {

struct SectionKey {
    std::string key, value, where;
};

inline std::vector<SectionKey> readSection(const mrpt::config::CConfigFileBase& source,
                                           const std::string& section) {
    std::vector<travel::IniEntry> lines;
    std::string file;
    if (const auto* on_disk = dynamic_cast<const mrpt::config::CConfigFile*>(&source)) {
        file = on_disk->getAssociatedFile();
        try {
            lines = travel::readIni(travel::readConfigFile(file), file);
        } catch (const travel::ConfigError&) {
            lines.clear();  // MRPT read it; positions are only a courtesy
        }
    }
    std::vector<std::string> keys;
    source.getAllKeys(section, keys);
    std::vector<SectionKey> out;
    for (const std::string& key : keys) {
        std::string where = "section [" + section + "]: ";
        for (const auto& e : lines)
            if (e.section == section && e.key == key)
                where = file + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) +
                        ": " + where;
        out.push_back({key, source.read_string(section, key, "", true), where});
    }
    return out;
}

/// `preset` first (replacing `params`), then every other key through travel::assignFlatKey on
/// `sections...`; errors name where the key was written.
template <class... Sections>
void applySection(const std::vector<SectionKey>& keys, travel::Params& params,
                  Sections&... sections) {
    for (const auto& k : keys) {
        if (k.key != "preset") continue;
        try {
            params = travel::loadPreset(k.value);
        } catch (const std::exception& e) {
            throw travel::ConfigError(k.where + "preset: " + e.what());
        }
    }
    for (const auto& k : keys) {
        if (k.key == "preset") continue;
        try {
            travel::assignFlatKey(k.key, k.value, sections..., params);
        } catch (const std::exception& e) {
            throw travel::ConfigError(k.where + e.what());
        }
    }
}

/// Every key of `sections...` as `key = value` (shortest exact text; strings as they are, since
/// MRPT's ini reader keeps quotes).
template <class... Sections>
void writeSection(mrpt::config::CConfigFileBase& target, const std::string& section,
                  const Sections&... sections) {
    (travel::visitFields(sections,
                         [&](const char* name, const auto& value, const char* unit, auto&&...) {
                             using T = travel::fields::Bare<decltype(value)>;
                             if constexpr (std::is_same_v<T, std::string>) {
                                 target.write(section, name, value);
                             } else {
                                 target.write(section, name,
                                              travel::fields::formatAny(value, unit));
                             }
                         }),
     ...);
}

}  // namespace travel_mrpt::config_text
