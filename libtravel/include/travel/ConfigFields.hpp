// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The rules of one configuration key, for every section of Config.hpp: text -> value (whole
// string, locale-independent, range- and choice-checked), value -> text (shortest exact), the
// range check, "did you mean" and the documented dump. Every loader (YAML, ini, command-line
// --set, MRPT's CConfigFileBase sections) goes through assignKey(), so one key gives the same
// message wherever it is written. Parsing files is travel::config's job (ConfigIO.hpp).
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "travel/Config.hpp"
#include "travel/Errors.hpp"

namespace travel {

namespace fields {
// Each parse returns "" on success, otherwise why `text` is not a value of that type.
std::string parse(const std::string& text, double& out);
std::string parse(const std::string& text, float& out);
std::string parse(const std::string& text, int& out);
std::string parse(const std::string& text, bool& out);
/// "auto" (any case) keeps out.value as the fallback; "auto(1.2)" is auto with fallback 1.2;
/// otherwise a number as for double.
std::string parse(const std::string& text, AutoReal& out);
/// `choices` "a|b|c": the matching choice (any case) stored as listed; "" = any text.
std::string parse(const std::string& text, std::string& out, const char* choices);
/// Index of `text` in `choices` (any case), or why not.
std::string parseChoice(const std::string& text, const char* choices, int& index);

std::string format(double value);  ///< shortest text that reads back exactly, with '.' or 'e'
std::string format(float value);
std::string format(int value);
std::string format(bool value);
std::string format(const AutoReal& value);     ///< "auto(FALLBACK)" or the number
std::string format(const std::string& value);  ///< bare word or quoted
/// The n-th '|'-separated choice.
std::string choiceAt(const char* choices, int index);

/// "[lo, hi] unit".
std::string rangeText(double lo, double hi, const char* unit);
/// The nearest of `names` to `key` (edit distance, or a name containing `key`), or "" when
/// none is near. Also the apps' "did you mean" for command-line flags.
std::string nearestName(const std::string& key, const std::vector<std::string>& names);
/// "; did you mean 'x'?" for nearestName(), or "" when none is near.
std::string didYouMean(const std::string& key, const std::vector<std::string>& names);
/// "# text tail" comment lines of at most 100 columns, each prefixed by `indent`.
std::string wrappedComment(const std::string& text, const std::string& tail,
                           const std::string& indent);

/// The '|'-separated allowed values contain `value` exactly ("" allows anything).
bool isAllowedChoice(const std::string& value, const char* choices);

template <class T>
using Bare = std::remove_cv_t<std::remove_reference_t<T>>;

template <class T>
std::string parseAny(const std::string& text, T& out, const char* unit) {
    if constexpr (std::is_same_v<T, std::string>) {
        return parse(text, out, unit);
    } else if constexpr (std::is_enum_v<T>) {
        int index = 0;
        std::string error = parseChoice(text, unit, index);
        if (error.empty()) out = static_cast<T>(index);
        return error;
    } else {
        return parse(text, out);
    }
}

template <class T>
std::string formatAny(const T& value, const char* unit) {
    if constexpr (std::is_enum_v<T>) {
        return choiceAt(unit, static_cast<int>(value));
    } else {
        (void)unit;
        return format(value);
    }
}

/// "" when `value` is inside its documented range / choices, else the message (no position).
template <class T>
std::string rangeError(const char* name, const T& value, const char* unit, double lo, double hi) {
    if constexpr (std::is_same_v<T, std::string>) {
        if (isAllowedChoice(value, unit)) return {};
        return "'" + std::string(name) + "' = '" + value + "' is not one of " + unit;
    } else if constexpr (std::is_enum_v<T> || std::is_same_v<T, bool>) {
        return {};
    } else if constexpr (std::is_same_v<T, AutoReal>) {
        return rangeError(name, value.value, unit, lo, hi);  // auto: its fallback
    } else {
        const double v = static_cast<double>(value);
        if (v >= lo && v <= hi) return {};  // false for NaN
        return "'" + std::string(name) + "' = " + format(value) + " is outside its allowed range " +
               rangeText(lo, hi, unit);
    }
}
}  // namespace fields

/// The names of a section's keys, in declaration order.
template <class Section>
std::vector<std::string> keyNames() {
    std::vector<std::string> names;
    const Section defaults{};
    visitFields(defaults, [&](const char* name, auto&&...) { names.emplace_back(name); });
    return names;
}

template <class Section>
bool hasKey(const std::string& key) {
    bool found = false;
    const Section defaults{};
    visitFields(defaults, [&](const char* name, auto&&...) { found = found || key == name; });
    return found;
}

/// Sets `section.<key>` from `text` when the section has that key: returns false when it has
/// not; throws ConfigError with the reason (no position) when the value is invalid or out of
/// range. Nothing is changed on error.
template <class Section>
bool assignKey(Section& section, const std::string& key, const std::string& text) {
    bool found = false;
    visitFields(section, [&](const char* name, auto& value, const char* unit, double lo, double hi,
                             const char*) {
        if (found || key != name) return;
        found = true;
        using T = fields::Bare<decltype(value)>;
        T parsed = value;  // AutoReal: `auto` keeps the current number as its fallback
        const std::string error = fields::parseAny(text, parsed, unit);
        if (!error.empty()) throw ConfigError("invalid value for '" + key + "': " + error);
        const std::string range = fields::rangeError(name, parsed, unit, lo, hi);
        if (!range.empty()) throw ConfigError(range);
        value = std::move(parsed);
    });
    return found;
}

/// assignKey() on the first of `sections` that has `key` (a flat list of keys shared by several
/// sections, as in MRPT .ini sections); an unknown key throws ConfigError naming the key and the
/// nearest name of any of them.
template <class... Sections>
void assignFlatKey(const std::string& key, const std::string& text, Sections&... sections) {
    if ((assignKey(sections, key, text) || ...)) return;
    std::vector<std::string> names;
    (
        [&] {
            const auto more = keyNames<fields::Bare<Sections>>();
            names.insert(names.end(), more.begin(), more.end());
        }(),
        ...);
    std::string what;
    ((what += (what.empty() ? "" : ", ") + std::string(sectionName(sections))), ...);
    throw ConfigError("unknown key '" + key + "' (not a key of " + what + ")" +
                      fields::didYouMean(key, names));
}

/// Throws ConfigError naming the first key out of its documented range or choices.
template <class Section>
void checkRanges(const Section& section) {
    visitFields(section, [](const char* name, const auto& value, const char* unit, double lo,
                            double hi, const char*) {
        const std::string error = fields::rangeError(name, value, unit, lo, hi);
        if (!error.empty()) throw ConfigError(error);
    });
}

/// Every key as "key: value" preceded by its documentation, each line prefixed by `indent`.
template <class Section>
std::string sectionToYaml(const Section& section, const std::string& indent) {
    std::string yaml;
    visitFields(section, [&](const char* name, const auto& value, const char* unit, double lo,
                             double hi, const char* description) {
        using T = fields::Bare<decltype(value)>;
        std::string comment;
        if constexpr (std::is_same_v<T, std::string> || std::is_enum_v<T>) {
            const std::string allowed = *unit ? "(one of " + std::string(unit) + ")" : "(any text)";
            comment = fields::wrappedComment(description, allowed, indent);
        } else {
            std::string range =
                std::is_same_v<T, bool> ? "true/false" : "range " + fields::rangeText(lo, hi, "");
            if constexpr (std::is_same_v<T, AutoReal>) range += " or auto";
            comment =
                fields::wrappedComment("[" + std::string(*unit ? unit : "-") + "] " + description,
                                       "(" + range + ")", indent);
        }
        yaml += "\n" + comment + indent + name + ": " + fields::formatAny(value, unit) + "\n";
    });
    return yaml;
}

}  // namespace travel
