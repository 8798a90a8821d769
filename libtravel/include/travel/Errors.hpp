// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#pragma once

#include <stdexcept>
#include <string>

namespace travel {

/// A configuration problem: unknown key, bad value, out-of-range parameter. The message names
/// the source (file:line) and the key.
struct ConfigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A malformed input: a file (wrong size, wrong count; the message names it), or a cloud that
/// an explicit ring_source cannot read (Pipeline::process; the message names the source).
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace travel
