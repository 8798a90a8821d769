// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The apps' command-line parser: CommandLine, MRPT's TCLAP with the project's version
// (--version), examples at the end of --help, and parse errors as one line naming the flag with
// a suggestion ("unknown flag --scans; did you mean -i/--input?") instead of TCLAP's usage dump.
// The flags themselves are declared in CommandLine.hpp.
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/3rdparty/tclap/StdOutput.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "travel/ConfigFields.hpp"  // nearestName

#ifndef TRAVEL_VERSION
#error "TRAVEL_VERSION (CMake's PROJECT_VERSION) is defined for the apps in apps/CMakeLists.txt"
#endif

namespace travel::apps {

/// Flags the one dialect replaced (the project is 0.x: the old spellings are gone, not kept as
/// aliases); giving one gets the new spelling suggested.
inline const std::pair<const char*, const char*> kReplacedFlags[] = {
    {"--scans", "-i/--input"}, {"--scan", "-i/--input"},
    {"-w", "-i/--input"},      {"--world", "-i/--input"},
    {"--out", "-o/--output"},  {"--png-mpp", "--mpp"},
    {"--png-size", "--size"},  {"--print-params", "--print-config"}};

/// "-i/--input" or "--set": how the help and the messages name a flag.
inline std::string flagName(const TCLAP::Arg& arg) {
    if (arg.shortID().rfind('<', 0) == 0) return arg.shortID();  // positional: "<command>"
    return (arg.getFlag().empty() ? "" : "-" + arg.getFlag() + "/") + "--" + arg.getName();
}

/// The declared flag nearest to `given` ("--inptu", "--scans"), as "; did you mean -i/--input?",
/// or "".
inline std::string suggestFlag(TCLAP::CmdLineInterface& cmd, const std::string& given) {
    const std::string bare = given.substr(0, given.find('='));
    std::vector<std::string> names;
    std::vector<const TCLAP::Arg*> args;
    for (const TCLAP::Arg* arg : cmd.getArgList()) {
        if (arg->getName().empty() || arg->getName() == TCLAP::Arg::ignoreNameString()) continue;
        if (arg->shortID().rfind('<', 0) == 0) continue;  // an unlabelled (positional) argument
        names.push_back(arg->getName());
        args.push_back(arg);
    }
    for (const auto& [old_flag, new_flag] : kReplacedFlags)
        for (const TCLAP::Arg* arg : args)  // only a flag this app has
            if (bare == old_flag && flagName(*arg) == new_flag)
                return std::string("; did you mean ") + new_flag + "?";
    const std::string key = bare.substr(std::min(bare.find_first_not_of('-'), bare.size()));
    const std::string best = key.size() < 2 ? "" : travel::fields::nearestName(key, names);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == best) return "; did you mean " + flagName(*args[i]) + "?";
    return "";
}

/// TCLAP's output for the apps: --help with examples, --version as "<app> <version>", and a
/// parse error as one line naming the flag (instead of TCLAP's full usage dump).
class AppOutput : public TCLAP::StdOutput {
  public:
    AppOutput(std::string app, std::vector<std::string> examples)
        : app_(std::move(app)), examples_(std::move(examples)) {}

    void usage(TCLAP::CmdLineInterface& cmd) override {
        TCLAP::StdOutput::usage(cmd);
        std::cout << "Examples:\n";
        for (const std::string& example : examples_) std::cout << "  " << example << "\n";
        std::cout << "\nThe flags every app shares: docs/cli.md\n";
    }
    void version(TCLAP::CmdLineInterface& cmd) override {
        std::cout << app_ << " " << cmd.getVersion() << "\n";
    }
    void failure(TCLAP::CmdLineInterface& cmd, TCLAP::ArgException& e) override {
        failed_ = true;
        std::string id = e.argId();
        if (id.rfind("Argument: ", 0) == 0) id.erase(0, 10);
        if (id.size() > 2 && id.front() == '(' && id.back() == ')')
            id = id.substr(1, id.size() - 2);
        std::string text;
        // A flag where a positional value is expected (travel-eval's command) fails its
        // constraint: "Value '--scans' does not meet constraint: ...".
        const auto quote = e.error().find("Value '-");
        if (quote == 0 && e.error().find("' does not meet constraint") != std::string::npos)
            id = e.error().substr(7, e.error().find('\'', 7) - 7);
        if (e.error().rfind("Couldn't find match", 0) == 0 || quote == 0)
            text = (id.rfind('-', 0) == 0 ? "unknown flag " + id : "unexpected argument " + id) +
                   suggestFlag(cmd, id);
        else if (e.error().rfind("One or more required", 0) == 0)
            for (const TCLAP::Arg* arg : cmd.getArgList())
                if (arg->isRequired() && !arg->isSet())
                    text += (text.empty() ? "missing " : ", ") + flagName(*arg);
        if (text.empty()) text = e.error() + (id.empty() || id == " " ? "" : " (" + id + ")");
        std::cerr << app_ << ": " << text << "\nRun '" << app_
                  << " --help' for the flags and examples.\n";
    }
    bool failed() const { return failed_; }

  private:
    std::string app_;
    std::vector<std::string> examples_;
    bool failed_ = false;
};

/// A command-line mistake found while or after parsing (a missing or contradictory flag): runMain()
/// prints it with the --help hint.
inline TCLAP::CmdLineParseException usageError(const std::string& message) {
    return TCLAP::CmdLineParseException(message);
}

/// An app's command line: TCLAP's CmdLine with the project version and AppOutput. Declare the
/// flags on cmd, then parse().
class CommandLine {
  public:
    CommandLine(const std::string& app, const std::string& description,
                std::vector<std::string> examples)
        : output_(app, std::move(examples)), cmd(description, ' ', TRAVEL_VERSION) {
        // TCLAP's setOutput() neither deletes the StdOutput its constructor allocated nor, once
        // an output was set, deletes it in ~CmdLine: free it here (LeakSanitizer found it).
        std::unique_ptr<TCLAP::CmdLineOutput> tclap_default(cmd.getOutput());
        cmd.setOutput(&output_);
    }
    /// Returns the exit code to stop with (0 after --help / --version, 1 after an error, the
    /// message printed), or nothing when the program should go on.
    std::optional<int> parse(int argc, char** argv) {
        // "-j2" as "-j 2" (getopt's attached value, what make users type) for the short flags
        // that take a value, and "--max-frames=1" as "--max-frames 1" (getopt_long's) for the
        // long ones; TCLAP alone reads both as unknown flags.
        std::vector<std::string> args(argv, argv + argc);
        for (std::size_t i = 1; i < args.size(); ++i) {
            const std::string& a = args[i];
            if (a == "--") break;
            const std::size_t equals = a.find('=');
            if (a.rfind("--", 0) == 0 && equals != std::string::npos) {
                for (const TCLAP::Arg* arg : cmd.getArgList())
                    if (arg->isValueRequired() && arg->getName() == a.substr(2, equals - 2)) {
                        args.insert(args.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                    a.substr(equals + 1));
                        args[i].resize(equals);
                        ++i;
                        break;
                    }
                continue;
            }
            if (a.size() < 3 || a[0] != '-' || a[1] == '-') continue;
            for (const TCLAP::Arg* arg : cmd.getArgList())
                if (arg->isValueRequired() && arg->getFlag() == a.substr(1, 1)) {
                    args.insert(args.begin() + static_cast<std::ptrdiff_t>(i) + 1, a.substr(2));
                    args[i].resize(2);
                    ++i;
                    break;
                }
        }
        // An empty value ("-o ''", "--max-frames=", -o "$UNSET") is a usage error: TCLAP
        // leaves a number at its default and an empty -o would write into the current folder.
        for (std::size_t i = 1; i + 1 < args.size(); ++i) {
            if (args[i] == "--") break;
            for (const TCLAP::Arg* arg : cmd.getArgList()) {
                const bool named = args[i] == "--" + arg->getName() ||
                                   (!arg->getFlag().empty() && args[i] == "-" + arg->getFlag());
                if (!arg->isValueRequired() || !named) continue;
                if (args[i + 1].find_first_not_of(" \t") == std::string::npos)
                    throw usageError(flagName(*arg) + ": empty value");
                ++i;  // the value, whatever it looks like
                break;
            }
        }
        std::vector<const char*> split(args.size());
        for (std::size_t i = 0; i < args.size(); ++i) split[i] = args[i].c_str();
        if (!cmd.parse(static_cast<int>(split.size()), split.data()))
            return output_.failed() ? 1 : 0;
        for (const auto& check : checks) check();  // throw usageError()
        return std::nullopt;
    }
    /// Checks across flags, run after parsing (before the app looks at any file).
    std::vector<std::function<void()>> checks;

  private:
    AppOutput output_;  // declared first: outlives cmd, which does not own it

  public:
    TCLAP::CmdLine cmd;
};

}  // namespace travel::apps
