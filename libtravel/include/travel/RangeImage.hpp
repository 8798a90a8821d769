// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Range image (paper Sec. IV-A): a (ring, column) cell for every valid point, without losses:
// several points may share a cell and none is dropped (the reference keeps one point per cell
// and reads past its table for points above the top beam).
//
// Rings come from (params.ring_source = auto tries them in this order):
//   field       the input's ring field (PointCloud::ring), when present and < num_rings;
//   scan_order  KITTI-style .bin files store the points laser by laser, each sweeping the full
//               azimuth: a ring ends where the azimuth wraps around. Accepted only when the
//               recovered ring count is plausible for num_rings;
//   table       nearest beam of an elevation table (params.elevation_table: a sensor's table, or
//               num_rings uniform bins), by the point's elevation in the sensor frame.
// Columns: azimuth in the sensor frame, num_columns bins over 360 degrees, column 0 at -180.
// Sweep start: the column where the sweep began (and ended 0.1 s later): of the earliest valid
// point by the time field, else of the first valid point in storage order when that order is
// the sweep's (rings from the field or the scan order: KITTI .bin files start at azimuth 0,
// ahead), else unknown (-1). Objects moving relative to the sensor are seen displaced across
// it (RunClustering's seam linkage).
#pragma once

#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"

namespace travel {

enum class RingSource : uint8_t { None = 0, Field = 1, ScanOrder = 2, Table = 3 };
const char* toString(RingSource source);

/// Beam elevations [deg] by ascending ring of a named table ("hdl64", "hdl32", "vlp16",
/// "os128"), or num_rings uniform bins for "uniform". Throws ConfigError for other names.
std::vector<double> elevationTableDeg(const Params& params);

class RangeImage {
  public:
    /// Assigns row (ring, 0 = lowest elevation) and column to every point with valid[i] != 0;
    /// other points get row = col = -1. `cloud` is in the sensor frame (as acquired: the
    /// beams are fixed there). Reuses its buffers across frames.
    void build(const PointCloud& cloud, const std::vector<uint8_t>& valid, const Params& params);
    /// Sizes (and maps) the buffers for frames of up to `points` points.
    void reserve(std::size_t points);

    int rows() const { return rows_; }
    int cols() const { return cols_; }
    RingSource source() const { return source_; }
    /// Column where the sweep started and ended (see the file comment), -1 when unknown.
    int sweepStartColumn() const { return sweep_start_col_; }
    const std::vector<int16_t>& row() const { return row_; }
    const std::vector<int32_t>& col() const { return col_; }

  private:
    int rows_ = 0, cols_ = 0;
    RingSource source_ = RingSource::None;
    int sweep_start_col_ = -1;
    std::vector<int16_t> row_;
    std::vector<int32_t> col_;
    std::vector<double> table_deg_;              // cached elevation table
    std::vector<float> table_mid_;               // decision boundaries between table beams [rad]
    std::vector<int32_t> table_mids_quantised_;  // the same, quantised (row_of_elevation_'s)
    std::vector<int16_t> row_of_elevation_;      // row of each quantised elevation
    std::vector<int16_t> elevation_;  // quantised elevations, when taken with the columns
};

}  // namespace travel
