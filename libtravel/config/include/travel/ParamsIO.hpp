// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Loading Params from text: a small YAML subset and ini, no third-party parser.
//
// Accepted syntax (one assignment per line):
//   # comment          ; comment (ini, at line start)      --- (one YAML document marker)
//   key: value         key = value                         value may be "quoted" or 'quoted'
//   [travel]           optional single ini section; any other section is an error
//   travel:            optional YAML wrapper; the keys are then indented beneath it
//   preset: vlp16      only as the first key: start from loadPreset("vlp16"), then apply the rest
// Values: booleans true/false/yes/no/on/off/1/0 (any case); numbers must be the whole string
// (no units, no NaN/inf); integers must be integral and fit an int. Strings are a bare word or
// a quoted string and must be one of the parameter's allowed values (any case; stored as listed).
// Every error is a ConfigError whose message starts with "<source>:<line>: ".
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

/// Where shared data is looked for, in order: $TRAVEL_SHARE_DIR (when set), the source tree's
/// share/ (runs from the build tree), then the installed share/travel. Existing or not.
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
