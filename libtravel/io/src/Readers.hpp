// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Internal to travel_io: the record decoder shared by the .bin, PCD and PLY readers, the
// format-specific readers and the LZF codec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"
#include "travel/Text.hpp"  // quotedExcerpt: file contents quoted in messages

namespace travel::io_detail {

/// A stored value's type (PCD TYPE+SIZE, PLY property type).
enum class ValueType : uint8_t { I8, U8, I16, U16, I32, U32, F32, F64 };
std::size_t sizeOf(ValueType type);
bool isInteger(ValueType type);

/// Where a decoded value goes; Skip for fields the cloud has no place for.
enum class Target : uint8_t { X, Y, Z, Intensity, Ring, Time, Skip };
constexpr int kTargets = 6;

/// One field of a record: `count` values of `type` (or, for a PLY list, a `count_type` length
/// followed by that many values). The first value goes to `target`, times `scale`.
struct Field {
    std::string name;
    Target target = Target::Skip;
    ValueType type = ValueType::F32;
    unsigned count = 1;
    bool list = false;
    ValueType count_type = ValueType::U8;
    double scale = 1.0;
};

/// The target of a field named `name` (x, y, z, intensity, ring, time or t); Skip otherwise.
/// An integer-typed "t" is in nanoseconds (Ouster), so its scale is 1e-9.
Target targetOf(const std::string& name, ValueType type, double& scale);

/// Values in file order: whitespace-separated ASCII numbers, one record per line, or packed
/// little-endian binary. Errors name the file, the record and (ASCII) the line.
class ValueSource {
  public:
    ValueSource(const std::string& path, bool ascii, const unsigned char* begin,
                const unsigned char* end, std::size_t first_line)
        : path_(path), ascii_(ascii), p_(begin), end_(end), line_(first_line) {}

    void beginRecord(std::size_t index, std::size_t total, const char* what);
    double next(ValueType type);
    void endRecord();
    /// Throws unless only whitespace (ASCII) or nothing (binary) is left.
    void expectEnd(std::size_t total, const char* what);
    std::size_t bytesLeft() const { return static_cast<std::size_t>(end_ - p_); }
    bool ascii() const { return ascii_; }
    /// Binary only: the next `size` bytes (throws when fewer are left), for bulk decoding.
    const unsigned char* take(std::size_t size, std::size_t total, const char* what);
    /// Throws InputError: "path:line: message" (ASCII) or "path: message" (binary).
    [[noreturn]] void fail(const std::string& message) const;

  private:
    void skipBlanks();  // spaces, tabs and carriage returns, not newlines

    const std::string& path_;
    bool ascii_;
    const unsigned char* p_;
    const unsigned char* end_;
    std::size_t line_;
    std::size_t record_ = 0, total_ = 0;
    const char* what_ = "point";
};

/// Reads one record of `fields`; values[t] receives the value for Target t (others untouched).
void readRecord(const std::vector<Field>& fields, ValueSource& src, double values[kTargets]);

/// Decodes `n` records into `cloud` (x, y, z, intensity always; ring and time when a field
/// targets them). `what` names a record in messages ("point", "vertex").
void decodeRecords(const std::string& path, const std::vector<Field>& fields, std::size_t n,
                   ValueSource& src, PointCloud& cloud, const char* what);

/// Throws InputError when `n` records of `fields` cannot fit in `bytes_left` bytes (a header
/// announcing more points than the file can hold; also keeps a corrupt count from allocating).
void checkRecordsFit(const std::string& path, const std::vector<Field>& fields, std::size_t n,
                     bool ascii, std::size_t bytes_left, const char* what);

void readPcd(const std::string& path, const std::vector<unsigned char>& bytes, PointCloud& cloud);
void readPly(const std::string& path, const std::vector<unsigned char>& bytes, PointCloud& cloud);

/// LZF (liblzf's format, as in PCD binary_compressed). Returns false unless `in` decodes to
/// exactly `out_size` bytes.
bool lzfDecompress(const unsigned char* in, std::size_t in_size, unsigned char* out,
                   std::size_t out_size);
/// A greedy LZF encoder (valid input for any LZF decoder, not maximally compact).
std::vector<unsigned char> lzfCompress(const unsigned char* in, std::size_t size);

/// "path: message" as an InputError.
[[noreturn]] void fail(const std::string& path, const std::string& message);
/// "path:line: message" as an InputError.
[[noreturn]] void failAt(const std::string& path, std::size_t line, const std::string& message);

/// "points", "vertices", "faces": `what` in the plural, for messages.
std::string plural(const std::string& what);

}  // namespace travel::io_detail
