// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// What the sample data showed (shared/data, see the ring sources in RangeImage.hpp):
//   - Rows are ordered by ascending elevation (row 0 = lowest beam), whatever the input's ring
//     numbering. The MRPT adapters and nuScenes number rings that way (nuScenes
//     hdl32_000000.bin: ring 0 has median elevation -30.6 deg, ring 31 +10.7 deg, 1.33 deg
//     apart, stored column by column), but Ouster drivers number ring 0 as the top beam and
//     raw Velodyne laser ids are interleaved. So the field's numbering is checked on every
//     frame: ascending is kept, descending is reversed, anything else is sorted by each ring's
//     mean elevation.
//   - KITTI .bin files store the lasers top beam first (+2 deg down to -24 deg), each sweeping
//     counter-clockwise from azimuth 0 (the frame is cut facing forward); the lowest beams miss
//     about +-20 deg ahead (the car's hood). The recovered rings are therefore reversed.
//   - The ouster128 sample is stored ring by ring too, but clockwise. Its origin is at ground
//     level, so the rings' mean elevations seen from there are not in beam order: auto rejects
//     the scan order (its walk stops after 48 of the 128 rings, where the disorder is certain)
//     and uses the table.
//   - Elevation tables: see fillElevationTableDeg().
//
// build() makes three passes over the points: one vectorised (azimuths and columns), one that
// assigns provisional ring ids (field statistics, the scan-order walk, or the elevation table),
// and one mapping them to rows: 0.55 ms for a 124k-point KITTI frame on the development machine
// with baseline SSE2 code, ~0.3 ms with the per-point loops' AVX2 clones (see
// TRAVEL_AVX2_CLONES; docs/performance.md). When the elevation table gave the last frame's rows
// (or is the source asked for), the first pass also takes the quantised elevations.
#include "travel/RangeImage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "CpuDispatch.hpp"
#include "FastAtan2.hpp"
#include "Prefault.hpp"
#include "travel/EnumNames.hpp"
#include "travel/Errors.hpp"

namespace travel {

namespace {

using detail::fastAtan2;

constexpr float kPi = 3.14159265358979f;
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

constexpr EnumName<RingSource> kRingSourceNames[] = {{RingSource::None, "none"},
                                                     {RingSource::Field, "field"},
                                                     {RingSource::ScanOrder, "scan_order"},
                                                     {RingSource::Table, "table"}};

// Params limits num_rings to 1024; per-ring arrays live on the stack at this size.
constexpr int kMaxRings = 1024;

// The HDL-64E's lasers do not fire from the sensor origin: fitting z = tan(e) * r_xy + h to each
// KITTI ring gives h = 0.18-0.21 m for the upper block, so near points of a beam look up to
// 2 deg higher than far ones. The hdl64 table is measured from this height, which halves its
// row errors on KITTI; the other tables assume beams from the origin.
constexpr float kHdl64BeamOriginHeight = 0.2f;

// Height above the origin from which the elevation table's beams are seen.
float tableOriginHeight(const Params& params) {
    return params.elevation_table == "hdl64" ? kHdl64BeamOriginHeight : 0.0f;
}

// HDL-64E S2 on KITTI, ascending [deg]. Measured: rings of SemanticKITTI sequence 00 frames
// 000000-000005 recovered from the scan order (cut at azimuth 0), then each ring's median of
// atan2(z - 0.2 m, r_xy) over the points with 3-D range in [2.7, 80] m. With this table 80 % of
// the KITTI points get their scan-order row and 96 % are within one row (without the 0.2 m:
// 45 % / 89 %; the nominal two linear blocks +2.0..-8.33 and -8.83..-24.33 deg: 12 % / 58 %).
constexpr std::array<double, 64> kHdl64ElevationsDeg = {
    -26.014, -25.491, -24.985, -24.320, -23.854, -23.408, -22.908, -22.225, -21.682, -21.088,
    -20.583, -20.146, -19.610, -19.112, -18.484, -17.924, -17.256, -16.851, -16.309, -15.819,
    -15.212, -14.641, -14.052, -13.596, -13.099, -12.637, -12.103, -11.429, -10.926, -10.506,
    -10.001, -9.447,  -8.724,  -8.321,  -8.068,  -7.686,  -7.292,  -7.001,  -6.679,  -6.330,
    -5.956,  -5.609,  -5.248,  -4.909,  -4.583,  -4.207,  -3.927,  -3.529,  -3.224,  -2.862,
    -2.532,  -2.191,  -1.814,  -1.473,  -1.179,  -0.780,  -0.429,  -0.066,  0.203,   0.601,
    0.894,   1.329,   1.599,   1.963};

void uniformElevations(int beams, double lo_deg, double hi_deg, std::vector<double>& out) {
    out.resize(static_cast<std::size_t>(beams));
    for (int k = 0; k < beams; ++k) {
        out[k] = beams == 1 ? lo_deg : lo_deg + (hi_deg - lo_deg) * k / (beams - 1);
    }
}

// elevationTableDeg() into `out`, reusing its capacity.
void fillElevationTableDeg(const Params& params, std::vector<double>& out) {
    const std::string& name = params.elevation_table;
    if (name == "hdl64") {
        out.assign(kHdl64ElevationsDeg.begin(), kHdl64ElevationsDeg.end());
    } else if (name == "hdl32") {
        // HDL-32E datasheet; the nuScenes sample's ring medians agree within 0.1 deg.
        uniformElevations(32, -30.67, 10.67, out);
    } else if (name == "vlp16") {
        uniformElevations(16, -15.0, 15.0, out);  // VLP-16 datasheet
    } else if (name == "os128") {
        // OS1-128 datasheet (uniform). The ouster128 sample is not an OS1-128 in its own frame:
        // its sensor sits 2.6 m behind and 1.8 m above the origin, and its beams are not
        // uniform (docs/performance.md, "The sample's own sensor frame and rings").
        uniformElevations(128, -22.5, 22.5, out);
    } else if (name == "uniform") {
        if (params.num_rings < 1) throw ConfigError("num_rings must be >= 1");
        uniformElevations(params.num_rings, params.min_elevation_deg, params.max_elevation_deg,
                          out);
    } else {
        throw ConfigError("elevation_table = '" + name +
                          "' is not one of hdl64|hdl32|vlp16|os128|uniform");
    }
}

// ---- Vectorisable maths ------------------------------------------------------------------
// The library is built for baseline x86-64 (SSE2) without -ffast-math; these are written so
// that GCC vectorises the loops that use them.

// std::sqrt keeps an errno branch (no -fno-math-errno here) that stops vectorisation. Inverse
// square root from the exponent bits and three Newton steps: relative error 2e-7.
inline float vectorisableSqrt(float s) {
    uint32_t bits;
    std::memcpy(&bits, &s, sizeof bits);
    bits = 0x5f375a86u - (bits >> 1);
    float inverse;
    std::memcpy(&inverse, &bits, sizeof inverse);
    const float half = 0.5f * s;
    inverse *= 1.5f - half * inverse * inverse;
    inverse *= 1.5f - half * inverse * inverse;
    inverse *= 1.5f - half * inverse * inverse;
    return s * inverse;  // s = 0: the guess stays finite, so 0
}

// Angles in [-pi, pi] as int16 steps of pi / 32767 (0.0055 deg), NaN -> kNoAngle. Used for the
// scan-order walk (a turn is kTurn steps) and for elevations in [-pi/2, pi/2].
constexpr int kNoAngle = -32768;
constexpr int kHalfTurn = 32767;
constexpr int kTurn = 2 * kHalfTurn;

inline int16_t quantisedAngle(float angle) {
    constexpr float kStepsPerRad = kHalfTurn / kPi;
    float v = std::max(static_cast<float>(kNoAngle), angle * kStepsPerRad);  // NaN -> kNoAngle
    v = std::min(v, static_cast<float>(kHalfTurn));
    return static_cast<int16_t>(v);  // truncation: -pi (-32767.x) stays above kNoAngle
}

// a - b for quantised azimuths, wrapped into [-half turn, half turn).
inline int angleDifference(int a, int b) {
    int d = a - b;
    d -= d >= kHalfTurn ? kTurn : 0;
    d += d < -kHalfTurn ? kTurn : 0;
    return d;
}

// The per-point loops of build() (and the scan-order walk's block test below) are compiled
// twice, for baseline x86-64 and for AVX2 (CpuDispatch.hpp: same results, more lanes).

// Quantised azimuths (for the scan-order walk) and final columns: col = floor((azimuth + pi) /
// 2 pi * columns), clamped (azimuth +pi, y = +0 and x < 0, is the last column, -pi the first;
// no azimuth, x = y = 0 or NaN, column 0), -1 where !keep.
struct ColumnScale {
    explicit ColumnScale(int cols)
        : per_rad(static_cast<float>(cols) / (2.0f * kPi)),
          middle(0.5f * static_cast<float>(cols)),
          last(static_cast<float>(cols - 1)) {}
    float per_rad, middle, last;
};

TRAVEL_INTO_CALLER void azimuthAndColumn(float x, float y, uint8_t keep, const ColumnScale& scale,
                                         int16_t& azimuth16, int32_t& col) {
    const float azimuth = fastAtan2(y, x);
    azimuth16 = quantisedAngle(azimuth);
    float column = std::max(0.0f, azimuth * scale.per_rad + scale.middle);  // NaN -> 0
    column = std::min(column, scale.last);
    col = keep ? static_cast<int32_t>(column) : -1;
}

// Quantised elevations seen from origin_height above the origin.
TRAVEL_INTO_CALLER int16_t quantisedElevation(float x, float y, float z, float origin_height) {
    const float horizontal = vectorisableSqrt(x * x + y * y);
    return quantisedAngle(fastAtan2(z - origin_height, horizontal));
}

TRAVEL_AVX2_CLONES
void azimuthsAndColumns(const float* xs, const float* ys, const uint8_t* keep, std::size_t n,
                        int cols, int16_t* azimuth16, int32_t* col) {
    const ColumnScale scale(cols);
    for (std::size_t i = 0; i < n; ++i)
        azimuthAndColumn(xs[i], ys[i], keep[i], scale, azimuth16[i], col[i]);
}

TRAVEL_AVX2_CLONES
void quantisedElevations(const float* xs, const float* ys, const float* zs, std::size_t n,
                         float origin_height, int16_t* elevation16) {
    for (std::size_t i = 0; i < n; ++i)
        elevation16[i] = quantisedElevation(xs[i], ys[i], zs[i], origin_height);
}

// Both in one pass over the points (the same values): when the rows will come from the
// elevation table.
TRAVEL_AVX2_CLONES
void azimuthsColumnsAndElevations(const float* xs, const float* ys, const float* zs,
                                  const uint8_t* keep, std::size_t n, int cols, float origin_height,
                                  int16_t* azimuth16, int32_t* col, int16_t* elevation16) {
    const ColumnScale scale(cols);
    for (std::size_t i = 0; i < n; ++i) {
        azimuthAndColumn(xs[i], ys[i], keep[i], scale, azimuth16[i], col[i]);
        elevation16[i] = quantisedElevation(xs[i], ys[i], zs[i], origin_height);
    }
}

// A block of the scan-order walk (RowAssigner::findRings): the azimuth swept from each
// point's predecessor to it, summed into `sweep`, and whether the block holds a point without
// azimuth or a drop of the offset from `cut` by more than half a turn (a wrap: the walk then
// takes the block point by point). `azimuth[-1]` is read. Integer arithmetic: every clone
// gives the same result.
template <int Direction>
bool blockSweepImpl(const int16_t* azimuth, std::size_t count, int cut, int& sweep) {
    auto offsetOf = [cut](int a) {  // swept since the cut, in [0, turn)
        const int offset = Direction * (a - cut);
        return offset + (offset < 0 ? kTurn : 0);
    };
    int irregular = 0;
    for (std::size_t j = 0; j < count; ++j) {
        const int a = azimuth[j], p = azimuth[static_cast<std::ptrdiff_t>(j) - 1];
        irregular |= (a == kNoAngle) | (offsetOf(p) - offsetOf(a) > kHalfTurn);
        sweep += Direction * angleDifference(a, p);
    }
    return irregular != 0;
}

TRAVEL_AVX2_CLONES
bool blockSweepForward(const int16_t* azimuth, std::size_t count, int cut, int& sweep) {
    return blockSweepImpl<+1>(azimuth, count, cut, sweep);
}

TRAVEL_AVX2_CLONES
bool blockSweepBackward(const int16_t* azimuth, std::size_t count, int cut, int& sweep) {
    return blockSweepImpl<-1>(azimuth, count, cut, sweep);
}

template <int Direction>
bool blockSweep(const int16_t* azimuth, std::size_t count, int cut, int& sweep) {
    return Direction > 0 ? blockSweepForward(azimuth, count, cut, sweep)
                         : blockSweepBackward(azimuth, count, cut, sweep);
}

// row[i] = row_of[elevation[i] - kNoAngle], -1 where !keep[i], from i = begin; `elevation` may
// be `row`. Its own function, without a branch: inside RangeImage::build() GCC kept the pointers
// on the stack and branched on keep[i], a mispredicted branch wherever valid and invalid points
// alternate.
void rowsOfElevationsScalar(const int16_t* row_of, const int16_t* elevation, const uint8_t* keep,
                            std::size_t begin, std::size_t n, int16_t* row) {
    for (std::size_t i = begin; i < n; ++i) {
        const int beam = row_of[elevation[i] - kNoAngle];  // >= 0
        row[i] = static_cast<int16_t>(beam | -static_cast<int>(keep[i] == 0));
    }
}

#ifdef TRAVEL_AVX2_INTRINSICS
// The same, 8 points at a time: a 32-bit gather at each entry (row_of holds one more entry, so
// that the last one's upper half is readable), its lower 16 bits the row (little endian).
__attribute__((target("avx2"))) void rowsOfElevationsAvx2(const int16_t* row_of,
                                                          const int16_t* elevation,
                                                          const uint8_t* keep, std::size_t n,
                                                          int16_t* row) {
    const int* base = reinterpret_cast<const int*>(row_of);
    const __m256i offset = _mm256_set1_epi32(-kNoAngle), low16 = _mm256_set1_epi32(0xffff);
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i e = _mm256_add_epi32(
            _mm256_cvtepi16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(elevation + i))),
            offset);
        const __m256i beam = _mm256_and_si256(_mm256_i32gather_epi32(base, e, 2), low16);
        const __m256i invalid = _mm256_cmpeq_epi32(
            _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(keep + i))),
            _mm256_setzero_si256());
        const __m256i rows = _mm256_or_si256(beam, invalid);  // in [-1, 32767]
        const __m256i packed = _mm256_permute4x64_epi64(_mm256_packs_epi32(rows, rows), 0xd8);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(row + i), _mm256_castsi256_si128(packed));
    }
    rowsOfElevationsScalar(row_of, elevation, keep, i, n, row);
}
#endif

// row_of: 65537 entries (see rowsOfElevationsAvx2).
void rowsOfElevations(const int16_t* row_of, const int16_t* elevation, const uint8_t* keep,
                      std::size_t n, int16_t* row) {
#ifdef TRAVEL_AVX2_INTRINSICS
    if (detail::cpuHasAvx2()) return rowsOfElevationsAvx2(row_of, elevation, keep, n, row);
#endif
    rowsOfElevationsScalar(row_of, elevation, keep, 0, n, row);
}

// ---- Ring statistics and row maps ------------------------------------------------------------

// Per ring, sum z / sum range is the range-weighted mean sine of elevation: far points, whose
// elevation is least distorted by the beams' offsets from the origin, weigh most.
class RingStats {
  public:
    // Sums stay in registers while consecutive points share a ring: ring-by-ring input would
    // otherwise chain every addition through memory.
    void add(int ring, float x, float y, float z) {
        float range;
        if (!counted(x, y, z, range)) return;
        if (ring != run_ring_) {
            flush();
            run_ring_ = ring;
        }
        run_z_ += z;
        run_range_ += range;
    }
    // The point's range; false (not counted) when it is NaN or inf.
    static bool counted(float x, float y, float z, float& range) {
        range = std::sqrt(x * x + y * y + z * z);
        return range <= std::numeric_limits<float>::max();
    }
    // Call once after the last add().
    void flush() {
        if (run_ring_ >= 0) {
            sum_z_[run_ring_] += run_z_;
            sum_range_[run_ring_] += run_range_;
        }
        run_ring_ = -1;
        run_z_ = run_range_ = 0.0f;
    }
    // The sums of one run of add() calls for `ring` (any: at least one point), made by the
    // caller in registers: the same floats as those calls and flush().
    void addRun(int ring, bool any, float z, float range) {
        flush();
        if (any) sum_z_[ring] += z, sum_range_[ring] += range;
    }
    bool has(int ring) const { return sum_range_[ring] > 0.0; }
    double sinElevation(int ring) const { return sum_z_[ring] / sum_range_[ring]; }

  private:
    std::array<double, kMaxRings> sum_z_{}, sum_range_{};
    int run_ring_ = -1;
    float run_z_ = 0.0f, run_range_ = 0.0f;
};

// Provisional ring ids (field values, or rings in storage order) to rows.
struct RowMap {
    enum Kind { Identity, Reversed, Lookup } kind = Identity;
    int last = 0;                             // Reversed: row = last - id
    std::array<int16_t, kMaxRings> row_of{};  // Lookup
};

// How far (in ranks among the ids that have points) an id may sit from its place by elevation
// with its ids still "in elevation order" (see mapByElevation()).
constexpr int kMaxDisplacement = 2;

// The map for ids 0..count-1 from their mean elevations. Ids in ascending elevation order are
// kept, in descending order reversed, where "in order" tolerates each id being up to
// kMaxDisplacement places from its rank (neighbours with nearly equal means, a ring seen only at
// short range). Otherwise `mixed` is set and the ids that have points keep their set of rows,
// handed out by ascending mean elevation.
RowMap mapByElevation(const RingStats& stats, int count, bool& mixed) {
    std::array<int16_t, kMaxRings> present{}, by_elevation{}, position{};
    int used = 0;
    for (int id = 0; id < count; ++id) {
        if (!stats.has(id)) continue;
        position[id] = static_cast<int16_t>(used);
        present[used++] = static_cast<int16_t>(id);
    }
    std::copy(present.begin(), present.begin() + used, by_elevation.begin());
    // Ascending mean elevation, equal means in ascending id order: the order of a stable sort
    // of `present`, without the buffer std::stable_sort allocates on every frame.
    std::sort(by_elevation.begin(), by_elevation.begin() + used, [&](int16_t a, int16_t b) {
        const double ea = stats.sinElevation(a), eb = stats.sinElevation(b);
        return ea < eb || (ea == eb && a < b);
    });
    // by_elevation[k] = present[k] when ascending, present[used - 1 - k] when descending.
    int ascending_displacement = 0, descending_displacement = 0;
    for (int k = 0; k < used; ++k) {
        const int at = position[by_elevation[k]];
        ascending_displacement = std::max(ascending_displacement, std::abs(at - k));
        descending_displacement = std::max(descending_displacement, std::abs(at - (used - 1 - k)));
    }
    RowMap map;
    mixed = false;
    if (ascending_displacement <= kMaxDisplacement) return map;
    if (descending_displacement <= kMaxDisplacement) {
        map.kind = RowMap::Reversed;
        map.last = count - 1;
        return map;
    }
    mixed = true;
    map.kind = RowMap::Lookup;
    for (int id = 0; id < count; ++id) map.row_of[id] = static_cast<int16_t>(id);
    for (int k = 0; k < used; ++k) map.row_of[by_elevation[k]] = present[k];
    return map;
}

// Tells, from the first ids' mean elevations alone, that mapByElevation() will set `mixed`.
// Fed the ids that have points in ascending id order (their ranks are then final), it looks
// for two pairs of ids at least kMinRankGap ranks apart: one whose lower-ranked id is strictly
// above the other (stable sort: it then sorts after it, so one of the two lies more than
// kMaxDisplacement from its ascending place), and one whose lower-ranked id is not above the
// other (one of the two lies that far from its descending place).
class MixedOrderProof {
  public:
    static constexpr int kMinRankGap = 2 * kMaxDisplacement + 1;
    void add(double sin_elevation) {
        if (ranks_ >= kMinRankGap) {  // the id kMinRankGap ranks lower comes within reach
            const double reachable = sin_elevation_[ranks_ - kMinRankGap];
            lowest_ = std::min(lowest_, reachable), highest_ = std::max(highest_, reachable);
            not_ascending_ = not_ascending_ || highest_ > sin_elevation;
            not_descending_ = not_descending_ || lowest_ <= sin_elevation;
        }
        sin_elevation_[ranks_++] = sin_elevation;
    }
    bool mixed() const { return not_ascending_ && not_descending_; }

  private:
    std::array<double, kMaxRings> sin_elevation_{};  // by rank
    int ranks_ = 0;
    double lowest_ = std::numeric_limits<double>::infinity(), highest_ = -lowest_;
    bool not_ascending_ = false, not_descending_ = false;
};

// row[i] = map(id[i]), -1 where !valid[i]. `id` may be `row` itself.
template <class Id>
void applyRowMap(const RowMap& map, const Id* id, const std::vector<uint8_t>& valid, int16_t* row) {
    const uint8_t* keep = valid.data();
    const std::size_t n = valid.size();
    switch (map.kind) {
        case RowMap::Identity:
            for (std::size_t i = 0; i < n; ++i) row[i] = keep[i] ? int16_t(id[i]) : int16_t{-1};
            break;
        case RowMap::Reversed:
            for (std::size_t i = 0; i < n; ++i) {
                row[i] = keep[i] ? int16_t(map.last - id[i]) : int16_t{-1};
            }
            break;
        case RowMap::Lookup:
            for (std::size_t i = 0; i < n; ++i) row[i] = keep[i] ? map.row_of[id[i]] : int16_t{-1};
            break;
    }
}

// ---- Ring sources ----------------------------------------------------------------------------

// The ring sources. Each writes the final rows (-1 where !valid) into `row`, RangeImage's buffer,
// which holds the quantised azimuths on entry (see RangeImage::build()), or returns false and,
// given `why`, why it cannot be used (ring_source = auto passes none: it tries the next source,
// and a message made on every frame of a sensor without a ring field would allocate).
class RowAssigner {
  public:
    RowAssigner(const PointCloud& cloud, const std::vector<uint8_t>& valid, const Params& params,
                std::vector<int16_t>& row)
        : cloud_(cloud), valid_(valid), params_(params), row_(row), n_(cloud.size()) {}

    // The ring field, when every valid point's ring is below num_rings.
    bool fromField(std::string* why) {
        if (!cloud_.hasRing()) {
            if (why) *why = "the cloud has no ring field";
            return false;
        }
        const int num_rings = params_.num_rings;
        const uint16_t* ring = cloud_.ring.data();
        const uint8_t* keep = valid_.data();
        int max_ring = 0;
        for (std::size_t i = 0; i < n_; ++i) {
            max_ring = std::max<int>(max_ring, keep[i] ? ring[i] : 0);
        }
        if (max_ring >= num_rings) {
            if (why)
                *why = "a valid point has ring " + std::to_string(max_ring) +
                       " >= num_rings = " + std::to_string(num_rings);
            return false;
        }
        // Every 7th point is plenty for the mean elevations; 7 is prime to the usual ring counts,
        // which matters when the points are stored column by column. Each ring gets one at least.
        constexpr int kStatsStride = 7;
        RingStats stats;
        std::array<bool, kMaxRings> sampled{};
        for (std::size_t i = 0, countdown = 0; i < n_; ++i, --countdown) {
            if (keep[i] && (countdown == 0 || !sampled[ring[i]])) {  // invalid: any ring
                stats.add(ring[i], cloud_.x[i], cloud_.y[i], cloud_.z[i]);
                sampled[ring[i]] = true;
            }
            if (countdown == 0) countdown = kStatsStride;
        }
        stats.flush();
        bool mixed = false;
        applyRowMap(mapByElevation(stats, num_rings, mixed), ring, valid_, row_.data());
        return true;
    }

    // The storage order: a ring ends where the azimuth, measured from the first point's in the
    // sweep direction, drops back by more than half a turn. Needs num_rings / 2 to num_rings
    // rings; `strict` (ring_source = auto) also wants them stored in elevation order, either
    // way up (otherwise they are sorted by mean elevation).
    //
    // The cut between rings is taken at the first point's azimuth: when a later ring starts a
    // little before it (KITTI frame 000003: first point at 0.48 deg, true cut at 0), its first
    // points stay on the ring before (0.1 % of that frame's points).
    bool fromScanOrder(bool strict, std::string* why) {
        const int num_rings = params_.num_rings;
        const int16_t* azimuth = row_.data();
        const int direction = sweepDirection(azimuth);
        if (direction == 0) {
            if (why) *why = "no point has an azimuth";
            return false;
        }
        // ring_start[k]: index of ring k's first point; the points without azimuth that follow
        // a ring stay on it. Each ring's mean elevation is taken as soon as the walk has found
        // its end. When `strict`, rings found out of elevation order either way up
        // (MixedOrderProof) end the walk: the scan order would be rejected whatever followed.
        std::array<std::size_t, kMaxRings + 1> ring_start;
        RingStats stats;
        MixedOrderProof proof;
        const auto ring_found = [&](int ring, std::size_t end) {
            // Every 8th point is plenty for a ring's mean elevation; each ring gets one at least.
            constexpr std::size_t kStatsStride = 8;
            std::size_t i = ring_start[ring];
            while (i < end && !valid_[i]) ++i;
            // RingStats::add() for each point, its sums kept in local registers (GCC kept the
            // object's in memory: a store and reload per point).
            bool any = false;
            float sum_z = 0.0f, sum_range = 0.0f;
            for (; i < end; i += kStatsStride) {
                float range;
                if (!valid_[i] || !RingStats::counted(cloud_.x[i], cloud_.y[i], cloud_.z[i], range))
                    continue;
                sum_z += cloud_.z[i], sum_range += range, any = true;
            }
            stats.addRun(ring, any, sum_z, sum_range);
            if (strict && stats.has(ring)) proof.add(stats.sinElevation(ring));
            return strict && proof.mixed();
        };
        const int recovered = direction > 0
                                  ? findRings<+1>(azimuth, num_rings, ring_start, ring_found)
                                  : findRings<-1>(azimuth, num_rings, ring_start, ring_found);
        if (recovered == kOutOfOrder) {
            if (why) *why = "the rings found are not stored in elevation order";
            return false;
        }
        if (recovered > num_rings) {
            if (why)
                *why =
                    "more than num_rings = " + std::to_string(num_rings) + " azimuth wrap-arounds";
            return false;
        }
        ring_start[recovered] = n_;
        if (recovered < std::max(1, num_rings / 2)) {
            if (why)
                *why = "only " + std::to_string(recovered) +
                       " azimuth wrap-arounds for num_rings = " + std::to_string(num_rings);
            return false;
        }
        ring_found(recovered - 1, n_);  // the last ring ends with the points
        bool mixed = false;
        const RowMap map = mapByElevation(stats, recovered, mixed);
        if (strict && mixed) {
            if (why) *why = "the rings found are not stored in elevation order";
            return false;
        }
        // Rows 0..recovered-1: rings never seen (beams into the sky) would be the top rows.
        const uint8_t* keep = valid_.data();
        int16_t* row = row_.data();
        for (int ring = 0; ring < recovered; ++ring) {
            const int16_t ring_row =
                static_cast<int16_t>(map.kind == RowMap::Identity   ? ring
                                     : map.kind == RowMap::Reversed ? map.last - ring
                                                                    : map.row_of[ring]);
            for (std::size_t i = ring_start[ring]; i < ring_start[ring + 1]; ++i) {
                row[i] = keep[i] ? ring_row : int16_t{-1};
            }
        }
        return true;
    }

    // The nearest beam of `table_deg` by elevation. `boundaries` receives the midpoints
    // between beams [rad]; `row_of_elevation` caches the row of every quantised elevation for
    // them (rebuilt when they change, `cached_mids` says for which).
    // `elevations`: the points' quantised elevations (tableOriginHeight()) if already
    // computed, else null.
    void fromTable(const std::vector<double>& table_deg, std::vector<float>& boundaries,
                   std::vector<int32_t>& cached_mids, std::vector<int16_t>& row_of_elevation,
                   const int16_t* elevations) {
        const int count = static_cast<int>(table_deg.size()) - 1;
        boundaries.resize(static_cast<std::size_t>(count));
        for (int k = 0; k < count; ++k) {
            boundaries[k] = static_cast<float>(0.5 * (table_deg[k] + table_deg[k + 1]) * kDegToRad);
        }
        // Vectorised: quantised elevations, in `row`, unless given.
        if (elevations == nullptr) {
            quantisedElevations(cloud_.x.data(), cloud_.y.data(), cloud_.z.data(), n_,
                                tableOriginHeight(params_), row_.data());
            elevations = row_.data();
        }
        int16_t* row = row_.data();
        const std::size_t n = n_;
        // A search per point would cost more than all the rest: the row of every quantised
        // elevation (65536 values and a padding entry, 128 KiB) is looked up instead, row = the
        // number of quantised boundaries <= the elevation (kNoAngle, NaN, ends on row 0). Built
        // once per table.
        std::array<int32_t, kMaxRings> mids{};
        for (int k = 0; k < count; ++k) mids[k] = quantisedAngle(boundaries[k]);
        if (cached_mids.size() != static_cast<std::size_t>(count) ||
            !std::equal(cached_mids.begin(), cached_mids.end(), mids.begin()) ||
            row_of_elevation.size() != 65537) {
            row_of_elevation.assign(65537, 0);
            int beam = 0;
            for (int e = kNoAngle; e <= kHalfTurn; ++e) {
                while (beam < count && mids[beam] <= e) ++beam;
                row_of_elevation[e - kNoAngle] = static_cast<int16_t>(beam);
            }
            cached_mids.assign(mids.begin(), mids.begin() + count);
        }
        rowsOfElevations(row_of_elevation.data(), elevations, valid_.data(), n, row);
    }

  private:
    static constexpr int kOutOfOrder = -1;  // findRings(): ring_found() stopped the walk

    // The walk of fromScanOrder(), for the sweep `Direction` (+1: azimuth increasing): fills
    // ring_start and returns the number of rings, or max_rings + 1 as soon as there are more.
    // A ring ends where the azimuth, measured from the first point's in the sweep direction,
    // drops back by more than half a turn; ring_found(ring, end) is then called (not for the
    // last ring), and when it returns true the walk stops with kOutOfOrder.
    template <int Direction, class RingFound>
    int findRings(const int16_t* azimuth, int max_rings,
                  std::array<std::size_t, kMaxRings + 1>& ring_start,
                  const RingFound& ring_found) const {
        // A ring must sweep this far before a wrap can end it: a ring's first points jittering
        // behind the cut (KITTI steps back by up to 7 deg) must not count as a revolution.
        constexpr int kMinRingSweep = kTurn / 4;
        int cut = kNoAngle, previous = 0, previous_offset = 0, sweep = 0, rings = 1;
        ring_start[0] = 0;
        auto offsetOf = [&cut](int a) {  // swept since the cut, in [0, turn)
            const int offset = Direction * (a - cut);
            return offset + (offset < 0 ? kTurn : 0);
        };
        // Most blocks of points hold no wrap (drop of the offset) and no point without azimuth:
        // there only the sweep grows, by the block's sum, found in one vectorised pass. The
        // other blocks take the point-by-point walk. Same rings as walking every point.
        constexpr std::size_t kBlock = 64;
        std::size_t i = 0;
        while (i < n_) {
            const std::size_t block_end = std::min(n_, i + kBlock);
            if (cut != kNoAngle && i > 0 && azimuth[i - 1] != kNoAngle && block_end - i == kBlock) {
                int block_sweep = 0;
                const bool irregular = Direction > 0
                                           ? blockSweep<+1>(azimuth + i, kBlock, cut, block_sweep)
                                           : blockSweep<-1>(azimuth + i, kBlock, cut, block_sweep);
                if (!irregular) {
                    sweep += block_sweep;
                    previous = azimuth[block_end - 1];
                    previous_offset = offsetOf(previous);
                    i = block_end;
                    continue;
                }
            }
            for (; i < block_end; ++i) {
                const int a = azimuth[i];
                if (a == kNoAngle) continue;
                if (cut == kNoAngle) cut = previous = a;
                const int offset = offsetOf(a);
                if (previous_offset - offset > kHalfTurn && sweep > kMinRingSweep) {
                    if (rings == max_rings) return max_rings + 1;
                    ring_start[rings++] = i;
                    if (ring_found(rings - 2, i)) return kOutOfOrder;
                    sweep = 0;
                } else {
                    sweep += Direction * angleDifference(a, previous);
                }
                previous_offset = offset;
                previous = a;
            }
        }
        return rings;
    }

    // +1 when the azimuth mostly increases from point to point, -1 when it decreases, 0 when no
    // point has an azimuth. Counts the steps' signs, not their sizes: the jumps between sparse
    // rings (ouster128 sample) outweigh many small steps. The first points are enough.
    int sweepDirection(const int16_t* azimuth) const {
        constexpr int kStepsLookedAt = 1000;
        int increasing = 0, decreasing = 0, previous = kNoAngle;
        for (std::size_t i = 0; i < n_ && increasing + decreasing < kStepsLookedAt; ++i) {
            if (azimuth[i] == kNoAngle) continue;
            if (previous != kNoAngle) {
                const int step = angleDifference(azimuth[i], previous);
                increasing += step > 0;
                decreasing += step < 0;
            }
            previous = azimuth[i];
        }
        if (previous == kNoAngle) return 0;
        return decreasing > increasing ? -1 : 1;
    }

    const PointCloud& cloud_;
    const std::vector<uint8_t>& valid_;
    const Params& params_;
    std::vector<int16_t>& row_;
    const std::size_t n_;
};

}  // namespace

const char* toString(RingSource source) {
    return nameOf(kRingSourceNames, source);
}

std::vector<double> elevationTableDeg(const Params& params) {
    std::vector<double> table;
    fillElevationTableDeg(params, table);
    return table;
}

void RangeImage::reserve(std::size_t points) {
    detail::prefault(row_, points), detail::prefault(col_, points);
    detail::prefault(elevation_, points);
}

void RangeImage::build(const PointCloud& cloud, const std::vector<uint8_t>& valid,
                       const Params& params) {
    const std::size_t n = cloud.size();
    if (cloud.y.size() != n || cloud.z.size() != n || valid.size() != n) {
        throw std::invalid_argument("RangeImage::build: x, y, z and valid differ in size");
    }
    if (params.num_rings < 1 || params.num_rings > kMaxRings) {
        throw ConfigError("num_rings = " + std::to_string(params.num_rings) + " is outside [1, " +
                          std::to_string(kMaxRings) + "]");
    }
    if (params.num_columns < 1) {
        throw ConfigError("num_columns = " + std::to_string(params.num_columns) + " is < 1");
    }
    const std::string& source = params.ring_source;
    const bool is_auto = source == "auto";
    if (!is_auto && source != "field" && source != "scan_order" && source != "table") {
        throw ConfigError("ring_source = '" + source +
                          "' is not one of auto|field|scan_order|table");
    }

    // Pass 1, vectorised: the final columns, and the quantised azimuths for the scan-order walk
    // (in row_ until the rows replace them). When the rows will likely come from the elevation
    // table (it is the source asked for, or gave the last frame's rows), the same pass also
    // takes the quantised elevations (the table's values, computed once per point either way).
    row_.resize(n);
    col_.resize(n);
    cols_ = params.num_columns;
    const bool elevations_first =
        source == "table" || (is_auto && source_ == RingSource::Table && !cloud.hasRing());
    if (elevations_first) {
        elevation_.resize(n);
        azimuthsColumnsAndElevations(cloud.x.data(), cloud.y.data(), cloud.z.data(), valid.data(),
                                     n, cols_, tableOriginHeight(params), row_.data(), col_.data(),
                                     elevation_.data());
    } else {
        azimuthsAndColumns(cloud.x.data(), cloud.y.data(), valid.data(), n, cols_, row_.data(),
                           col_.data());
    }

    // Sweep start (header): the earliest valid point by time, else the first valid point.
    sweep_start_col_ = -1;
    std::size_t first_valid = n;
    if (cloud.hasTime()) {
        float earliest = std::numeric_limits<float>::infinity();
        for (std::size_t i = 0; i < n; ++i)
            if (valid[i] && cloud.time[i] < earliest) earliest = cloud.time[i], first_valid = i;
    } else {
        first_valid = static_cast<std::size_t>(
            std::find_if(valid.begin(), valid.end(), [](uint8_t v) { return v != 0; }) -
            valid.begin());
    }
    const int first_col = first_valid < n ? col_[first_valid] : -1;

    // A frame without a valid point (empty, or a sensor dropout) has no row to find: a source
    // given explicitly cannot be contradicted by it, so it is kept, not an error.
    if (first_valid == n && !is_auto && (source == "field" || source == "scan_order")) {
        source_ = source == "field" ? RingSource::Field : RingSource::ScanOrder;
        rows_ = params.num_rings;
        return;
    }
    RowAssigner rows(cloud, valid, params, row_);
    std::string why;
    if (is_auto || source == "field") {
        if (rows.fromField(is_auto ? nullptr : &why)) {
            source_ = RingSource::Field;
            rows_ = params.num_rings;
            sweep_start_col_ = first_col;
            return;
        }
        if (!is_auto) throw InputError("ring_source = field: " + why);
    }
    if (is_auto || source == "scan_order") {
        if (rows.fromScanOrder(is_auto, is_auto ? nullptr : &why)) {
            source_ = RingSource::ScanOrder;
            rows_ = params.num_rings;
            sweep_start_col_ = first_col;
            return;
        }
        if (!is_auto) throw InputError("ring_source = scan_order: " + why);
    }
    // A named table fixes the number of rows, whatever num_rings says.
    fillElevationTableDeg(params, table_deg_);
    rows.fromTable(table_deg_, table_mid_, table_mids_quantised_, row_of_elevation_,
                   elevations_first ? elevation_.data() : nullptr);
    source_ = RingSource::Table;
    rows_ = static_cast<int>(table_deg_.size());
    // Storage order alone does not say where the sweep began: only the time field does.
    if (cloud.hasTime()) sweep_start_col_ = first_col;
}

}  // namespace travel
