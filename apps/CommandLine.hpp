// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Shared by the apps: MRPT's TCLAP returns false from parse() - after printing the message - on
// a parse error and after --help / --version, instead of exiting. Callers must stop then.
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <exception>
#include <iostream>
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

/// The apps' main(): runs `run`, turning any exception into "<name>: error: ..." on stderr and
/// exit code 1 (never a crash or an uncaught exception).
template <class Run>
int runMain(const char* name, Run&& run, int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const TCLAP::ArgException& e) {
        std::cerr << name << ": " << e.error() << " (" << e.argId() << ")\n";
    } catch (const std::exception& e) {
        std::cerr << name << ": error: " << e.what() << "\n";
    }
    return 1;
}

}  // namespace travel::apps
