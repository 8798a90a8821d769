// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The keys of one section of an MRPT CConfigFileBase (as in CMultiMetricMap .ini files), each
// with where it was written (travel/SectionKeys.hpp applies them) and its value read as in any
// other ini file (travel::iniValue: quotes removed), and the writing back.
#pragma once

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

#include "travel/SectionKeys.hpp"

namespace travel_mrpt::config_text {

inline std::vector<travel::SectionKey> readSection(const mrpt::config::CConfigFileBase& source,
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
    std::vector<travel::SectionKey> out;
    for (const std::string& key : keys) {
        travel::SectionKey k{key, "", travel::keyLocation(lines, file, section, key)};
        // MRPT keeps the quotes of `key="value"`: the value is read as in every other ini.
        try {
            k.value = travel::iniValue(source.read_string(section, key, "", true));
        } catch (const travel::ConfigError& e) {
            throw travel::ConfigError(k.where + key + ": " + e.what());
        }
        out.push_back(std::move(k));
    }
    return out;
}

/// Every key of `sections...` as `key = value` in `section` of `target`.
template <class... Sections>
void writeSection(mrpt::config::CConfigFileBase& target, const std::string& section,
                  const Sections&... sections) {
    travel::forEachKeyText(
        [&](const char* name, const std::string& text) { target.write(section, name, text); },
        sections...);
}

}  // namespace travel_mrpt::config_text
