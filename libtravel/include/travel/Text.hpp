// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Small text helpers shared by every layer's messages and name rules.
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace travel {

/// 'text': how messages quote a path, a key or a value.
inline std::string inQuotes(const std::string& text) {
    return "'" + text + "'";
}

/// `text` in lower case (ASCII): names and extensions compared case-insensitively.
inline std::string toLower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace travel
