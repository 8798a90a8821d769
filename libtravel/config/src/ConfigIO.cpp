// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// YAML through yaml-cpp (line and column of every node, a maintained parser); ini is a few
// lines of text splitting. Both feed the same applyKey(), so both give the same messages.
#include "travel/ConfigIO.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <tuple>
#include <vector>

#include "travel/ConfigFields.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Text.hpp"
#include "travel/TextFile.hpp"

namespace travel {
namespace fs = std::filesystem;

namespace {

// A preset file may itself start with `preset:`; this bounds the chain (and breaks cycles).
constexpr int kMaxPresetDepth = 8;

const std::vector<std::string>& sectionNames() {
    static const std::vector<std::string> names = {"travel", "filter",  "map",
                                                   "nav",    "regress", "tracking"};
    return names;
}

bool isSection(const std::string& name) {
    for (const auto& s : sectionNames())
        if (s == name) return true;
    return false;
}

/// f(section struct) for the section called `name`; false when there is none.
template <class F>
bool withSection(Config& config, const std::string& name, F&& f) {
    bool found = false;
    visitSections(config, [&](auto& section) {
        if (!found && name == sectionName(section)) {
            found = true;
            f(section);
        }
    });
    return found;
}

/// The sections (other than `except`) that have `key`.
std::vector<std::string> sectionsWithKey(const std::string& key, const std::string& except) {
    std::vector<std::string> out;
    const Config defaults;
    visitSections(defaults, [&](const auto& section) {
        using S = fields::Bare<decltype(section)>;
        if (sectionName(section) != except && hasKey<S>(key))
            out.emplace_back(sectionName(section));
    });
    return out;
}

std::string unknownKeyMessage(const std::string& section, const std::string& key) {
    std::string message = "unknown key " + quotedExcerpt(key);
    Config probe;
    withSection(probe, section, [&](auto& s) {
        message += fields::didYouMean(key, keyNames<fields::Bare<decltype(s)>>());
    });
    const auto elsewhere = sectionsWithKey(key, section);
    if (!elsewhere.empty())
        message += " ('" + key + "' is a key of section '" + elsewhere[0] + "')";
    return message;
}

std::string position(const std::string& source, int line, int column) {
    std::string out = source;
    if (line > 0) out += ":" + std::to_string(line);
    if (column > 0) out += ":" + std::to_string(column);
    return out + ": ";
}

struct Location {
    int line = 0, column = 0;  // 1-based, 0 = unknown
};

Location locationOf(const YAML::Mark& mark) {
    if (mark.is_null() || mark.line < 0) return {};
    return {mark.line + 1, mark.column + 1};
}

/// Applies keys of one source (YAML or ini) with one set of rules and messages.
class Applier {
  public:
    Applier(const std::string& source, Config& config, int depth)
        : source_(source), config_(config), depth_(depth) {}

    [[noreturn]] void fail(const Location& at, const std::string& message) const {
        throw ConfigError(position(source_, at.line, at.column) + message);
    }

    void applyKey(const std::string& section, const std::string& key, const std::string& value,
                  const Location& at) {
        const std::string where = section + "." + key;
        const auto [previous, inserted] = first_line_.emplace(where, at.line);
        if (!inserted) {
            fail(at, "section '" + section + "': duplicate key '" + key + "' (first set on line " +
                         std::to_string(previous->second) + ")");
        }
        if (key == "preset" && section == "travel") return applyPreset(value, at);
        saw_key_ = true;
        withSection(config_, section, [&](auto& s) {
            try {
                if (!assignKey(s, key, value))
                    fail(at, "section '" + section + "': " + unknownKeyMessage(section, key));
            } catch (const ConfigError& e) {
                if (std::string_view(e.what()).rfind(source_, 0) == 0) throw;
                fail(at, "section '" + section + "': " + e.what());
            }
        });
    }

    void applySectionName(const std::string& name, const Location& at) {
        if (isSection(name)) return;
        fail(at, "unknown section " + quotedExcerpt(name) +
                     " (sections: travel, filter, map, nav, regress, tracking)" +
                     fields::didYouMean(name, sectionNames()));
    }

    void applyYaml(const std::string& text) {
        YAML::Node root;
        try {
            // One document: a second one ('---') would be ignored by YAML::Load, keys and all.
            const std::vector<YAML::Node> documents = YAML::LoadAll(text);
            for (std::size_t d = 1; d < documents.size(); ++d)
                if (!documents[d].IsNull())
                    fail(locationOf(documents[d].Mark()),
                         "a second YAML document ('---'): a configuration is one document");
            if (!documents.empty()) root = documents.front();
        } catch (const YAML::Exception& e) {
            failSyntax(text, locationOf(e.mark), e.msg);
        }
        if (root.IsNull()) return;
        if (!root.IsMap()) {
            fail(locationOf(root.Mark()),
                 "expected 'key: value' lines or the sections travel:, filter:, map:, nav:, "
                 "regress:, tracking:");
        }
        for (const auto& item : root) {
            const std::string key = scalarKey(item.first);
            const YAML::Node& value = item.second;
            const Location at = locationOf(item.first.Mark());
            if (value.IsMap() || (isSection(key) && !value.IsScalar())) {
                applySectionName(key, at);
                if (!seen_sections_.insert(key).second) {
                    fail(at, "section '" + key + "' appears twice");
                }
                if (value.IsNull()) continue;  // an empty section
                if (!value.IsMap()) fail(at, "section '" + key + "' must be a map of 'key: value'");
                for (const auto& entry : value) {
                    applyYamlKey(key, scalarKey(entry.first), entry.second,
                                 locationOf(entry.first.Mark()));
                }
            } else if (isSection(key)) {
                fail(at, "section '" + key + "' must be a map of 'key: value', not a value");
            } else {
                applyYamlKey("travel", key, value, at);  // keys at the root: travel's
            }
        }
    }

    void applyIni(const std::string& text) {
        std::string current;
        for (const IniEntry& e : readIni(text, source_)) {
            const std::string section = e.section.empty() ? "travel" : e.section;
            if (section != current) applySectionName(section, {e.line, 1});
            current = section;
            applyKey(section, e.key, e.value, {e.line, e.column});
        }
    }

  private:
    // yaml-cpp notices a broken line where the next token makes it impossible ("tgf_resolution;
    // 4.0" is only rejected on the line after it): name the line that is no `key: value`.
    [[noreturn]] void failSyntax(const std::string& text, const Location& at,
                                 const std::string& why) const {
        std::istringstream lines(text);
        int number = 0, suspect = 0;
        std::string suspect_text;
        for (std::string line; std::getline(lines, line) && (at.line == 0 || number < at.line);) {
            ++number;
            const std::size_t start = line.find_first_not_of(" \t\r");
            if (start == std::string::npos || line[start] == '#' || line[start] == '-') continue;
            const std::string content = line.substr(start);
            const std::size_t colon = content.find(':');
            const bool assignment = colon != std::string::npos &&
                                    (colon + 1 == content.size() || content[colon + 1] == ' ' ||
                                     content[colon + 1] == '\t' || content[colon + 1] == '\r');
            if (!assignment) suspect = number, suspect_text = content;
        }
        const std::string where =
            at.line > 0 ? " at " + std::to_string(at.line) + ":" + std::to_string(at.column) : "";
        if (suspect > 0) {
            while (!suspect_text.empty() && suspect_text.back() == '\r') suspect_text.pop_back();
            fail({suspect, 0}, "expected 'key: value', got " + quotedExcerpt(suspect_text) +
                                   " (YAML syntax: " + why + where + ")");
        }
        fail(at, "YAML syntax: " + why);
    }

    std::string scalarKey(const YAML::Node& node) const {
        if (!node.IsScalar()) fail(locationOf(node.Mark()), "expected a key, got a map or list");
        return node.Scalar();
    }

    void applyYamlKey(const std::string& section, const std::string& key, const YAML::Node& value,
                      const Location& at) {
        if (value.IsNull()) {
            // `key:` with nothing: in YAML an empty (null) value, never meant for TRAVEL.
            fail(at, "section '" + section + "': missing value for '" + key + "'");
        }
        if (!value.IsScalar()) {
            fail(locationOf(value.Mark()),
                 "section '" + section + "': expected a single value for '" + key + "', got a " +
                     (value.IsMap() ? "map" : "list") +
                     (isSection(key) ? " (sections are only accepted at the top level)" : ""));
        }
        applyKey(section, key, value.Scalar(), at);
    }

    void applyPreset(const std::string& name, const Location& at) {
        if (saw_key_) fail(at, "'preset' must come before every other key");
        if (depth_ >= kMaxPresetDepth) {
            fail(at, "presets nest more than " + std::to_string(kMaxPresetDepth) +
                         " levels deep (a cycle?)");
        }
        try {
            Config preset;
            const std::string path = findPresetFile(name);
            Applier nested(path, preset, depth_ + 1);
            nested.applyText(readConfigFile(path));
            nested.validate();
            config_ = preset;
        } catch (const ConfigError& e) {
            fail(at, std::string("preset '") + name + "': " + e.what());
        }
    }

  public:
    void applyText(const std::string& text) {
        if (looksLikeIni(text)) {
            applyIni(text);
        } else {
            applyYaml(text);
        }
    }

    /// Config::validate() on the result, its message prefixed with the source and, when this
    /// source set the key the failed rule is about, that key's line.
    void validate() const {
        try {
            config_.validate();
        } catch (const ConfigError& e) {
            throw ConfigError(position(source_, lineOfRuleKey(e.what()), 0) + e.what());
        }
    }

  private:
    /// A rule's message is "section 'S': ..." naming the keys it is about, the first one first
    /// ("max_motion_age must be > 0", "min_x/max_x: need ...", "min_range = 50 m must be smaller
    /// than max_range = 40": Config::validate, the sections' rules): the line of the first key
    /// named that this source set, 0 when it set none (a default or a preset's value broke it).
    int lineOfRuleKey(std::string_view message) const {
        constexpr std::string_view prefix = "section '";
        if (message.rfind(prefix, 0) != 0) return 0;
        const std::size_t close = message.find('\'', prefix.size());
        if (close == std::string_view::npos || message.substr(close, 3) != "': ") return 0;
        const std::string section(message.substr(prefix.size(), close - prefix.size()));
        constexpr std::string_view word_chars = "abcdefghijklmnopqrstuvwxyz0123456789_";
        for (std::size_t at = message.find_first_of(word_chars, close + 3);
             at != std::string_view::npos; at = message.find_first_of(word_chars, at)) {
            const std::size_t end =
                std::min(message.find_first_not_of(word_chars, at), message.size());
            const auto line =
                first_line_.find(section + "." + std::string(message.substr(at, end - at)));
            if (line != first_line_.end()) return line->second;
            at = end;
        }
        return 0;
    }

    static bool looksLikeIni(const std::string& text) {
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            const std::size_t start = line.find_first_not_of(" \t\r");
            if (start == std::string::npos || line[start] == '#' || line[start] == ';') continue;
            if (line[start] == '[') return true;
            const std::size_t equals = line.find('='), colon = line.find(':');
            return equals != std::string::npos && (colon == std::string::npos || equals < colon);
        }
        return false;
    }

    const std::string& source_;
    Config& config_;
    const int depth_;
    bool saw_key_ = false;  // any key but preset: 'preset' must come before it
    std::map<std::string, int> first_line_;
    std::set<std::string> seen_sections_;
};

std::string trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return std::string(s);
}

}  // namespace

std::vector<IniEntry> readIni(const std::string& text, const std::string& source_name) {
    std::vector<IniEntry> entries;
    std::string section;
    std::istringstream lines(text);
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        const std::size_t start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos || line[start] == '#' || line[start] == ';') continue;
        const auto fail = [&](const std::string& message) {
            throw ConfigError(position(source_name, number, int(start) + 1) + message);
        };
        const std::string content = trimmed(std::string_view(line).substr(start));
        if (content.front() == '[') {
            const std::size_t close = content.find(']');
            const std::string after =
                close == std::string::npos ? "" : trimmed(content.substr(close + 1));
            if (close == std::string::npos ||
                !(after.empty() || after[0] == '#' || after[0] == ';'))
                fail("malformed section header " + quotedExcerpt(content));
            section = trimmed(content.substr(1, close - 1));
            if (section.empty()) fail("empty section name '" + content + "'");
            continue;
        }
        const std::size_t equals = content.find('=');
        if (equals == std::string::npos)
            fail("expected 'key = value', got " + quotedExcerpt(content));
        IniEntry e{section, trimmed(content.substr(0, equals)), "", number, int(start) + 1};
        if (e.key.empty()) fail("missing key before '='");
        try {
            e.value = iniValue(content.substr(equals + 1));
        } catch (const ConfigError& error) {
            fail(error.what());
        }
        entries.push_back(std::move(e));
    }
    return entries;
}

std::string iniQuoted(const std::string& value) {
    try {
        if (iniValue(value) == value) return value;
    } catch (const ConfigError&) {  // an unterminated quote: quoting keeps it
    }
    for (const char quote : {'"', '\''})
        if (value.find(quote) == std::string::npos) return quote + value + quote;
    throw ConfigError("the value " + value +
                      " holds both quotes and a comment character: an ini file cannot keep it");
}

std::string iniValue(std::string_view written) {
    std::string value = trimmed(written);
    if (!value.empty() && (value.front() == '"' || value.front() == '\'')) {
        const std::size_t close = value.find(value.front(), 1);
        if (close == std::string::npos) throw ConfigError("unterminated quoted value");
        const std::string rest = trimmed(value.substr(close + 1));
        if (!(rest.empty() || rest[0] == '#' || rest[0] == ';'))
            throw ConfigError("unexpected text after the quoted value " +
                              value.substr(0, close + 1));
        return value.substr(1, close - 1);
    }
    // An unquoted value ends at a comment, '#' or ';' as for a whole line or a section header.
    return trimmed(value.substr(0, value.find_first_of("#;")));
}

std::string readConfigFile(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw ConfigError("cannot read config file '" + path +
                          "': " + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    }
    return readTextFile<ConfigError>(path, "a configuration is YAML or ini text");
}

void applyConfigText(const std::string& text, const std::string& source_name, Config& config) {
    Config result = config;
    Applier(source_name, result, 0).applyText(text);
    config = std::move(result);
}

void applyConfigFile(const std::string& path, Config& config) {
    Config result = config;
    Applier applier(path, result, 0);
    applier.applyText(readConfigFile(path));
    applier.validate();
    config = std::move(result);
}

Config loadConfigFile(const std::string& path) {
    Config config;
    applyConfigFile(path, config);
    return config;
}

Config loadPresetConfig(const std::string& name) {
    return loadConfigFile(findPresetFile(name));
}

std::pair<std::string, std::string> sectionAndKey(const std::string& name) {
    const std::size_t dot = name.find('.');
    if (dot == std::string::npos) return {std::string(), trimmed(name)};
    return {trimmed(std::string_view(name).substr(0, dot)),
            trimmed(std::string_view(name).substr(dot + 1))};
}

void applyConfigOverride(const std::string& assignment, Config& config) {
    const std::string prefix = "override '" + assignment + "': ";
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos) throw ConfigError(prefix + "expected key=value");
    std::string key = trimmed(std::string_view(assignment).substr(0, equals));
    std::string value = trimmed(std::string_view(assignment).substr(equals + 1));
    // Quotes as in a file ("ring_source='table'"), in case the shell left them.
    if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') &&
        value.back() == value.front()) {
        value = value.substr(1, value.size() - 2);
    }
    std::string section;
    std::tie(section, key) = sectionAndKey(key);
    if (!section.empty()) {
        if (!isSection(section)) {
            throw ConfigError(prefix + "unknown section " + quotedExcerpt(section) +
                              fields::didYouMean(section, sectionNames()));
        }
    } else {
        const auto owners = sectionsWithKey(key, "");
        if (owners.size() > 1) {
            throw ConfigError(prefix + "'" + key + "' is a key of sections '" + owners[0] +
                              "' and '" + owners[1] + "': write " + owners[0] + "." + key + "=...");
        }
        section = owners.empty() ? "travel" : owners[0];
    }
    if (key == "preset") throw ConfigError(prefix + "a preset cannot be applied as an override");
    withSection(config, section, [&](auto& s) {
        try {
            if (!assignKey(s, key, value)) {
                std::vector<std::string> names;
                const Config defaults;
                visitSections(defaults, [&](const auto& any) {
                    for (const auto& n : keyNames<fields::Bare<decltype(any)>>())
                        names.push_back(n);
                });
                throw ConfigError("unknown key " + quotedExcerpt(key) +
                                  fields::didYouMean(key, names));
            }
        } catch (const ConfigError& e) {
            throw ConfigError(prefix + e.what());
        }
    });
}

std::string configToYaml(const Config& config) {
    std::string yaml =
        "# TRAVEL configuration: one section per stage (travel: ground segmentation, filter: the\n"
        "# MRPT observation filter, map: the traversability map, nav: the obstacle sources,\n"
        "# regress: the tolerances of travel-regress, tracking: the object tracker).\n"
        "# Every key is optional: a missing key keeps its default. A first key `preset: NAME`\n"
        "# starts from share/presets/NAME.yaml.\n";
    visitSections(config, [&](const auto& section) {
        yaml += "\n" + std::string(sectionName(section)) + ":";
        yaml += sectionToYaml(section, "  ");
    });
    return yaml;
}

}  // namespace travel
