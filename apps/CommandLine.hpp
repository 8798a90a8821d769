// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Shared by the apps: the one command-line dialect (docs/cli.md), declared here once:
// CommonFlags (-i/-o/-f/-q/-v and the configuration flags), PictureFlags (--mpp, --size),
// MaxFramesFlag, JobsFlag, MemoryLimitFlag (createFolder and AppError: OutputFolder.hpp), the
// parameter sources in their documented order, and main()'s one-line error reporting. The parser
// itself (CommandLine: version, examples, "did you mean") is in CommandLineParser.hpp.
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "CommandLineParser.hpp"
#include "Interrupt.hpp"
#include "MemoryLimit.hpp"  // kDefaultMemoryLimitMiB
#include "OrderedWork.hpp"  // defaultJobs
#include "OutputFolder.hpp"
#include "travel/Config.hpp"
#include "travel/ConfigFields.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/Params.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Text.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel_mrpt/MrptMessage.hpp"

namespace travel::apps {

/// The app's own flags for configuration keys (travel-map's --resolution): set them in `config`.
using AppConfigFlags = std::function<void(Config& config)>;

/// --preset (already applied to `config` by the caller), then --config (every section), then
/// the app's own flags for configuration keys, then each --set (KEY=VALUE or SECTION.KEY=VALUE),
/// then the cross-key checks: the order every app documents.
inline void applyConfigSources(const std::string& config_file,
                               const std::vector<std::string>& overrides, Config& config,
                               const AppConfigFlags& app_flags = {}) {
    if (!config_file.empty()) applyConfigFile(config_file, config);
    if (app_flags) app_flags(config);
    for (const std::string& kv : overrides) applyConfigOverride(kv, config);  // errors quote kv
    config.validate();
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
/// top of `defaults` (preset, file, the app's own flags for configuration keys, each --set, then
/// the cross-key checks).
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
                 "filter:, map:, nav:, regress:, tracking: (keys at the root are travel's), or "
                 "ini with [travel] ... [tracking] (docs/parameters.md)",
                 false, "", "FILE", cmd),
          set("", "set",
              "Set one key, applied last (repeatable): KEY=VALUE or SECTION.KEY=VALUE, e.g. "
              "--set sensor_height=1.9 --set map.resolution=0.25",
              false, "[SECTION.]KEY=VALUE", cmd),
          print_config(cmd) {}

    Config load(Config defaults = {}, const AppConfigFlags& app_flags = {}) const {
        if (!preset.getValue().empty())
            applyConfigFile(findPresetFile(preset.getValue()), defaults);
        applyConfigSources(config.getValue(), set.getValue(), defaults, app_flags);
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
            return list.empty() ? "none found" : list;
        } catch (const std::exception&) {
            return "none found";
        }
    }
};

/// -i/--input: a MultiArg, shown in --help as repeatable only where the app reads several inputs.
class InputArg : public TCLAP::MultiArg<std::string> {
  public:
    InputArg(const std::string& description, bool repeatable, TCLAP::CmdLine& cmd)
        : MultiArg("i", "input", description, false, "PATH", cmd), repeatable_(repeatable) {}
    std::string shortID(const std::string& val) const override {
        return repeatable_ ? MultiArg::shortID(val) : Arg::shortID(_typeDesc);
    }
    std::string longID(const std::string& val) const override {
        return repeatable_ ? MultiArg::longID(val) : Arg::longID(_typeDesc);
    }

  private:
    bool repeatable_;
};

/// The flags every app takes, with the same meaning everywhere (docs/cli.md): -i/--input,
/// -o/--output, -f/--format, -q/--quiet, -v/--verbose and the ConfigFlags.
struct CommonFlags {
    mutable InputArg input;  // TCLAP's getValue() is not const
    mutable TCLAP::ValueArg<std::string> output;
    ConfigFlags config;
    mutable TCLAP::ValueArg<std::string> format;
    mutable TCLAP::SwitchArg quiet_arg, verbose_arg;

    /// `repeatable_input`: the app reads several inputs (-i A -i B); `default_preset` as
    /// ConfigFlags'.
    CommonFlags(CommandLine& line, bool repeatable_input, const std::string& default_preset)
        : CommonFlags(line.cmd, repeatable_input, default_preset) {
        line.checks.push_back([this] {
            if (quiet_arg.getValue() && verbose_arg.getValue())
                throw usageError("-q/--quiet and -v/--verbose contradict each other");
        });
    }
    CommonFlags(TCLAP::CmdLine& cmd, bool repeatable_input, const std::string& default_preset)
        : input(
              "Input: a scan (.bin, .pcd, .ply), a folder of scans, a KITTI sequence folder "
              "(velodyne/; labels/ found automatically), a rawlog or a Velodyne .pcap, "
              "whichever this app reads (see above)",
              repeatable_input, cmd),
          output("o", "output", "Output file or folder (see above); folders are created", false, "",
                 "PATH", cmd),
          config(cmd, default_preset),
          format("f", "format",
                 std::string("Scan file format: ") + scanFormatNames() +
                     " (auto: decided from the file name, folder and contents, never guessed)",
                 false, "auto", "NAME", cmd),
          quiet_arg("q", "quiet", "Print nothing but errors", cmd),
          verbose_arg("v", "verbose", "Print more (per-frame details, library debug logs)", cmd),
          repeatable_(repeatable_input) {}

    /// Every -i, in order; `fallback` (when not empty) if none was given.
    std::vector<std::string> inputs(const std::string& fallback = "") const {
        if (input.getValue().empty() && fallback.empty())
            throw usageError("missing -i/--input PATH");
        if (input.getValue().size() > 1 && !repeatable_)
            throw usageError("-i/--input given " + std::to_string(input.getValue().size()) +
                             " times: this app reads one input");
        return input.getValue().empty() ? std::vector<std::string>{fallback} : input.getValue();
    }
    /// The one -i (required unless `fallback` is given).
    std::string inputPath(const std::string& fallback = "") const {
        return inputs(fallback).front();
    }
    /// The -o (required unless `fallback` is given).
    std::string outputPath(const std::string& fallback = "") const {
        if (!output.isSet() && fallback.empty()) throw usageError("missing -o/--output PATH");
        return output.isSet() ? output.getValue() : fallback;
    }
    /// -f as ScanFormat (ConfigError listing the names when unknown).
    ScanFormat scanFormat() const { return scanFormatFromString(format.getValue()); }
    /// For the apps whose inputs are not scan files (rawlogs, pcaps, worlds).
    void requireAutoFormat(const std::string& what) const {
        if (format.getValue() != "auto")
            throw usageError("-f/--format " + format.getValue() + ": this app reads " + what +
                             ", recognised by their contents; only -f auto");
    }
    bool quiet() const { return quiet_arg.getValue(); }
    bool verbose() const { return verbose_arg.getValue(); }

  private:
    bool repeatable_;
};

/// A number inside a flag's value that TCLAP does not read itself (the parts of --probe X,Y and
/// --extent): by the configuration's rule (travel::fields::parse: decimal, finite, the whole
/// text, locale-independent; no hex, no nan/inf), blanks around it allowed. A usage error naming
/// `flag` otherwise.
inline double parseNumber(const std::string& text, const std::string& flag) {
    const std::size_t first = text.find_first_not_of(" \t");
    const std::string trimmed = first == std::string::npos
                                    ? ""
                                    : text.substr(first, text.find_last_not_of(" \t") + 1 - first);
    double value = 0;
    const std::string why = fields::parse(trimmed, value);
    if (!why.empty()) throw usageError(flag + ": " + why);
    return value;
}

/// `count` comma-separated numbers (parseNumber each) of `flag`'s value `text`; `expected`
/// names them for the message ("X,Y in metres").
inline std::vector<double> parseNumbers(const std::string& text, std::size_t count,
                                        const std::string& flag, const std::string& expected) {
    const std::vector<std::string> parts = travel::splitList(text, ',');
    if (parts.size() != count)
        throw usageError(flag + ": expected " + expected + ", got '" + text + "'");
    std::vector<double> values;
    for (const std::string& part : parts) values.push_back(parseNumber(part, flag));
    return values;
}

/// The bird's-eye picture flags of travel-view, travel-rawlog and travel-regress: --mpp and --size.
struct PictureFlags {
    mutable TCLAP::ValueArg<double> mpp;  // TCLAP's getValue() is not const
    mutable TCLAP::ValueArg<int> size;
    explicit PictureFlags(TCLAP::CmdLine& cmd)
        : mpp("", "mpp", "Picture scale: metres per pixel (default 0.075: +/-30 m in 800 px)",
              false, 0.075, "M", cmd),
          size("", "size", "Picture (panel) side in pixels, 64 to 8192 (default 800)", false, 800,
               "PX", cmd) {}
    /// --mpp or --size given where no picture is drawn is a usage error, not ignored: `drawn`
    /// says whether this run draws any, `needs` names the flag that makes it draw.
    void requirePictures(bool drawn, const std::string& needs) const {
        if ((mpp.isSet() || size.isSet()) && !drawn)
            throw usageError("--mpp and --size need " + needs);
    }
    double metresPerPixel() const {
        if (!(mpp.getValue() > 0) || !std::isfinite(mpp.getValue()))
            throw usageError("--mpp must be > 0");
        return mpp.getValue();
    }
    int sidePixels() const {
        if (size.getValue() < 64 || size.getValue() > 8192)
            throw usageError("--size must be in [64, 8192]");
        return size.getValue();
    }
};

/// --max-frames N, for the apps that read a sequence: the first N frames, 0 (the default) = all;
/// a negative N is a usage error.
struct MaxFramesFlag {
    mutable TCLAP::ValueArg<long> arg;  // TCLAP's getValue() is not const
    /// `what`: the frames as the app's --help names them ("scans", "labelled frames").
    MaxFramesFlag(CommandLine& line, const std::string& what)
        : arg("", "max-frames", "Process at most the first N " + what + " (0 = all, the default)",
              false, 0, "N", line.cmd) {
        line.checks.push_back([this] {
            if (arg.getValue() < 0) throw usageError("--max-frames must be >= 0 (0 = all)");
        });
    }
    /// N, 0 = all.
    long count() const { return arg.getValue(); }
    /// Keeps the first N of `items` (all when N is 0).
    template <class T>
    void keepFirst(std::vector<T>& items) const {
        if (count() > 0 && items.size() > static_cast<std::size_t>(count())) items.resize(count());
    }
};

/// -j N, --jobs N, for the batch apps: N worker threads, each with its own Pipeline (the
/// library is single-threaded per instance); outputs are identical to -j 1 and in input order
/// (OrderedWork.hpp). Default: the number of cores; 0 is a usage error.
struct JobsFlag {
    mutable TCLAP::ValueArg<long> arg;  // TCLAP's getValue() is not const
    /// `what`: what the workers process, as the app's --help names it ("scans"); `how`: how
    /// the threads share the work, if not one pipeline each.
    JobsFlag(CommandLine& line, const std::string& what,
             const std::string& how = "one pipeline each")
        : arg("j", "jobs",
              "Process " + what + " on N threads, " + how +
                  "; output identical to -j 1 "
                  "and in input order (default: the number of cores, here " +
                  std::to_string(defaultJobs()) + ")",
              false, static_cast<long>(defaultJobs()), "N", line.cmd) {
        line.checks.push_back([this] {
            if (arg.getValue() < 1) throw usageError("-j must be >= 1");
        });
    }
    unsigned count() const { return static_cast<unsigned>(std::min<long>(arg.getValue(), 256)); }
};

/// --max-memory MIB, for the apps that read MRPT files (travel-map, travel-rawlog; see
/// MemoryLimit.hpp for why).
struct MemoryLimitFlag {
    mutable TCLAP::ValueArg<long> arg;  // TCLAP's getValue() is not const
    explicit MemoryLimitFlag(TCLAP::CmdLine& cmd)
        : arg("", "max-memory",
              "Address-space ceiling of this process in MiB (0 = none). A corrupt rawlog can "
              "announce gigabyte-sized objects that MRPT's reader would allocate; above the "
              "ceiling the record is reported as corrupt instead. Default " +
                  std::to_string(kDefaultMemoryLimitMiB),
              false, static_cast<long>(kDefaultMemoryLimitMiB), "MIB", cmd) {}
    std::size_t mib() const {
        // At most 2^30 MiB (1 PiB): the ceiling in bytes must fit the 64-bit rlim_t.
        if (arg.getValue() < 0 || (arg.getValue() > 0 && arg.getValue() < 256) ||
            arg.getValue() > (1L << 30))
            throw usageError(
                "--max-memory must be 0 (no limit) or 256 to 1073741824 MiB (the default " +
                std::to_string(kDefaultMemoryLimitMiB) + " suits every rawlog we know)");
        return static_cast<std::size_t>(arg.getValue());
    }
};

/// After an allocation or a thread start failed: the address-space ceiling, when one is set.
inline std::string memoryLimitNote() {
    if (applied_memory_limit_mib == 0) return "";
    return " (out of memory within --max-memory " + std::to_string(applied_memory_limit_mib) +
           " MiB of address space: raise it, or give 0 for no ceiling)";
}

/// The apps' main(): runs `run`, turning any exception into one line on stderr,
/// "<name>: configuration error: ..." or "<name>: error: ...", and exit code 1 (never a crash
/// or an uncaught exception). Ctrl-C / SIGTERM: "<name>: interrupted" and exit code 130, after
/// the stack unwound (temporary files and partial outputs removed). `error_code`: the exit code
/// of an error (travel-regress keeps 1 for "outside the tolerances").
template <class Run>
int runMain(const char* name, Run&& run, int argc, char** argv, int error_code = 1) {
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
        std::cerr << name << ": " << e.error() << "\nRun '" << name
                  << " --help' for the flags and examples.\n";
    } catch (const ConfigError& e) {
        std::cerr << name << ": configuration error: " << travel_mrpt::mrptMessage(e.what())
                  << "\n";
    } catch (const std::bad_alloc& e) {
        std::cerr << name << ": error: " << e.what() << memoryLimitNote() << "\n";
    } catch (const std::system_error& e) {  // a thread that cannot start, among others
        std::cerr << name << ": error: " << travel_mrpt::mrptMessage(e.what())
                  << (e.code() == std::errc::resource_unavailable_try_again ? memoryLimitNote()
                                                                            : "")
                  << "\n";
    } catch (const std::exception& e) {
        std::cerr << name << ": error: " << travel_mrpt::mrptMessage(e.what()) << "\n";
    } catch (...) {
        std::cerr << name << ": error: unknown exception\n";
    }
    return error_code;
}

}  // namespace travel::apps
