// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Shared by the apps: command-line parsing (MRPT's TCLAP returns false from parse() - after
// printing the message - on a parse error and after --help / --version, instead of exiting;
// callers must stop then), the parameter sources in their documented order, and main()'s
// one-line error reporting.
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "Interrupt.hpp"
#include "travel/Config.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/Params.hpp"
#include "travel/ParamsIO.hpp"

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

/// MRPT exception texts span many lines (banner, nested "Message:" lines, locations, call
/// stacks); keep the innermost message, which says what went wrong. One-line texts are kept.
inline std::string oneLine(const std::string& text) {
    std::istringstream lines(text);
    std::string line, message, first;
    while (std::getline(lines, line)) {
        const auto start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos) continue;
        line = line.substr(start);
        if (first.empty()) first = line;
        if (line.rfind("Message:", 0) == 0) message = line.substr(line.find_first_not_of(' ', 8));
    }
    std::string best = message.empty() ? first : message;
    // MRPT's hint about gzip is wrong here: the readers accept plain and gzip files alike.
    const auto hint = best.find(" (Perhaps it's a gz");
    if (hint != std::string::npos) best.erase(hint);
    return best.empty() ? text : best;
}

/// --preset (already applied to `config` by the caller), then --config (every section), then
/// each --set (KEY=VALUE or SECTION.KEY=VALUE), then the cross-key checks: the order every app
/// documents.
inline void applyConfigSources(const std::string& config_file,
                               const std::vector<std::string>& overrides, Config& config) {
    if (!config_file.empty()) applyConfigFile(config_file, config);
    for (const std::string& kv : overrides) applyConfigOverride(kv, config);  // errors quote kv
    config.validate();
}

/// The whole configuration of an app: --preset (none: defaults), --config, each --set.
inline Config loadAppConfig(const std::string& preset, const std::string& config_file,
                            const std::vector<std::string>& overrides) {
    Config config = preset.empty() ? Config() : loadPresetConfig(preset);
    applyConfigSources(config_file, overrides, config);
    return config;
}

/// The same for the apps that run the ground segmentation only: the other sections of the file
/// are checked and ignored.
inline void applyParamSources(const std::string& config_file,
                              const std::vector<std::string>& overrides, Params& params) {
    Config config;
    config.travel = params;
    applyConfigSources(config_file, overrides, config);
    params = config.travel;
}

/// Every app's --print-config switch: every section with its documentation, as YAML that
/// --config reads back identically.
struct PrintConfigFlag {
    mutable TCLAP::SwitchArg arg;  // TCLAP's getValue() is not const
    explicit PrintConfigFlag(TCLAP::CmdLine& cmd)
        : arg("", "print-config",
              "Print the effective configuration (every section, documented) as YAML and exit", cmd,
              false) {}
    /// Prints and returns true when the flag was given.
    bool print(const Config& config) const {
        if (!arg.getValue()) return false;
        std::cout << configToYaml(config);
        return true;
    }
};

/// The configuration flags of the apps, one dialect: -p/--preset NAME, -c/--config FILE,
/// --set [SECTION.]KEY=VALUE (repeatable), --print-config. load() applies them in that order on
/// top of `defaults` (preset, file, each --set, then the cross-key checks).
struct ConfigFlags {
    mutable TCLAP::ValueArg<std::string> preset;  // TCLAP's getValue() is not const
    mutable TCLAP::ValueArg<std::string> config;
    mutable TCLAP::MultiArg<std::string> set;
    PrintConfigFlag print_config;

    /// `default_preset`: "" starts from the built-in defaults (HDL-64E on KITTI).
    ConfigFlags(TCLAP::CmdLine& cmd, const std::string& default_preset)
        : preset("p", "preset",
                 "Sensor preset from share/presets (" + presetNames() + "), applied first" +
                     (default_preset.empty() ? "" : " (default " + default_preset + ")"),
                 false, default_preset, "NAME", cmd),
          config("c", "config",
                 "Configuration file applied after the preset: YAML with the sections travel:, "
                 "filter:, map:, nav: (keys at the root are travel's), or ini with [travel] ... "
                 "[nav] (docs/parameters.md)",
                 false, "", "FILE", cmd),
          set("", "set",
              "Set one key, applied last (repeatable): KEY=VALUE or SECTION.KEY=VALUE, e.g. "
              "--set sensor_height=1.9 --set map.resolution=0.25",
              false, "[SECTION.]KEY=VALUE", cmd),
          print_config(cmd) {}

    Config load(Config defaults = {}) const {
        if (!preset.getValue().empty())
            applyConfigFile(findPresetFile(preset.getValue()), defaults);
        applyConfigSources(config.getValue(), set.getValue(), defaults);
        return defaults;
    }
    /// Prints the configuration and returns true when --print-config was given.
    bool print(const Config& configuration) const { return print_config.print(configuration); }
    /// "preset P, config F, K=V, ..." for reports.
    std::string describe() const {
        std::string text = "preset " + (preset.getValue().empty() ? "none" : preset.getValue());
        if (config.isSet()) text += ", config " + config.getValue();
        for (const std::string& kv : set.getValue()) text += ", " + kv;
        return text;
    }

  private:
    static std::string presetNames() {
        try {
            std::string list;
            for (const std::string& name : availablePresets())
                list += (list.empty() ? "" : ", ") + name;
            return list;
        } catch (const std::exception&) {
            return "none found";
        }
    }
};

/// The apps' main(): runs `run`, turning any exception into one line on stderr,
/// "<name>: configuration error: ..." or "<name>: error: ...", and exit code 1 (never a crash
/// or an uncaught exception). Ctrl-C / SIGTERM: "<name>: interrupted" and exit code 130, after
/// the stack unwound (temporary files and partial outputs removed).
template <class Run>
int runMain(const char* name, Run&& run, int argc, char** argv) {
    installInterruptHandlers();
    try {
        const int code = run(argc, argv);
        if (!interrupted()) return code;
        std::cerr << name << ": interrupted\n";  // after the outputs were completed
        return kInterruptedExitCode;
    } catch (const Interrupted&) {
        std::cerr << name << ": interrupted\n";
        return kInterruptedExitCode;
    } catch (const TCLAP::ArgException& e) {
        std::cerr << name << ": " << e.error() << " (" << e.argId() << ")\n";
    } catch (const ConfigError& e) {
        std::cerr << name << ": configuration error: " << oneLine(e.what()) << "\n";
    } catch (const std::exception& e) {
        std::cerr << name << ": error: " << oneLine(e.what()) << "\n";
    } catch (...) {
        std::cerr << name << ": error: unknown exception\n";
    }
    return 1;
}

}  // namespace travel::apps
