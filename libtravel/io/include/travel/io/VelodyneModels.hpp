// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Which Velodyne model a driver's model string names, and its firing timing: what a reader of
// rotating-scan data needs to pick the default calibration and to time each laser.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace travel::io {

struct VelodyneModel {
    /// "VLP16", "HDL32" or "HDL64" (the names of MRPT's default calibrations).
    const char* name = "";
    /// Firing delay of laser id k after its column's azimuth is k * this (in columns) for a
    /// layout of one firing cycle per column, from the Velodyne timing tables: VLP-16 fires a
    /// laser every 2.304 us and stores one firing (55.296 us) per column; HDL-32E fires every
    /// 1.152 us and stores one 46.08 us firing cycle per column (0: unknown).
    double laser_delay_in_columns = 0.0;
};

/// "VLP-16" -> "VLP16", "HDL-32E" -> "HDL32E": the spellings drivers use vary.
std::string normalisedModel(const std::string& model);

/// The model named by `model` (any spelling: VLP16 / Puck, HDL32, HDL64), falling back on the
/// ring count (16: VLP16, 32: HDL32); nullopt when none fits.
std::optional<VelodyneModel> velodyneModelFor(const std::string& model, std::size_t rows);

}  // namespace travel::io
