// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#pragma once

#include <sstream>
#include <string>

namespace travel_mrpt {

/// MRPT's exception texts span many lines (banner, nested "Message:" lines, call stack): the
/// innermost "Message:" says what went wrong. Its hint about gzip does not apply (both are read).
inline std::string mrptMessage(const std::string& text) {
    std::istringstream lines(text);
    std::string line, message;
    while (std::getline(lines, line)) {
        const std::size_t at = line.find("Message:");
        if (at != std::string::npos && line.find_first_not_of(" \t") == at)
            message = line.substr(line.find_first_not_of(' ', at + 8));
    }
    if (message.empty()) message = text.substr(0, text.find('\n'));
    return message.substr(0, message.find(" (Perhaps it's a gz"));
}

}  // namespace travel_mrpt
