// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Reading and writing a Config (travel/Config.hpp): the one loader of every app and of the MRPT
// modules. Part of travel::config, the I/O component (yaml-cpp, privately); the algorithm core
// (travel::travel) stays Eigen-only.
//
// YAML: top-level maps `travel:`, `filter:`, `map:`, `nav:` (each optional); keys at the root
// belong to `travel` (the presets in share/presets are written so). ini: sections [travel],
// [filter], [map], [nav]; keys before the first section belong to [travel]. A text is ini when
// its first line that is not blank or a comment starts with '[' or is `key = value`.
// `preset: NAME` (root, `travel:` or [travel], before every other key) starts from the whole
// configuration of share/presets/NAME.yaml. Values follow ConfigFields.hpp (whole string,
// locale-independent numbers, ranges, choices). Duplicate keys are errors.
// Every error is a ConfigError "<source>:<line>:<column>: section '<s>': <what>" (line and
// column where known), with "did you mean" for unknown keys and sections.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "travel/Config.hpp"

namespace travel {

/// Applies the text's keys on top of `config`; ranges are checked per key, cross-key rules are
/// not (call Config::validate() once everything is applied).
void applyConfigText(const std::string& text, const std::string& source_name, Config& config);

/// applyConfigText() on the file's contents, then Config::validate() (message prefixed with
/// the path). Throws ConfigError if the file cannot be read.
void applyConfigFile(const std::string& path, Config& config);

/// Defaults plus the file.
Config loadConfigFile(const std::string& path);

/// Defaults plus share/presets/<name>.yaml, validated.
Config loadPresetConfig(const std::string& name);

/// "section.key" split at its first '.', both trimmed; {"", key} for a key without a section.
std::pair<std::string, std::string> sectionAndKey(const std::string& name);

/// One command-line assignment: "section.key=value", or "key=value" for a key that only one
/// section has. Range-checked; call Config::validate() after the last one.
void applyConfigOverride(const std::string& assignment, Config& config);

/// Every section with every key, each preceded by its documentation; loads back identically.
std::string configToYaml(const Config& config);

/// One `key = value` line of an ini text (any section name; keys before the first section
/// have section ""). line and column are 1-based (column of the key).
struct IniEntry {
    std::string section, key, value;
    int line = 0, column = 0;
};
/// The entries of an ini text, in order. Throws ConfigError "<source>:<line>:<col>: ..." on a
/// malformed line.
std::vector<IniEntry> readIni(const std::string& text, const std::string& source_name);
/// An ini value as written after '=': trimmed; a quoted one ("..." or '...', followed by nothing
/// or a comment) is the text between the quotes, an unquoted one ends at a '#' or ';' comment.
/// Throws ConfigError (no position) on an unterminated quote or text after the closing one.
std::string iniValue(std::string_view written);
/// `value` as written after '=' so that iniValue() reads it back: as it is, or in quotes ("..."
/// or '...', one it does not contain) when it holds a comment character or starts with a quote
/// or a blank. Throws ConfigError when no quoting can keep it (it holds both quotes and a comment
/// character).
std::string iniQuoted(const std::string& value);

/// The file's contents; throws ConfigError naming the path.
std::string readConfigFile(const std::string& path);

}  // namespace travel
