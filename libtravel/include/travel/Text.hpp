// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Small text helpers shared by every layer's messages and name rules.
#pragma once

#include <cctype>
#include <cstdio>
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

/// Length of the UTF-8 sequence starting at bytes[i] (1-4), or 0 when none starts there (a
/// stray continuation byte, an overlong or truncated sequence, a surrogate, beyond U+10FFFF).
inline std::size_t utf8SequenceLength(std::string_view bytes, std::size_t i) {
    const auto at = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
    const unsigned char b = at(i);
    if (b < 0x80) return 1;
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range
    if (b >= 0xC2 && b <= 0xDF)
        n = 2;
    else if (b == 0xE0)
        n = 3, lo = 0xA0;
    else if (b >= 0xE1 && b <= 0xEF)
        n = 3, hi = b == 0xED ? 0x9F : 0xBF;
    else if (b == 0xF0)
        n = 4, lo = 0x90;
    else if (b >= 0xF1 && b <= 0xF4)
        n = 4, hi = b == 0xF4 ? 0x8F : 0xBF;
    if (n == 0 || i + n > bytes.size()) return 0;
    if (at(i + 1) < lo || at(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (at(i + k) < 0x80 || at(i + k) > 0xBF) return 0;
    return n;
}

/// "" when `bytes` are text (UTF-8 without control bytes other than tab, line feed and carriage
/// return), else where they stop being text: "byte 0x00 at offset 12". Readers of text files
/// (configurations, pose files, worlds) check it first, so that a binary file given by mistake
/// (a scan as a configuration) is named as such instead of being echoed by a parser.
inline std::string notTextReason(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size();) {
        const unsigned char b = static_cast<unsigned char>(bytes[i]);
        const std::size_t n = utf8SequenceLength(bytes, i);
        if (n == 0 || (b < 0x20 && b != '\t' && b != '\n' && b != '\r') || b == 0x7F) {
            char reason[64];
            std::snprintf(reason, sizeof reason, "byte 0x%02X at offset %zu", b, i);
            return reason;
        }
        i += n;
    }
    return {};
}

namespace text_detail {
/// Appends `text` to `out` as printableText() does, at most `max_chars` characters (a byte
/// written as \xNN counts as one); returns the number of bytes of `text` used.
inline std::size_t appendPrintable(std::string& out, std::string_view text, std::size_t max_chars) {
    std::size_t shown = 0, i = 0;
    for (; i < text.size() && shown < max_chars; ++shown) {
        const unsigned char b = static_cast<unsigned char>(text[i]);
        std::size_t n = utf8SequenceLength(text, i);
        // C1 controls (U+0080-U+009F: 0xC2 0x80-0x9F) are valid UTF-8 that terminals act on
        // (U+009B is CSI): their two bytes are escaped one by one.
        if (n == 2 && b == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) n = 0;
        if (n == 0 || b < 0x20 || b == 0x7F) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", b);
            out += escaped;
            ++i;
        } else {
            out.append(text.substr(i, n));
            i += n;
        }
    }
    return i;
}
}  // namespace text_detail

/// `text` with every byte a terminal could act on, or that starts no UTF-8 character, written as
/// \xNN (control bytes 0x00-0x1f and 0x7f, tabs and line ends included, and the two bytes of a
/// C1 control U+0080-U+009F): bytes read from a file
/// (a class name, a key, a line) quoted in a one-line message, without sending the terminal
/// their escape sequences. Valid UTF-8 is kept.
inline std::string printableText(std::string_view text) {
    std::string out;
    text_detail::appendPrintable(out, text, text.size());
    return out;
}

/// 'text' for a message that echoes what a user wrote (a value, a line): printableText() in
/// quotes, cut after `max` characters with "... (N bytes)", so that a message stays one readable
/// line whatever the input held.
inline std::string quotedExcerpt(std::string_view text, std::size_t max = 80) {
    std::string out = "'";
    const std::size_t used = text_detail::appendPrintable(out, text, max);
    out += "'";
    if (used < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

}  // namespace travel
