// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One line from an MRPT exception's text, for every message that passes one on (the readers,
// the map layer, the apps' main()).
#pragma once

#include <cctype>
#include <sstream>
#include <string>

#include "travel/Text.hpp"

namespace travel_mrpt {

/// MRPT's exception texts span many lines (a banner, nested "Message:" lines, locations, a call
/// stack): the innermost "Message:" says what went wrong; without one, the first line that is
/// neither the banner nor the call stack (e.g. OpenCV's error). MRPT's hint about gzip is dropped
/// (the readers take plain and gzip files alike). A one-line text is kept as it is. Control
/// characters (MRPT quotes what it read, e.g. the class name of a corrupt record) and bytes of no
/// UTF-8 character are written as \xNN (travel::printableText).
inline std::string mrptMessage(const std::string& text) {
    std::istringstream lines(text);
    std::string line, message, first;
    while (std::getline(lines, line)) {
        const auto start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos) continue;
        line = line.substr(start, line.find_last_not_of(" \t\r") + 1 - start);
        if (line.rfind("====", 0) == 0 || line.rfind("Call stack backtrace:", 0) == 0 ||
            (line.size() > 1 && line[0] == '[' &&
             std::isdigit(static_cast<unsigned char>(line[1]))))
            continue;
        if (first.empty()) first = line;
        if (line.rfind("Message:", 0) == 0) {
            const auto at = line.find_first_not_of(' ', 8);
            message = at == std::string::npos ? "" : line.substr(at);
        }
    }
    std::string best = message.empty() ? first : message;
    const auto hint = best.find(" (Perhaps it's a gz");
    if (hint != std::string::npos) best.erase(hint);
    return travel::printableText(best.empty() ? text : best);
}

}  // namespace travel_mrpt
