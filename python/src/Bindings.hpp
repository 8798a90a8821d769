// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The Python module `travel._travel`, in two translation units (fast to compile): Params and
// the configuration (ParamsPy.cpp), everything that runs or scores a frame (PipelinePy.cpp).
// Thin: every rule (parameter ranges, readers, label encoding, metrics) is the library's.
#pragma once

#include <pybind11/pybind11.h>

namespace travel::python {

/// travel.Params, travel.ConfigError / InputError and the exception translation.
void bindParams(pybind11::module_& m);
/// travel.Pipeline, Result, Clusters, Terrain, Scan, read_scan, write_labels, metrics.
void bindPipeline(pybind11::module_& m);

}  // namespace travel::python
