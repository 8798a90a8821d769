// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One reader for the text files the layers read whole (configurations, pose and calib files,
// nav-sim worlds): a binary file given by mistake is named as such (notTextReason) before any
// parser could echo it.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "travel/Text.hpp"

namespace travel {

/// The whole file at `path`. Throws `Error` (std::runtime_error or derived) naming the file:
/// "<path>: cannot open for reading", "<path>: read error", or "<path>: not a text file (byte
/// 0x00 at offset 12); <expected>".
template <class Error = std::runtime_error>
std::string readTextFile(const std::string& path, const std::string& expected) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(path + ": cannot open for reading");
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (file.bad()) throw Error(path + ": read error");
    std::string text = std::move(bytes).str();
    if (const std::string why = notTextReason(text); !why.empty())
        throw Error(path + ": not a text file (" + why + "); " + expected);
    return text;
}

}  // namespace travel
