// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#pragma once
/// @file
/// The one home of enum <-> word conversions: every enum that appears in files, flags or messages
/// has one constexpr table of {value, "name"} rows next to its declaration, and these functions
/// read it (no hand-written switch per enum).

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace travel {

/// One row of an enum's name table.
template <class E>
struct EnumName {
    E value;
    const char* name;
};

/// The name of `value` in `table`, "?" when the table does not list it.
template <class E, std::size_t N>
constexpr const char* nameOf(const EnumName<E> (&table)[N], E value) {
    for (const EnumName<E>& row : table)
        if (row.value == value) return row.name;
    return "?";
}

/// The value called `name` (exact spelling), or nothing.
template <class E, std::size_t N>
constexpr std::optional<E> findByName(const EnumName<E> (&table)[N], std::string_view name) {
    for (const EnumName<E>& row : table)
        if (name == row.name) return row.value;
    return std::nullopt;
}

/// The names in table order joined by `separator`, with `last` before the final one:
/// "travel, raw or threshold".
template <class E, std::size_t N>
std::string namesOf(const EnumName<E> (&table)[N], const char* separator = ", ",
                    const char* last = " or ") {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) out += i + 1 == N ? last : separator;
        out += table[i].name;
    }
    return out;
}

/// The value called `name`; otherwise throws `Error` with
/// "unknown <what> '<name>' (expected a, b or c)".
template <class Error = std::invalid_argument, class E, std::size_t N>
E valueFromName(const EnumName<E> (&table)[N], const std::string& name, const char* what) {
    if (const std::optional<E> value = findByName(table, name)) return *value;
    throw Error("unknown " + std::string(what) + " '" + name + "' (expected " + namesOf(table) +
                ")");
}

}  // namespace travel
