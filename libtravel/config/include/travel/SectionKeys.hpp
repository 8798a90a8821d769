// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The keys of one configuration section read by a foreign loader (MRPT's CConfigFileBase, as in
// CMultiMetricMap .ini files), each with where it was written, applied with the same parsing
// and messages as every other loader (travel::assignFlatKey, ConfigFields.hpp), and the text
// each key is written back as.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "travel/ConfigFields.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace travel {

struct SectionKey {
    /// `where` prefixes error messages: "<file>:<line>:<col>: section '<name>': " when the
    /// position is known, "section '<name>': " otherwise, as travel's own config messages. No
    /// brackets: MRPT's exception wrapper (errors raised through CMultiMetricMap) reads
    /// "...[x]" as "file: [function]" and cuts the message there.
    std::string key, value, where;
};

/// The `where` of `key` in `section`, looked up in the ini lines of `file` (empty when the
/// text was not read from a file).
inline std::string keyLocation(const std::vector<IniEntry>& lines, const std::string& file,
                               const std::string& section, const std::string& key) {
    std::string where = "section '" + section + "': ";
    for (const auto& e : lines)
        if (e.section == section && e.key == key)
            where =
                file + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": " + where;
    return where;
}

/// `preset` first (replacing `params`), then every other key through travel::assignFlatKey on
/// `sections...`; errors name where the key was written. `keys` may come from several sections
/// read as one (a CMultiMetricMap's creation and insertion sections): the preset is the base of
/// them all, and a second `preset` is an error naming both places.
template <class... Sections>
void applySectionKeys(const std::vector<SectionKey>& keys, Params& params, Sections&... sections) {
    const SectionKey* preset = nullptr;
    for (const auto& k : keys) {
        if (k.key != "preset") continue;
        if (preset)
            throw ConfigError(k.where + "a second preset (the first: " + preset->where +
                              "preset=" + preset->value + "): give one, keys set the rest");
        preset = &k;
        try {
            params = loadPreset(k.value);
        } catch (const std::exception& e) {
            throw ConfigError(k.where + "preset: " + e.what());
        }
    }
    for (const auto& k : keys) {
        if (k.key == "preset") continue;
        try {
            assignFlatKey(k.key, k.value, sections..., params);
        } catch (const std::exception& e) {
            throw ConfigError(k.where + e.what());
        }
    }
}

/// Calls write(name, text) for every key of `sections...`: the shortest exact text of its
/// value, strings as they are.
template <class Write, class... Sections>
void forEachKeyText(Write&& write, const Sections&... sections) {
    (visitFields(sections,
                 [&](const char* name, const auto& value, const char* unit, auto&&...) {
                     using T = fields::Bare<decltype(value)>;
                     if constexpr (std::is_same_v<T, std::string>) {
                         write(name, iniQuoted(value));  // read back through iniValue
                     } else {
                         write(name, fields::formatAny(value, unit));
                     }
                 }),
     ...);
}

}  // namespace travel
