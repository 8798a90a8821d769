// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/ParamsIO.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <locale>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "travel/Errors.hpp"

// Floating-point <charconv> is exact and locale-independent, but some standard libraries
// (older libc++) lack it; streams imbued with the classic locale are the fallback.
#if defined(__cpp_lib_to_chars) && !defined(TRAVEL_NO_FP_CHARCONV)
#define TRAVEL_HAVE_FP_CHARCONV 1
#else
#define TRAVEL_HAVE_FP_CHARCONV 0
#endif

namespace travel {

namespace fs = std::filesystem;

namespace {

// A preset file may itself start with `preset:`; this bounds the chain (and breaks cycles).
constexpr int kMaxPresetDepth = 8;

bool isSpace(char c) {
    return c == ' ' || c == '\t';
}
bool isIdentStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (isSpace(s.front()) || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (isSpace(s.back()) || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::string toLower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

// ---- Numbers -----------------------------------------------------------------------------

// Whole-string, finite, locale-independent.
bool parseDouble(const std::string& text, double& out) {
    if (text.empty() || isSpace(text.front())) return false;
    std::size_t start = 0;
    if (text[0] == '+') {
        start = 1;  // from_chars rejects '+', YAML and ini users write it
        if (text.size() == 1 || text[1] == '+' || text[1] == '-') return false;
    }
#if TRAVEL_HAVE_FP_CHARCONV
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data() + start, end, out);
    if (ec != std::errc() || ptr != end) return false;
#else
    std::istringstream in(text.substr(start));
    in.imbue(std::locale::classic());
    in >> out;
    if (in.fail() || in.peek() != std::char_traits<char>::eof()) return false;
#endif
    return std::isfinite(out);
}

// The shortest text that parses back to exactly `value`, always with a '.' or an exponent so
// that a reader sees it is a real number.
std::string formatDouble(double value) {
    std::string text;
#if TRAVEL_HAVE_FP_CHARCONV
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    text.assign(buffer, result.ptr);
#else
    // %g-style output would write 80 as "8e+01"; whole numbers are written as integers.
    if (value == std::floor(value) && std::fabs(value) < 1e15) {
        text = std::to_string(static_cast<long long>(value));
        if (std::signbit(value) && value == 0) text = "-0";
    } else {
        // The fewest significant digits that read back exactly.
        for (int digits = 1; digits <= std::numeric_limits<double>::max_digits10; ++digits) {
            std::ostringstream out;
            out.imbue(std::locale::classic());
            out.precision(digits);
            out << value;
            text = out.str();
            double back = 0;
            if (parseDouble(text, back) && back == value) break;
        }
    }
#endif
    if (std::isfinite(value) && text.find_first_of(".eE") == std::string::npos) text += ".0";
    return text;
}

// A bare word when it reads back as the same string, otherwise quoted.
std::string formatString(const std::string& value) {
    const bool bare = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
        return isIdentChar(c) || c == '-' || c == '.';
    });
    if (bare) return value;
    return value.find('"') == std::string::npos ? "\"" + value + "\"" : "'" + value + "'";
}

template <class T>
std::string formatValue(const T& value) {
    if constexpr (std::is_same_v<T, std::string>) {
        return formatString(value);
    } else if constexpr (std::is_same_v<T, bool>) {
        return value ? "true" : "false";
    } else if constexpr (std::is_same_v<T, int>) {
        return std::to_string(value);
    } else {
        return formatDouble(value);
    }
}

std::string inQuotes(const std::string& text) {
    return "'" + text + "'";
}

// Each returns "" on success, otherwise why `text` is not a value of that type.
std::string parseValue(const std::string& text, double& out) {
    if (text.empty()) return "empty value, expected a number";
    if (!parseDouble(text, out)) return inQuotes(text) + " is not a finite number";
    return {};
}

std::string parseValue(const std::string& text, int& out) {
    if (text.empty()) return "empty value, expected an integer";
    double value = 0;
    if (!parseDouble(text, value)) return inQuotes(text) + " is not a number";
    if (value != std::floor(value)) return inQuotes(text) + " is not an integer";
    if (value < static_cast<double>(std::numeric_limits<int>::min()) ||
        value > static_cast<double>(std::numeric_limits<int>::max())) {
        return inQuotes(text) + " does not fit in an int";
    }
    out = static_cast<int>(value);
    return {};
}

std::string parseValue(const std::string& text, bool& out) {
    const std::string lower = toLower(text);
    if (lower == "true" || lower == "yes" || lower == "on" || lower == "1") {
        out = true;
    } else if (lower == "false" || lower == "no" || lower == "off" || lower == "0") {
        out = false;
    } else {
        return inQuotes(text) + " is not a boolean (true/false, yes/no, on/off, 1/0)";
    }
    return {};
}

// Strings are checked against their allowed values by the caller, which knows them.
std::string parseValue(const std::string& text, std::string& out) {
    out = text;
    return {};
}

std::vector<std::string> splitChoices(const char* choices) {
    std::vector<std::string> out;
    std::string_view rest = choices ? choices : "";
    while (!rest.empty()) {
        const std::size_t bar = rest.find('|');
        out.emplace_back(rest.substr(0, bar));
        if (bar == std::string_view::npos) break;
        rest.remove_prefix(bar + 1);
    }
    return out;
}

// The allowed spelling of `text` (case-insensitive match), or "" when it is not allowed.
std::string canonicalChoice(const std::string& text, const char* choices) {
    const std::string lower = toLower(text);
    for (const auto& choice : splitChoices(choices)) {
        if (toLower(choice) == lower) return choice;
    }
    return {};
}

// Range bounds are mostly whole numbers: "[1, 8192]" reads better than "[1.0, 8192.0]".
std::string formatBound(double bound) {
    if (bound == std::floor(bound) && std::fabs(bound) < 1e15) {
        return std::to_string(static_cast<long long>(bound));
    }
    return formatDouble(bound);
}

std::string rangeText(double lo, double hi, const char* unit) {
    std::string text = "[" + formatBound(lo) + ", " + formatBound(hi) + "]";
    return (unit && *unit) ? text + " " + unit : text;
}

// ---- Keys --------------------------------------------------------------------------------

std::vector<std::string> paramNames() {
    std::vector<std::string> names;
    const Params defaults;
    visitParams(defaults, [&](const char* name, const auto&, const char*, double, double,
                              const char*) { names.emplace_back(name); });
    return names;
}

// Optimal string alignment distance: Levenshtein plus adjacent transpositions, the most
// common typo ("resolutoin").
std::size_t editDistance(const std::string& a, const std::string& b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}

std::string unknownKeyMessage(const std::string& key) {
    std::string message = "unknown parameter " + inQuotes(key);
    const std::string lower_key = toLower(key);
    std::string best;
    std::size_t best_distance = std::numeric_limits<std::size_t>::max();
    for (const auto& name : paramNames()) {
        const std::size_t distance = editDistance(lower_key, name);
        if (distance < best_distance) best_distance = distance, best = name;
    }
    // Only suggest a near miss: a distant "closest" key would mislead.
    const std::size_t max_distance = std::max<std::size_t>(2, key.size() / 3);
    if (best.empty() || best_distance > max_distance) {
        // A part of a name ("resolution") is also a near miss.
        best.clear();
        for (const auto& name : paramNames()) {
            if (lower_key.size() >= 4 && name.find(lower_key) != std::string::npos) {
                best = name;
                break;
            }
        }
    }
    if (!best.empty()) message += "; did you mean " + inQuotes(best) + "?";
    return message;
}

// Sets params.<key> from text; returns "" on success, otherwise the message (no position).
std::string assignParam(Params& params, const std::string& key, const std::string& text) {
    bool found = false;
    std::string error;
    visitParams(params, [&](const char* name, auto& value, const char* unit, double lo, double hi,
                            const char*) {
        if (found || key != name) return;
        found = true;
        using T = std::remove_reference_t<decltype(value)>;
        T parsed{};
        error = parseValue(text, parsed);
        if (!error.empty()) {
            error = "invalid value for " + inQuotes(key) + ": " + error;
            return;
        }
        if constexpr (std::is_same_v<T, std::string>) {
            // For strings the unit slot lists the allowed values.
            parsed = canonicalChoice(parsed, unit);
            if (parsed.empty()) {
                error = "invalid value for " + inQuotes(key) + ": " + inQuotes(text) +
                        " is not one of " + unit;
                return;
            }
        } else {
            const double as_double = static_cast<double>(parsed);
            if (as_double < lo || as_double > hi) {
                error = inQuotes(key) + " = " + formatValue(parsed) +
                        " is outside its allowed range " + rangeText(lo, hi, unit);
                return;
            }
        }
        value = std::move(parsed);
    });
    return found ? error : unknownKeyMessage(key);
}

// ---- Text --------------------------------------------------------------------------------

Params loadPresetImpl(const std::string& name, int depth);

bool isCommentOrBlank(std::string_view rest) {
    rest = trim(rest);
    return rest.empty() || rest.front() == '#';
}

class TextApplier {
  public:
    TextApplier(const std::string& source, Params& params, int depth)
        : source_(source), params_(params), depth_(depth) {}

    void apply(const std::string& text) {
        std::size_t begin = 0;
        while (begin <= text.size()) {
            std::size_t end = text.find('\n', begin);
            if (end == std::string::npos) end = text.size();
            ++line_number_;
            applyLine(std::string_view(text).substr(begin, end - begin));
            begin = end + 1;
        }
    }

  private:
    [[noreturn]] void fail(const std::string& message) const {
        throw ConfigError(source_ + ":" + std::to_string(line_number_) + ": " + message);
    }

    void applyLine(std::string_view line) {
        std::size_t pos = 0;
        while (pos < line.size() && isSpace(line[pos])) ++pos;
        const std::size_t indent = pos;
        const std::string_view rest = line.substr(pos);
        if (isCommentOrBlank(rest) || rest.front() == ';') return;

        if (rest.substr(0, 3) == "---" && isCommentOrBlank(rest.substr(3))) {
            if (saw_content_) fail("'---' is only accepted before the first key");
            saw_content_ = true;
            return;
        }
        saw_content_ = true;
        if (rest.front() == '[') return applySection(rest);

        std::size_t key_end = 0;
        if (isIdentStart(rest[0])) {
            while (key_end < rest.size() && isIdentChar(rest[key_end])) ++key_end;
        }
        std::size_t sep = key_end;
        while (sep < rest.size() && isSpace(rest[sep])) ++sep;
        if (key_end == 0 || sep == rest.size() || (rest[sep] != ':' && rest[sep] != '=')) {
            fail("expected 'key: value' or 'key = value', got " +
                 inQuotes(std::string(trim(rest))));
        }
        const std::string key(rest.substr(0, key_end));
        const std::string value = parseValueText(rest.substr(sep + 1));

        // A line at column 0 closes the `travel:` wrapper.
        if (indent == 0) in_wrapper_ = false;
        if (value.empty() && !value_was_quoted_) {
            if (key == "travel" && indent == 0 && rest[sep] == ':') {
                if (saw_wrapper_) fail("'travel:' appears twice");
                saw_wrapper_ = in_wrapper_ = true;
                return;
            }
            const auto names = paramNames();
            if (key != "preset" && std::find(names.begin(), names.end(), key) == names.end()) {
                fail("unknown section " + inQuotes(key + ":") +
                     " (only a top-level 'travel:' may hold the parameters)");
            }
            fail("missing value for " + inQuotes(key));
        }
        // In YAML, indentation means nesting; ini ('=' or after [travel]) ignores it.
        if (indent > 0 && !in_wrapper_ && rest[sep] == ':' && !saw_section_) {
            fail(inQuotes(key) + " is indented, but only keys under a top-level 'travel:' may be");
        }

        const auto [previous, inserted] = first_line_.emplace(key, line_number_);
        if (!inserted) {
            fail("duplicate key " + inQuotes(key) + " (first set on line " +
                 std::to_string(previous->second) + ")");
        }
        if (key == "preset") return applyPreset(value);
        saw_param_ = true;
        const std::string error = assignParam(params_, key, value);
        if (!error.empty()) fail(error);
    }

    void applySection(std::string_view rest) {
        const std::size_t close = rest.find(']');
        if (close == std::string_view::npos || !isCommentOrBlank(rest.substr(close + 1))) {
            fail("malformed section header " + inQuotes(std::string(trim(rest))));
        }
        const std::string name(trim(rest.substr(1, close - 1)));
        if (name != "travel") {
            fail("unknown section " + inQuotes("[" + name + "]") +
                 " (only a single [travel] section is accepted)");
        }
        if (saw_section_) fail("section [travel] appears twice");
        saw_section_ = true;
    }

    // The value after the separator: unquoted, comment stripped, trimmed.
    std::string parseValueText(std::string_view after_separator) {
        std::string_view text = trim(after_separator);
        value_was_quoted_ = false;
        if (!text.empty() && (text.front() == '"' || text.front() == '\'')) {
            const std::size_t close = text.find(text.front(), 1);
            if (close == std::string_view::npos) fail("unterminated quoted value");
            if (!isCommentOrBlank(text.substr(close + 1))) {
                fail("unexpected text after the quoted value " +
                     std::string(text.substr(0, close + 1)));
            }
            value_was_quoted_ = true;
            return std::string(text.substr(1, close - 1));
        }
        return std::string(trim(text.substr(0, text.find('#'))));
    }

    void applyPreset(const std::string& name) {
        if (saw_param_) fail("'preset' must come before every parameter");
        if (depth_ >= kMaxPresetDepth) {
            fail("presets nest more than " + std::to_string(kMaxPresetDepth) +
                 " levels deep (a cycle?)");
        }
        try {
            params_ = loadPresetImpl(name, depth_ + 1);
        } catch (const ConfigError& e) {
            fail(e.what());
        }
    }

    const std::string& source_;
    Params& params_;
    const int depth_;
    int line_number_ = 0;
    bool saw_content_ = false;  // anything but comments: '---' must come before it
    bool saw_param_ = false;    // a parameter key: 'preset' must come before it
    bool saw_section_ = false;
    bool saw_wrapper_ = false;
    bool in_wrapper_ = false;
    bool value_was_quoted_ = false;
    std::map<std::string, int> first_line_;
};

void applyFileImpl(const std::string& path, Params& params, int depth) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw ConfigError("cannot read config file " + inQuotes(path) + ": " +
                          (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream contents;
    if (in) contents << in.rdbuf();
    if (!in || in.bad()) throw ConfigError("cannot read config file " + inQuotes(path));

    TextApplier(path, params, depth).apply(contents.str());
    try {
        params.validate();
    } catch (const ConfigError& e) {
        throw ConfigError(path + ": " + e.what());
    }
}

Params loadPresetImpl(const std::string& name, int depth) {
    Params params;
    applyFileImpl(findPresetFile(name), params, depth);
    return params;
}

bool isValidPresetName(const std::string& name) {
    // Names, not paths: keeps `preset:` from reaching outside the presets directories.
    return !name.empty() &&
           std::all_of(name.begin(), name.end(), [](char c) { return isIdentChar(c) || c == '-'; });
}

// "# text tail" lines of at most kCommentWidth columns, broken at the spaces of `text`; the
// tail (a range like "(range [0, 100])") is never split.
std::string wrappedComment(const std::string& text, const std::string& tail) {
    constexpr std::size_t kCommentWidth = 100;
    std::vector<std::string> words;
    std::istringstream text_words(text);
    for (std::string word; text_words >> word;) words.push_back(word);
    words.push_back(tail);
    std::string out, line = "#";
    for (const auto& word : words) {
        if (line.size() > 1 && line.size() + 1 + word.size() > kCommentWidth) {
            out += line + "\n";
            line = "#  ";  // continuation lines are indented
        }
        line += " " + word;
    }
    return out + line + "\n";
}

}  // namespace

bool isAllowedChoice(const std::string& value, const char* choices) {
    const auto allowed = splitChoices(choices);
    return std::find(allowed.begin(), allowed.end(), value) != allowed.end();
}

void applyParamsText(const std::string& text, const std::string& source_name, Params& params) {
    TextApplier(source_name, params, 0).apply(text);
}

void applyParamsFile(const std::string& path, Params& params) {
    applyFileImpl(path, params, 0);
}

Params loadPreset(const std::string& name) {
    return loadPresetImpl(name, 0);
}

std::vector<std::string> shareSearchDirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("TRAVEL_SHARE_DIR"); env && *env) dirs.emplace_back(env);
#ifdef TRAVEL_SOURCE_SHARE_DIR
    dirs.emplace_back(TRAVEL_SOURCE_SHARE_DIR);
#endif
#ifdef TRAVEL_INSTALL_SHARE_DIR
    dirs.emplace_back(TRAVEL_INSTALL_SHARE_DIR);
#endif
    dirs.erase(std::remove(dirs.begin(), dirs.end(), std::string()), dirs.end());
    return dirs;
}

std::string findShareDir() {
    std::error_code ec;
    const auto dirs = shareSearchDirs();
    for (const auto& dir : dirs) {
        if (fs::is_directory(dir, ec)) return dir;
    }
    throw ConfigError("no travel share directory found (searched: " + joined(dirs, ", ") +
                      "); set TRAVEL_SHARE_DIR");
}

std::vector<std::string> availablePresets() {
    std::vector<std::string> names;
    for (const auto& dir : shareSearchDirs()) {
        std::error_code ec;
        for (fs::directory_iterator it(fs::path(dir) / "presets", ec), end; !ec && it != end;
             it.increment(ec)) {
            const fs::path& path = it->path();
            if (path.extension() == ".yaml" && it->is_regular_file(ec)) {
                names.push_back(path.stem().string());
            }
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::string findPresetFile(const std::string& name) {
    const auto dirs = shareSearchDirs();
    if (isValidPresetName(name)) {
        for (const auto& dir : dirs) {
            const fs::path candidate = fs::path(dir) / "presets" / (name + ".yaml");
            std::error_code ec;
            if (fs::is_regular_file(candidate, ec)) return candidate.string();
        }
    }
    std::vector<std::string> searched;
    for (const auto& dir : dirs) searched.push_back((fs::path(dir) / "presets").string());
    const auto available = availablePresets();
    throw ConfigError("preset " + inQuotes(name) + " not found; available presets: " +
                      (available.empty() ? "(none)" : joined(available, ", ")) +
                      "; searched: " + (searched.empty() ? "(nothing)" : joined(searched, ", ")) +
                      " (set TRAVEL_SHARE_DIR to add a directory)");
}

void applyOverride(const std::string& key_equals_value, Params& params) {
    const std::string prefix = "override " + inQuotes(key_equals_value) + ": ";
    const std::size_t equals = key_equals_value.find('=');
    if (equals == std::string::npos) throw ConfigError(prefix + "expected key=value");
    const std::string key(trim(std::string_view(key_equals_value).substr(0, equals)));
    std::string value(trim(std::string_view(key_equals_value).substr(equals + 1)));
    // Quotes as in a file ("ring_source='table'"), in case the shell left them.
    if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') &&
        value.back() == value.front()) {
        value = value.substr(1, value.size() - 2);
    }
    if (key == "preset") throw ConfigError(prefix + "a preset cannot be applied as an override");
    const std::string error = assignParam(params, key, value);
    if (!error.empty()) throw ConfigError(prefix + error);
}

std::string paramsToYaml(const Params& params) {
    std::string yaml =
        "# TRAVEL ground segmentation parameters. Every key is optional: a missing key keeps\n"
        "# its default. A first line `preset: NAME` starts from share/presets/NAME.yaml.\n";
    visitParams(params, [&](const char* name, const auto& value, const char* unit, double lo,
                            double hi, const char* description) {
        using T = std::remove_cv_t<std::remove_reference_t<decltype(value)>>;
        std::string comment;
        if constexpr (std::is_same_v<T, std::string>) {
            // The unit slot of a string holds its allowed values.
            comment = wrappedComment(description, "(one of " + std::string(unit) + ")");
        } else {
            const std::string range =
                std::is_same_v<T, bool> ? "true/false" : "range " + rangeText(lo, hi, "");
            comment = wrappedComment("[" + std::string(*unit ? unit : "-") + "] " + description,
                                     "(" + range + ")");
        }
        yaml += "\n" + comment + name + ": " + formatValue(value) + "\n";
    });
    return yaml;
}

}  // namespace travel
