// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Small text helpers shared by every layer's messages and name rules.
#pragma once

#include <cctype>
#include <string>
#include <string_view>
#include <vector>

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

/// `text` with every ASCII control character (bytes 0x00-0x1f and 0x7f, tabs and line ends
/// included) replaced by '?': bytes read from a file (a class name, a key) quoted in a one-line
/// message, without sending a terminal their escape sequences. Other bytes (UTF-8) are kept.
inline std::string withoutControlCharacters(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return text;
}

/// "a,b,c" -> {"a", "b", "c"} for sep ','; "" -> {}; "a,,b" and "a,b," keep their empty items.
inline std::vector<std::string> splitList(std::string_view text, char sep) {
    std::vector<std::string> items;
    if (text.empty()) return items;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(sep, start);
        items.emplace_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) return items;
        start = end + 1;
    }
}

}  // namespace travel
