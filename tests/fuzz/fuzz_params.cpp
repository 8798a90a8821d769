// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// bytes as text -> applyParamsText and applyConfigText (YAML / ini, every section) and
// applyOverride / applyConfigOverride per line. ConfigError is the expected failure; any other
// exception, a crash or UB is a finding. Text that is accepted must round-trip through
// paramsToYaml / configToYaml, and validated params must build a Pipeline.
#include <cstdint>
#include <sstream>

#include "FuzzCommon.hpp"
#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace {
bool sameParams(const travel::Params& a, const travel::Params& b) {
    return travel::paramsToYaml(a) == travel::paramsToYaml(b);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        travel::Params p;
        bool applied = false;
        try {
            travel::applyParamsText(text, "fuzz.yaml", p);
            applied = true;
            p.validate();
        } catch (const travel::ConfigError& e) {
            FUZZ_CHECK(std::string(e.what()).rfind("fuzz.yaml:", 0) == 0 || applied);
        }
        if (applied) {
            // Round trip: what we write reads back identically.
            travel::Params q;
            travel::applyParamsText(travel::paramsToYaml(p), "roundtrip", q);
            FUZZ_CHECK(sameParams(p, q));
            try {
                p.validate();
                travel::Pipeline pipeline(p);  // must accept validated params
            } catch (const travel::ConfigError&) {
            }
        }
        // The whole configuration: what configToYaml writes reads back identically.
        travel::Config c;
        bool loaded = false;
        try {
            travel::applyConfigText(text, "fuzz.yaml", c);
            loaded = true;
        } catch (const travel::ConfigError& e) {
            FUZZ_CHECK(std::string(e.what()).rfind("fuzz.yaml", 0) == 0);
        }
        if (loaded) {
            travel::Config back;
            travel::applyConfigText(travel::configToYaml(c), "roundtrip", back);
            FUZZ_CHECK(travel::configToYaml(back) == travel::configToYaml(c));
        }
        // Each line as a command-line override.
        travel::Params o;
        travel::Config oc;
        std::istringstream lines(text);
        std::string line;
        int count = 0;
        while (std::getline(lines, line) && count++ < 64) {
            try {
                travel::applyOverride(line, o);
            } catch (const travel::ConfigError&) {
            }
            try {
                travel::applyConfigOverride(line, oc);
            } catch (const travel::ConfigError&) {
            }
        }
        try {
            travel::applyOverride(text, o);
        } catch (const travel::ConfigError&) {
        }
        try {
            travel::isAllowedChoice(text, "auto|field|table");
        } catch (const travel::ConfigError&) {
        }
    } catch (const travel::ConfigError& e) {
        std::fprintf(stderr, "unexpected ConfigError in round trip: %s\n", e.what());
        std::abort();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "unexpected exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}
