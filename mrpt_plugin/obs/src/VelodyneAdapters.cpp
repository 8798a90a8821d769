// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Velodyne family: CObservationVelodyneScan (raw packets) and CObservationRotatingScan (range
// image). Both index lasers in FIRING order; TRAVEL wants rings in ELEVATION order.
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/VelodyneCalibration.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <array>

#include "travel/io/RotatingScan.hpp"
#include "travel/io/VelodyneModels.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"

namespace travel_mrpt {
namespace {

using mrpt::obs::CObservationRotatingScan;
using mrpt::obs::CObservationVelodyneScan;
using mrpt::obs::VelodyneCalibration;

using travel::io::kMaxLasers;
using RingTable = std::array<uint16_t, kMaxLasers>;
using LaserTable = std::array<travel::io::LaserCorrection, kMaxLasers>;

bool fail(std::string* why_not, const char* reason) {
    if (why_not) *why_not = reason;
    return false;
}

/// MRPT's calibration as libtravel's (n <= kMaxLasers lasers).
void toLaserTable(const VelodyneCalibration& calib, LaserTable& lasers) {
    for (std::size_t i = 0; i < calib.laser_corrections.size(); ++i) {
        const auto& lc = calib.laser_corrections[i];
        lasers[i] = {lc.verticalCorrection, lc.verticalOffsetCorrection,
                     lc.horizontalOffsetCorrection, lc.azimuthCorrection};
    }
}

/// Streams MRPT's decoded points straight into the travel cloud (no intermediate copy).
class TravelCloudSink final : public CObservationVelodyneScan::PointCloudStorageWrapper {
  public:
    TravelCloudSink(travel::PointCloud& out, const RingTable& ring_of_laser, std::size_t num_lasers,
                    mrpt::system::TTimeStamp t0, bool with_time)
        : out_(out),
          ring_of_laser_(ring_of_laser),
          num_lasers_(num_lasers),
          t0_(t0),
          with_time_(with_time) {}

    void reserve(std::size_t n) override {
        out_.reserve(n);
        out_.ring.reserve(n);
        if (with_time_) out_.time.reserve(n);
    }

    void add_point(float x, float y, float z, uint8_t intensity, const mrpt::system::TTimeStamp& t,
                   const float /*azimuth*/, uint16_t laser_id) override {
        out_.push_back(x, y, z, intensity);
        // Ids beyond the calibration cannot come from a consistent scan; clamp, never overrun.
        out_.ring.push_back(ring_of_laser_[std::min<std::size_t>(laser_id, num_lasers_ - 1)]);
        if (with_time_)
            out_.time.push_back(static_cast<float>(mrpt::system::timeDifference(t0_, t)));
    }

  private:
    travel::PointCloud& out_;
    const RingTable& ring_of_laser_;
    std::size_t num_lasers_;
    mrpt::system::TTimeStamp t0_;
    bool with_time_;
};

/// The default calibration for a rotating scan's lidarModel, falling back on the row count
/// (travel::io::velodyneModelFor), and its laser timing. Null when none fits (MRPT 2.5.8's
/// HDL64 default is empty, see the notes).
const VelodyneCalibration* calibrationFor(const CObservationRotatingScan& obs, std::size_t rows,
                                          double& laser_delay_in_columns) {
    const std::optional<travel::io::VelodyneModel> model =
        travel::io::velodyneModelFor(obs.lidarModel, rows);
    if (!model) return nullptr;
    laser_delay_in_columns = model->laser_delay_in_columns;
    const VelodyneCalibration& calib = VelodyneCalibration::LoadDefaultCalibration(model->name);
    if (calib.empty() || calib.laser_corrections.size() != rows) return nullptr;
    return &calib;
}

}  // namespace

bool velodyneToTravelCloud(const CObservationVelodyneScan& obs, travel::PointCloud& out,
                           std::string* why_not) {
    out.clear();
    const std::size_t num_lasers = obs.calibration.laser_corrections.size();
    if (num_lasers == 0)
        return fail(why_not, "Velodyne scan without calibration: cannot decode its packets");
    if (num_lasers > kMaxLasers) return fail(why_not, "Velodyne calibration with > 256 lasers");
    if (obs.scan_packets.empty()) return fail(why_not, "Velodyne scan without packets");

    LaserTable lasers;
    toLaserTable(obs.calibration, lasers);
    RingTable ring_of_laser{};
    travel::io::ringOfLaser(lasers.data(), num_lasers, ring_of_laser.data());

    CObservationVelodyneScan::TGeneratePointCloudParameters gen;
    gen.minDistance = 0.f;  // the range window is libtravel's min_range/max_range
    gen.generatePerPointTimestamp = obs.timestamp != INVALID_TIMESTAMP;
    TravelCloudSink sink(out, ring_of_laser, num_lasers, obs.timestamp,
                         gen.generatePerPointTimestamp);
    // generatePointCloud() only reads the packets; it is non-const because the overload
    // without a sink writes into obs.point_cloud. The sink overload does not.
    const_cast<CObservationVelodyneScan&>(obs).generatePointCloud(sink, gen);
    if (out.empty()) return fail(why_not, "Velodyne scan without any return");
    return true;
}

bool rotatingScanToTravelCloud(const CObservationRotatingScan& obs, travel::PointCloud& out,
                               std::string* why_not) {
    out.clear();
    const auto& ranges = obs.rangeImage;
    const std::size_t rows = static_cast<std::size_t>(ranges.rows());
    const std::size_t cols = static_cast<std::size_t>(ranges.cols());
    if (rows == 0 || cols == 0) return fail(why_not, "rotating scan with an empty range image");
    if (rows > kMaxLasers) return fail(why_not, "rotating scan with > 256 rows");
    double laser_delay_in_columns = 0;
    const VelodyneCalibration* calib = calibrationFor(obs, rows, laser_delay_in_columns);
    if (!calib)
        return fail(why_not,
                    "rotating scan: no Velodyne calibration for its lidarModel/row count "
                    "(MRPT 2.5 has VLP-16 and HDL-32E)");

    // MRPT 2.5's fromVelodyne() makes columnCount rowCount times too large and fills only the
    // first 1/rowCount of the columns (VLP-16: every other one, one firing per column). A real
    // scan has returns in its last columns too, so data ending before cols/rows means the quirk:
    // the true column count (which sets the azimuth and time of a column) is then cols/rows.
    std::size_t last_used = 0;
    bool any = false;
    for (std::size_t c = cols; c-- > 0 && !any;)
        for (std::size_t r = 0; r < rows; ++r)
            if (ranges(r, c) != 0) {
                last_used = c, any = true;
                break;
            }
    if (!any) return fail(why_not, "rotating scan without any return");
    const bool mrpt_quirk = (last_used + 1) * rows <= cols;
    const std::size_t true_cols = mrpt_quirk ? cols / rows : cols;
    // The per-laser firing delay is only known for fromVelodyne()'s column layout.
    if (!mrpt_quirk) laser_delay_in_columns = 0;

    travel::io::RangeImageScan scan;
    scan.ranges = ranges.data();
    scan.intensity = static_cast<std::size_t>(obs.intensityImage.rows()) == rows &&
                             static_cast<std::size_t>(obs.intensityImage.cols()) == cols
                         ? obs.intensityImage.data()
                         : nullptr;
    scan.rows = rows, scan.columns = cols, scan.columns_used = last_used + 1;
    scan.sweep_columns = true_cols;
    scan.laser_delay_in_columns = laser_delay_in_columns;
    scan.range_resolution = obs.rangeResolution;
    scan.start_azimuth = obs.startAzimuth, scan.azimuth_span = obs.azimuthSpan;
    scan.sweep_duration = obs.sweepDuration;
    LaserTable lasers;
    toLaserTable(*calib, lasers);
    travel::io::rangeImageToCloud(scan, lasers.data(), out);
    return true;
}

}  // namespace travel_mrpt
