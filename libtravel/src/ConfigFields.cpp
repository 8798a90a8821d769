// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/ConfigFields.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <locale>
#include <sstream>
#include <string_view>

#include "travel/Text.hpp"

// Floating-point <charconv> is exact and locale-independent, but some standard libraries
// (older libc++) lack it; streams imbued with the classic locale are the fallback.
#if defined(__cpp_lib_to_chars) && !defined(TRAVEL_NO_FP_CHARCONV)
#define TRAVEL_HAVE_FP_CHARCONV 1
#else
#define TRAVEL_HAVE_FP_CHARCONV 0
#endif

namespace travel::fields {
namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
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

// Whole-string, finite, locale-independent.
template <class Real>
bool parseReal(const std::string& text, Real& out) {
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
template <class Real>
std::string formatReal(Real value) {
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
        for (int digits = 1; digits <= std::numeric_limits<Real>::max_digits10; ++digits) {
            std::ostringstream out;
            out.imbue(std::locale::classic());
            out.precision(digits);
            out << value;
            text = out.str();
            Real back = 0;
            if (parseReal(text, back) && back == value) break;
        }
    }
#endif
    if (std::isfinite(value) && text.find_first_of(".eE") == std::string::npos) text += ".0";
    return text;
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

// Range bounds are mostly whole numbers: "[1, 8192]" reads better than "[1.0, 8192.0]".
std::string formatBound(double bound) {
    if (bound == std::floor(bound) && std::fabs(bound) < 1e15) {
        return std::to_string(static_cast<long long>(bound));
    }
    return formatReal(bound);
}

}  // namespace

std::string parse(const std::string& text, double& out) {
    if (text.empty()) return "empty value, expected a number";
    if (!parseReal(text, out)) return quotedExcerpt(text) + " is not a finite number";
    return {};
}

std::string parse(const std::string& text, float& out) {
    if (text.empty()) return "empty value, expected a number";
    if (!parseReal(text, out)) return quotedExcerpt(text) + " is not a finite number";
    return {};
}

std::string parse(const std::string& text, int& out) {
    if (text.empty()) return "empty value, expected an integer";
    double value = 0;
    if (!parseReal(text, value)) return quotedExcerpt(text) + " is not a number";
    if (value != std::floor(value)) return quotedExcerpt(text) + " is not an integer";
    if (value < static_cast<double>(std::numeric_limits<int>::min()) ||
        value > static_cast<double>(std::numeric_limits<int>::max())) {
        return quotedExcerpt(text) + " does not fit in an int";
    }
    out = static_cast<int>(value);
    return {};
}

std::string parse(const std::string& text, bool& out) {
    const std::string lower = toLower(text);
    if (lower == "true" || lower == "yes" || lower == "on" || lower == "1") {
        out = true;
    } else if (lower == "false" || lower == "no" || lower == "off" || lower == "0") {
        out = false;
    } else {
        return quotedExcerpt(text) + " is not a boolean (true/false, yes/no, on/off, 1/0)";
    }
    return {};
}

std::string parse(const std::string& text, AutoReal& out) {
    const std::string lower = toLower(text);
    if (lower == "auto") {
        out.automatic = true;
        return {};
    }
    // auto(FALLBACK): what format() writes, so that a printed configuration keeps its fallback.
    if (lower.size() > 6 && lower.compare(0, 5, "auto(") == 0 && lower.back() == ')') {
        double fallback = 0;
        const std::string error = parse(text.substr(5, text.size() - 6), fallback);
        if (!error.empty()) return "auto(FALLBACK): " + error;
        out = AutoReal::makeAuto(fallback);
        return {};
    }
    double value = 0;
    std::string error = parse(text, value);
    if (!error.empty()) return error + " (or auto)";
    out = AutoReal(value);
    return {};
}

std::string parseChoice(const std::string& text, const char* choices, int& index) {
    const std::string lower = toLower(text);
    const auto allowed = splitChoices(choices);
    for (std::size_t i = 0; i < allowed.size(); ++i) {
        if (toLower(allowed[i]) == lower) {
            index = static_cast<int>(i);
            return {};
        }
    }
    return quotedExcerpt(text) + " is not one of " + choices;
}

std::string parse(const std::string& text, std::string& out, const char* choices) {
    if (!choices || !*choices) {
        out = text;
        return {};
    }
    int index = 0;
    std::string error = parseChoice(text, choices, index);
    if (error.empty()) out = choiceAt(choices, index);
    return error;
}

std::string format(double value) {
    return formatReal(value);
}
std::string format(float value) {
    return formatReal(value);
}
std::string format(int value) {
    return std::to_string(value);
}
std::string format(bool value) {
    return value ? "true" : "false";
}
std::string format(const AutoReal& value) {
    return value.isAuto() ? "auto(" + formatReal(value.value) + ")" : formatReal(value.value);
}

// A bare word when it reads back as the same string, otherwise quoted.
std::string format(const std::string& value) {
    const bool bare = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
    // Bare null / Null / NULL would read back as YAML's null, not as the text.
    const bool null = value == "null" || value == "Null" || value == "NULL";
    if (bare && !null && !std::isdigit(static_cast<unsigned char>(value[0])) && value[0] != '-' &&
        value[0] != '.') {
        return value;
    }
    // YAML single quotes double an inner quote; "..." would need escapes.
    std::string quoted = "'";
    for (char c : value) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
}

std::string choiceAt(const char* choices, int index) {
    const auto allowed = splitChoices(choices);
    return index >= 0 && index < static_cast<int>(allowed.size()) ? allowed[index] : "?";
}

bool isAllowedChoice(const std::string& value, const char* choices) {
    if (!choices || !*choices) return true;
    const auto allowed = splitChoices(choices);
    return std::find(allowed.begin(), allowed.end(), value) != allowed.end();
}

std::string rangeText(double lo, double hi, const char* unit) {
    std::string text = "[" + formatBound(lo) + ", " + formatBound(hi) + "]";
    return (unit && *unit) ? text + " " + unit : text;
}

std::string nearestName(const std::string& key, const std::vector<std::string>& names) {
    const std::string lower_key = toLower(key);
    std::string best;
    std::size_t best_distance = std::numeric_limits<std::size_t>::max();
    for (const auto& name : names) {
        const std::size_t distance = editDistance(lower_key, name);
        if (distance < best_distance) best_distance = distance, best = name;
    }
    // Only suggest a near miss: a distant "closest" key would mislead.
    const std::size_t max_distance = std::max<std::size_t>(2, key.size() / 3);
    if (best.empty() || best_distance > max_distance) {
        // A part of a name ("resolution") is also a near miss.
        best.clear();
        for (const auto& name : names) {
            if (lower_key.size() >= 4 && name.find(lower_key) != std::string::npos) {
                best = name;
                break;
            }
        }
    }
    return best;
}

std::string didYouMean(const std::string& key, const std::vector<std::string>& names) {
    const std::string best = nearestName(key, names);
    return best.empty() ? std::string() : "; did you mean " + inQuotes(best) + "?";
}

std::string wrappedComment(const std::string& text, const std::string& tail,
                           const std::string& indent) {
    constexpr std::size_t kCommentWidth = 100;
    std::vector<std::string> words;
    std::istringstream text_words(text);
    for (std::string word; text_words >> word;) words.push_back(word);
    words.push_back(tail);
    std::string out, line = indent + "#";
    for (const auto& word : words) {
        if (line.size() > indent.size() + 1 && line.size() + 1 + word.size() > kCommentWidth) {
            out += line + "\n";
            line = indent + "#  ";  // continuation lines are indented
        }
        line += " " + word;
    }
    return out + line + "\n";
}

}  // namespace travel::fields
