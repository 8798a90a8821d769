// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Text <-> value helpers shared by the option loaders of the filter and the map layer (private
// to mrpt_plugin). Errors are travel::ConfigError prefixed with `where` ("section [x]: key").
#pragma once

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "travel/Errors.hpp"

namespace travel_mrpt::config_text {

inline std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// true/false, yes/no, on/off, 1/0 (any case).
inline bool parseBool(const std::string& text, const std::string& where) {
    const std::string v = lower(text);
    if (v == "true" || v == "yes" || v == "on" || v == "1") return true;
    if (v == "false" || v == "no" || v == "off" || v == "0") return false;
    throw travel::ConfigError(where + ": expected true/false, got '" + text + "'");
}

/// A finite number that is the whole text (no units, no trailing characters).
inline double parseNumber(const std::string& text, const std::string& where) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
        throw travel::ConfigError(where + ": expected a number, got '" + text + "'");
    return v;
}

/// Shortest decimal text that reads back to exactly `v` (saved configs reload bit-identical).
inline std::string exactText(double v) {
    char buf[40];
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

}  // namespace travel_mrpt::config_text
