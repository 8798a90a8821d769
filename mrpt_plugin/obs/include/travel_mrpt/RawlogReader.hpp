// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Reading an MRPT rawlog, written once for every tool (travel-rawlog, travel-map):
//
//   travel_mrpt::RawlogReader reader("in.rawlog");    // plain or gzip
//   travel_mrpt::RawlogMotion motion(filter);
//   while (auto record = reader.next()) {             // null at the end of the file
//       if (motion.process(*record)) continue;        // IMU, odometry, odometry actions
//       ...                                            // an observation or a SensoryFrame
//   }
//
// Both rawlog formats are streams of serialized objects: observations (CObservation*), or
// SensoryFrames alternating with CActionCollections. Every error is a travel::InputError whose
// message names the file and, once reading started, the record: "<file>: record <n>: <what>".
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include <mrpt/poses/CPose3D.h>

namespace mrpt::serialization {
class CSerializable;
}

namespace travel_mrpt {

class TravelFilter;

class RawlogReader {
  public:
    /// Opens the file and points MRPT's external storage at its "<name>_Images" folder
    /// (mrpt::img::CImage::setImagesPathBase, as MRPT's tools do). Throws InputError "<path>: no
    /// such file", "<path>: is a directory, not a rawlog" or "<path>: cannot open for reading".
    explicit RawlogReader(const std::string& path);
    ~RawlogReader();
    RawlogReader(const RawlogReader&) = delete;
    RawlogReader& operator=(const RawlogReader&) = delete;

    /// "<path>: record <n>": how every message names a record of a rawlog.
    static std::string where(const std::string& path, long record) {
        return path + ": record " + std::to_string(record);
    }

    /// The next record, or null at the end of the file (exactly at a record boundary). Throws
    /// InputError naming the record when it cannot be read: "truncated (end of file inside the
    /// record)", "corrupt record (it announces more data than --max-memory allows); is it a
    /// rawlog?" (std::bad_alloc), "cannot read (is it an MRPT rawlog?): ..." for the first
    /// record and "cannot read: ..." for later ones (MRPT's message, one line); at an end of
    /// file before any record: "empty file, not a rawlog" or "no record could be read (not an
    /// MRPT rawlog, or a corrupt gzip stream)".
    std::shared_ptr<mrpt::serialization::CSerializable> next();

    /// Bytes read over the file size, in [0, 1] (of the compressed bytes for a gzip rawlog);
    /// -1 when unknown. For a progress fraction and ETA.
    double fractionRead() const;
    /// Records read so far (the index of the next record).
    long index() const { return index_; }
    const std::string& path() const { return path_; }

  private:
    /// Every byte of the file was read (of the compressed file for gzip; false when unknown).
    bool wholeFileRead() const;
    struct Stream;
    std::string path_;
    std::unique_ptr<Stream> stream_;
    long index_ = 0;
};

/// The robot's motion in a rawlog: IMU and odometry observations and the odometry actions of
/// SensoryFrame rawlogs feed the filter's motion estimate (attitude levelling, deskew) and the
/// robot pose.
class RawlogMotion {
  public:
    explicit RawlogMotion(TravelFilter& filter) : filter_(filter) {}

    /// Takes a CObservationIMU, CObservationOdometry or CActionCollection (its best
    /// CActionRobotMovement2D); returns false, doing nothing, for any other record.
    bool process(const mrpt::serialization::CSerializable& record);

    /// The robot pose: the odometry actions composed from the identity when the rawlog has
    /// any, else the latest odometry observation, else nothing.
    std::optional<mrpt::poses::CPose3D> robotPose() const;
    std::size_t actions() const { return actions_; }
    bool hasOdometry() const { return has_odometry_; }

  private:
    TravelFilter& filter_;
    mrpt::poses::CPose3D action_pose_, odometry_pose_;
    std::size_t actions_ = 0;
    bool has_odometry_ = false;
};

}  // namespace travel_mrpt
