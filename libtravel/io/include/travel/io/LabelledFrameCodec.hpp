// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The binary form of a travel::LabelledFrame: what travel_mrpt::CObservationTravelLabels stores
// in rawlogs after its own header (sensor label, timestamp, pose, source class). Little-endian,
// no padding:
//   u32 n; f32 x[n], y[n], z[n], intensity[n]; u8 labels[n]; u32 clusterId[n];
//   u32 clusters; per cluster: u32 id, num_points, first_point; f32 centroid[3], aabb_min[3],
//     aabb_max[3], obb_yaw, obb_center[3], obb_extent[3], ground_z, height_above_ground;
//     (layout >= 1) u32 track_id; f32 velocity[3], velocity_sigma[3]; u8 moving (0 or 1);
//   f32 resolution; i32 cells_per_side; f32 origin_xy; u32 nodes; per node: u32 index;
//     u8 node_class, flags (1 traversable, 2 refitted); f32 normal[3], d, corner_z[3], mean[3];
//   f32 alignedRotation[9] (column-major); f64 timings (StageTimings, declaration order).
// Strings (for the caller's header) are u32 length + bytes.
//
// The layout has versions (the caller stores the number, e.g. as its serialization version):
// 0 = without the tracking fields, 1 = with them (issue 19). The writer writes the newest;
// the reader reads any, leaving the tracking fields of layout 0 at zero (untracked).
//
// The reader checks every count and id against what was already read, and grows large arrays
// slice by slice as bytes actually arrive: a corrupt or truncated stream throws InputError
// ("corrupt or truncated stream: ...") instead of allocating gigabytes or yielding an
// inconsistent frame; the frame is then left empty.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "travel/LabelledFrame.hpp"

namespace travel::io {

/// Where the writer puts bytes (an MRPT archive, a buffer, a file).
class ByteSink {
  public:
    virtual ~ByteSink() = default;
    virtual void write(const void* data, std::size_t bytes) = 0;
};

/// Where the reader takes bytes: read() returns how many it could read (less at the end).
class ByteSource {
  public:
    virtual ~ByteSource() = default;
    virtual std::size_t read(void* data, std::size_t bytes) = 0;
};

/// The layout writeLabelledFrame() writes (see above).
constexpr uint8_t kLabelledFrameLayout = 1;

/// Longest string writeString() writes (longer ones are cut) and readString() accepts.
constexpr std::size_t kMaxStringLength = 65536;

void writeString(ByteSink& out, const std::string& s);
/// Reads exactly `bytes` bytes; throws InputError naming `what` when the stream ends before.
void readExactly(ByteSource& in, void* data, std::size_t bytes, const char* what);
void readString(ByteSource& in, std::string& s, const char* what);

/// Throws std::logic_error when the per-point vectors differ in size.
void writeLabelledFrame(ByteSink& out, const LabelledFrame& frame);
/// Reads a frame written in `layout` (0..kLabelledFrameLayout). Throws InputError (see above)
/// and leaves `frame` empty when the stream is corrupt, truncated or holds more than max_points
/// points, or the layout is unknown.
void readLabelledFrame(ByteSource& in, LabelledFrame& frame, std::size_t max_points,
                       uint8_t layout = kLabelledFrameLayout);

}  // namespace travel::io
