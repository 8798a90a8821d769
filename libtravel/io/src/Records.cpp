// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

#include "Readers.hpp"
#include "travel/EnumNames.hpp"
#include "travel/Errors.hpp"
#include "travel/io/BinaryFile.hpp"

namespace travel::io_detail {
namespace {

// The PCD / PLY field names that have a place in a PointCloud ("t" is handled apart: its unit
// depends on the type).
constexpr EnumName<Target> kTargetNames[] = {
    {Target::X, "x"},       {Target::Y, "y"},
    {Target::Z, "z"},       {Target::Intensity, "intensity"},
    {Target::Ring, "ring"}, {Target::Time, "time"}};

}  // namespace

void fail(const std::string& path, const std::string& message) {
    throw InputError(path + ": " + message);
}

void failAt(const std::string& path, std::size_t line, const std::string& message) {
    throw InputError(path + ":" + std::to_string(line) + ": " + message);
}

std::size_t sizeOf(ValueType type) {
    switch (type) {
        case ValueType::I8:
        case ValueType::U8:
            return 1;
        case ValueType::I16:
        case ValueType::U16:
            return 2;
        case ValueType::I32:
        case ValueType::U32:
        case ValueType::F32:
            return 4;
        case ValueType::F64:
            return 8;
    }
    return 1;
}

bool isInteger(ValueType type) {
    return type != ValueType::F32 && type != ValueType::F64;
}

Target targetOf(const std::string& name, ValueType type, double& scale) {
    scale = 1.0;
    if (const auto target = findByName(kTargetNames, name)) return *target;
    if (name == "t") {
        if (isInteger(type)) scale = 1e-9;  // Ouster: uint32 ns since the start of the scan
        return Target::Time;
    }
    return Target::Skip;
}

std::string plural(const std::string& what) {
    return what == "vertex" ? "vertices" : what + "s";
}

void ValueSource::fail(const std::string& message) const {
    if (ascii_) failAt(path_, line_, message);
    io_detail::fail(path_, message);
}

void ValueSource::skipBlanks() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r')) ++p_;
}

void ValueSource::beginRecord(std::size_t index, std::size_t total, const char* what) {
    record_ = index, total_ = total, what_ = what;
    if (!ascii_) return;
    // Blank lines between records are allowed.
    for (;;) {
        skipBlanks();
        if (p_ < end_ && *p_ == '\n') {
            ++p_, ++line_;
            continue;
        }
        break;
    }
    if (p_ == end_) {
        io_detail::fail(path_, "data ends after " + std::to_string(index) + " of " +
                                   std::to_string(total) + " " + plural(what));
    }
}

double ValueSource::next(ValueType type) {
    if (!ascii_) {
        const std::size_t size = sizeOf(type);
        if (bytesLeft() < size) {
            fail("data ends inside " + std::string(what_) + " " + std::to_string(record_) + " of " +
                 std::to_string(total_));
        }
        const unsigned char* b = p_;
        p_ += size;
        switch (type) {
            case ValueType::I8:
                return static_cast<int8_t>(*b);
            case ValueType::U8:
                return *b;
            case ValueType::I16:
                return le::load<int16_t>(b);
            case ValueType::U16:
                return le::load<uint16_t>(b);
            case ValueType::I32:
                return le::load<int32_t>(b);
            case ValueType::U32:
                return le::load<uint32_t>(b);
            case ValueType::F32:
                return le::load<float>(b);
            case ValueType::F64:
                return le::load<double>(b);
        }
        return 0.0;
    }
    skipBlanks();
    if (p_ == end_ || *p_ == '\n') {
        fail(std::string(what_) + " " + std::to_string(record_) +
             " has fewer values than the header describes");
    }
    char token[64];
    std::size_t len = 0;
    while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') {
        if (len + 1 < sizeof(token)) token[len] = static_cast<char>(*p_);
        ++len, ++p_;
    }
    if (len + 1 >= sizeof(token)) fail("a value of " + std::to_string(len) + " characters");
    token[len] = '\0';
    char* parsed_end = nullptr;
    const double v = std::strtod(token, &parsed_end);
    if (parsed_end != token + len) fail(quotedExcerpt(token, 24) + " is not a number");
    return v;
}

const unsigned char* ValueSource::take(std::size_t size, std::size_t total, const char* what) {
    if (bytesLeft() < size) {
        io_detail::fail(path_, "data ends inside " + std::string(what) + " " +
                                   std::to_string(bytesLeft() / (size / total)) + " of " +
                                   std::to_string(total));
    }
    const unsigned char* bytes = p_;
    p_ += size;
    return bytes;
}

void ValueSource::endRecord() {
    if (!ascii_) return;
    skipBlanks();
    if (p_ < end_ && *p_ != '\n') {
        fail(std::string(what_) + " " + std::to_string(record_) +
             " has more values than the header describes");
    }
}

void ValueSource::expectEnd(std::size_t total, const char* what) {
    if (ascii_) {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
            if (*p_ == '\n') ++line_;
            ++p_;
        }
        if (p_ != end_)
            fail("more data after the last of " + std::to_string(total) + " " + plural(what));
    } else if (p_ != end_) {
        io_detail::fail(path_, std::to_string(bytesLeft()) + " bytes after the last of " +
                                   std::to_string(total) + " " + plural(what));
    }
}

void readRecord(const std::vector<Field>& fields, ValueSource& src, double values[kTargets]) {
    for (const Field& f : fields) {
        std::size_t count = f.count;
        if (f.list) {
            const double n = src.next(f.count_type);
            if (!(n >= 0.0 && n <= static_cast<double>(src.bytesLeft())) || n != std::floor(n))
                src.fail("list '" + f.name + "' has length " + std::to_string(n));
            count = static_cast<std::size_t>(n);
        }
        for (std::size_t k = 0; k < count; ++k) {
            const double v = src.next(f.type);
            if (k == 0 && f.target != Target::Skip)
                values[static_cast<int>(f.target)] = v * f.scale;
        }
    }
}

void checkRecordsFit(const std::string& path, const std::vector<Field>& fields, std::size_t n,
                     bool ascii, std::size_t bytes_left, const char* what) {
    // The least a record takes: ASCII one character per value (plus separators), binary the
    // packed size of its fixed fields (a list takes at least its length).
    std::size_t least = 0;
    for (const Field& f : fields) {
        if (ascii)
            least += f.list ? 2 : 2 * f.count;
        else
            least += f.list ? sizeOf(f.count_type) : sizeOf(f.type) * f.count;
    }
    if (ascii && least > 0) --least;
    if (least == 0) least = 1;
    if (n > bytes_left / least) {
        fail(path, "the header announces " + std::to_string(n) + " " + plural(what) + " but only " +
                       std::to_string(bytes_left) + " bytes of data follow");
    }
}

namespace {

// The float the general path below gives for a float32 value: it goes through a double, which
// turns a signalling NaN quiet (sets the quiet bit, keeps the payload); every other value,
// denormals and -0 included, comes back unchanged.
constexpr uint32_t kQuietNanBit = 0x00400000u;

inline float throughDouble(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    if (v != v) bits |= kQuietNanBit;
    std::memcpy(&v, &bits, sizeof bits);
    return v;
}

// KITTI's record layout: float32 x, y, z, intensity (16 bytes), each taken as it is.
bool isXyziFloat32(const std::vector<Field>& fields) {
    constexpr Target kXyzi[4] = {Target::X, Target::Y, Target::Z, Target::Intensity};
    if (fields.size() != 4) return false;
    for (std::size_t k = 0; k < 4; ++k) {
        const Field& f = fields[k];
        if (f.target != kXyzi[k] || f.type != ValueType::F32 || f.count != 1 || f.list ||
            f.scale != 1.0)
            return false;
    }
    return true;
}

// Splits n packed little-endian x, y, z, intensity float32 records into the four arrays, as the
// general path does (throughDouble()), four records at a time: four loads, a 4x4 transpose and
// four stores, where the general path converts every value through a double one by one.
void splitXyzi(const unsigned char* packed, std::size_t n, float* x, float* y, float* z,
               float* intensity) {
    std::size_t i = 0;
#if defined(__SSE2__)
    if constexpr (!le::kHostIsBigEndian) {
        const __m128 quiet = _mm_castsi128_ps(_mm_set1_epi32(static_cast<int>(kQuietNanBit)));
        auto quieted = [&](__m128 v) {
            return _mm_or_ps(v, _mm_and_ps(_mm_cmpunord_ps(v, v), quiet));
        };
        for (; i + 4 <= n; i += 4) {
            const float* r = reinterpret_cast<const float*>(packed + 16 * i);
            __m128 r0 = _mm_loadu_ps(r), r1 = _mm_loadu_ps(r + 4), r2 = _mm_loadu_ps(r + 8),
                   r3 = _mm_loadu_ps(r + 12);
            _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
            _mm_storeu_ps(x + i, quieted(r0));
            _mm_storeu_ps(y + i, quieted(r1));
            _mm_storeu_ps(z + i, quieted(r2));
            _mm_storeu_ps(intensity + i, quieted(r3));
        }
    }
#endif
    for (; i < n; ++i) {
        const unsigned char* r = packed + 16 * i;
        x[i] = throughDouble(le::load<float>(r));
        y[i] = throughDouble(le::load<float>(r + 4));
        z[i] = throughDouble(le::load<float>(r + 8));
        intensity[i] = throughDouble(le::load<float>(r + 12));
    }
}

}  // namespace

void decodeRecords(const std::string& path, const std::vector<Field>& fields, std::size_t n,
                   ValueSource& src, PointCloud& cloud, const char* what) {
    bool has[kTargets] = {};
    for (const Field& f : fields)
        if (f.target != Target::Skip) has[static_cast<int>(f.target)] = true;
    cloud.x.resize(n), cloud.y.resize(n), cloud.z.resize(n), cloud.intensity.resize(n);
    if (has[static_cast<int>(Target::Ring)])
        cloud.ring.resize(n);
    else
        cloud.ring.clear();
    if (has[static_cast<int>(Target::Time)])
        cloud.time.resize(n);
    else
        cloud.time.clear();
    // KITTI's layout (binary float32 x, y, z, intensity): split as it is, no per-value work.
    if (!src.ascii() && isXyziFloat32(fields)) {
        if (n > 0)
            splitXyzi(src.take(n * 16, n, what), n, cloud.x.data(), cloud.y.data(), cloud.z.data(),
                      cloud.intensity.data());
        return;
    }
    // Other packed float32 layouts (nuScenes, PCDs with more fields): no per-value dispatch
    // (about 4x faster than the general path below).
    bool all_f32 = !src.ascii();
    for (const Field& f : fields)
        all_f32 = all_f32 && f.type == ValueType::F32 && f.count == 1 && !f.list;
    const std::size_t row = 4 * fields.size();
    const unsigned char* packed = all_f32 && n > 0 ? src.take(n * row, n, what) : nullptr;
    double v[kTargets];
    for (std::size_t i = 0; i < n; ++i) {
        v[static_cast<int>(Target::Intensity)] = 0.0;
        if (packed) {
            const unsigned char* r = packed + i * row;
            for (std::size_t k = 0; k < fields.size(); ++k, r += 4)
                if (fields[k].target != Target::Skip)
                    v[static_cast<int>(fields[k].target)] = le::load<float>(r) * fields[k].scale;
        } else {
            src.beginRecord(i, n, what);
            readRecord(fields, src, v);
            src.endRecord();
        }
        cloud.x[i] = static_cast<float>(v[static_cast<int>(Target::X)]);
        cloud.y[i] = static_cast<float>(v[static_cast<int>(Target::Y)]);
        cloud.z[i] = static_cast<float>(v[static_cast<int>(Target::Z)]);
        cloud.intensity[i] = static_cast<float>(v[static_cast<int>(Target::Intensity)]);
        if (has[static_cast<int>(Target::Ring)]) {
            const double ring = v[static_cast<int>(Target::Ring)];
            if (!(ring >= 0.0 && ring <= 65535.0) || ring != std::floor(ring)) {
                fail(path, std::string(what) + " " + std::to_string(i) + " has ring " +
                               std::to_string(ring) + ", expected an integer in [0, 65535]");
            }
            cloud.ring[i] = static_cast<uint16_t>(ring);
        }
        if (has[static_cast<int>(Target::Time)])
            cloud.time[i] = static_cast<float>(v[static_cast<int>(Target::Time)]);
    }
}

}  // namespace travel::io_detail
