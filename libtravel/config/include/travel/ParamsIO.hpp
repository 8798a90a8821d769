// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Params only (the `travel` section): for callers that run the ground segmentation and nothing
// else. Every function goes through the one configuration loader (travel/ConfigIO.hpp): same
// syntax (YAML sections or ini, keys at the root = travel), same per-key rules and messages
// ("<source>:<line>:<column>: section 'travel': ..."); other sections of a file are checked
// and ignored. Also where shared data (presets) is found.
#pragma once

#include <string>
#include <vector>

#include "travel/Params.hpp"

namespace travel {

/// Apply the assignments in `text` to `params`. Each value is checked against its range as it is
/// read, but cross-parameter consistency is not (call Params::validate() once everything is
/// applied). A `preset:` key replaces `params` by loadPreset(name) before the rest is applied.
/// Duplicate keys are an error. `source_name` prefixes messages ("file.yaml:12: ...").
void applyParamsText(const std::string& text, const std::string& source_name, Params& params);

/// applyParamsText() on the file's contents, then Params::validate() (its message is prefixed
/// with the path). Throws ConfigError if the file cannot be read.
void applyParamsFile(const std::string& path, Params& params);

/// Default Params plus share/presets/<name>.yaml, validated.
Params loadPreset(const std::string& name);

/// Path of presets/<name>.yaml in the first of shareSearchDirs() that has it. Throws ConfigError
/// listing the available presets and the directories searched when there is none.
std::string findPresetFile(const std::string& name);

/// Names (without .yaml) of the presets in all shareSearchDirs(), sorted, without duplicates.
std::vector<std::string> availablePresets();

/// Where shared data is looked for, in order: $TRAVEL_SHARE_DIR (when set), share/travel of the
/// prefix the running binary is installed in (found from the binary's own path, so a moved
/// prefix works), the source tree's share/ (runs from the build tree), then share/travel of the
/// configured CMAKE_INSTALL_PREFIX. Existing or not.
std::vector<std::string> shareSearchDirs();

/// The first existing directory of shareSearchDirs(); throws ConfigError if none exists.
std::string findShareDir();

/// Apply one "key=value" assignment (command-line style, e.g. "tgf_resolution=4"). The value is
/// range-checked; call Params::validate() after the last override.
void applyOverride(const std::string& key_equals_value, Params& params);

/// True when `value` is one of the '|'-separated `choices` ("auto|field|table"), exactly.
bool isAllowedChoice(const std::string& value, const char* choices);

/// Every parameter as "key: value", each preceded by "# [unit] description (range)", or for
/// strings "# description (one of a|b|c)". Doubles are written with the shortest text that reads
/// back to the same value, so applyParamsText(paramsToYaml(p)) reproduces p exactly.
std::string paramsToYaml(const Params& params);

}  // namespace travel
