// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Shared by the apps: MRPT's TCLAP returns false from parse() - after printing the message - on
// a parse error and after --help / --version, instead of exiting. Callers must stop then.
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <optional>
#include <string>

namespace travel::apps {

/// Parses; returns the exit code to stop with (0 after --help / --version, 1 after an error),
/// or nothing when the program should go on.
inline std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv) {
    if (cmd.parse(argc, argv)) return std::nullopt;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help" || arg == "--version") return 0;
    }
    return 1;
}

}  // namespace travel::apps
