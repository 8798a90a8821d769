// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Whole-file byte I/O and little-endian loads/stores, shared by every reader and writer of
// binary files (scans here, SemanticKITTI labels in travel_eval). All the formats are
// little-endian; on a big-endian host the values are byte-swapped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace travel {

/// Reads the whole file into `bytes` (whose capacity is reused) with one fread. Throws
/// InputError naming the file when it is missing, a directory or unreadable.
void readFileBytes(const std::string& path, std::vector<unsigned char>& bytes);

/// Writes `size` bytes to `path` (created or truncated). Throws std::runtime_error naming the
/// file when it cannot be written (a full disk or a file size limit included: the close is
/// checked), after removing what was written: no half a file is left under `path`.
void writeFileBytes(const std::string& path, const unsigned char* data, std::size_t size);
/// The same for a text (or any byte string).
void writeFileBytes(const std::string& path, const std::string& bytes);

/// True when the file at `path` ends with a gzip trailer (CRC32, ISIZE) whose ISIZE is
/// `uncompressed_bytes` modulo 2^32: a gzip file written to its end. A write cut short (a full
/// disk when the compressor flushed its last bytes at close) ends elsewhere.
bool gzipEndsWithSize(const std::string& path, uint64_t uncompressed_bytes);

/// Removes `path` when it is a regular file, not a symlink (its target stays), a device or a
/// folder: what a failed write in place leaves under an output's name. Never throws.
void removeCutFile(const std::string& path) noexcept;

/// The last step of a write through a temporary `part` file (written beside `path`, so that a
/// failed or interrupted write never leaves half a file under the final name): moves `part` to
/// `path` (one folder: the move is atomic). On failure removes `part` and throws
/// std::runtime_error naming `path` and the reason: no orphaned part file is left behind.
void movePartInPlace(const std::string& part, const std::string& path);

/// "<path>: cannot write (<reason>)": how every writer names a file it could not write.
std::string cannotWriteMessage(const std::string& path, const std::string& reason);

/// A file written under a temporary name beside its final one, `path + ".part"`, and moved in
/// place by commit() (movePartInPlace) once complete. Destroyed before commit() (an error, an
/// exception, an interrupt that unwinds), it removes the part file: a failed write leaves
/// neither half a file under `path` nor a part file, and a previous file under `path` stays as
/// it was. Declare it before the stream that writes part(), so that the stream is closed when
/// the part file goes.
/// The constructor refuses (std::runtime_error "<path>: cannot write (...)") a `path` that is
/// a symbolic link or a device, FIFO or socket: the move would replace the link or the device.
class PartFile {
  public:
    /// Where the part file is: `path + ".part"`, or ".part" before the extension for a writer
    /// that tells the format by it (OpenCV's pictures): x.png -> x.part.png.
    enum class Name { Appended, BeforeExtension };

    explicit PartFile(std::string path, Name name = Name::Appended);
    ~PartFile();
    PartFile(const PartFile&) = delete;
    PartFile& operator=(const PartFile&) = delete;

    const std::string& path() const { return path_; }
    const std::string& part() const { return part_; }
    /// The part file of `path` (what part() is), for checks before a PartFile is made: a part
    /// file that is an input would be emptied when opened.
    static std::string partOf(const std::string& path, Name name = Name::Appended);
    /// Moves part() to path(); throws std::runtime_error naming path() (the part file removed).
    void commit();

  private:
    std::string path_, part_;
    bool done_ = false;
};

/// Writes the file `path` through a PartFile: `write` fills a stream on the part file, which is
/// then closed and moved in place. A failure (the open, a write, a full disk or a file size
/// limit at the close, the move) throws std::runtime_error "<path>: cannot write (<reason>)";
/// an exception from `write` goes on as it is. Either way the part file is removed and a
/// previous file under `path` stays as it was.
void writeThroughPartFile(const std::string& path, const std::function<void(std::ostream&)>& write);

namespace le {

#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__) && \
    __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostIsBigEndian = true;
#else
constexpr bool kHostIsBigEndian = false;
#endif

/// Little-endian bytes (any alignment) -> host value of type T (an arithmetic type).
template <class T>
inline T load(const unsigned char* bytes) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, bytes, sizeof(T));
    if constexpr (kHostIsBigEndian) {
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
}

/// Host value -> little-endian bytes (any alignment).
template <class T>
inline void store(T v, unsigned char* bytes) {
    std::memcpy(bytes, &v, sizeof(T));
    if constexpr (kHostIsBigEndian) {
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
            std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    }
}

}  // namespace le
}  // namespace travel
