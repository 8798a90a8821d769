// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A gzip file written through MRPT's archives (rawlogs, .travelmap, .gridmap.gz, .travelgrid)
// whose every failure is an error naming the file. MRPT's CFileGZOutputStream reports a failed
// write as "Cannot write bytes to stream!" (no file), and its close() ignores zlib's: the
// compressor's last bytes are written at close, so on a full disk the file was cut short
// without a word. close() here checks that the file ends with its gzip trailer.
//
//   travel::PartFile file(path);
//   travel_mrpt::GzFileOutput out(file.part(), path); // throws "<path>: cannot write ..."
//   mrpt::serialization::archiveFrom(out) << object;  // throws "<path>: cannot write ..."
//   out.close();                                      // throws when the file was cut short
//   file.commit();
#pragma once

#include <mrpt/io/CFileGZOutputStream.h>

#include <string>

namespace travel_mrpt {

class GzFileOutput : public mrpt::io::CStream {
  public:
    /// Opens (creates or truncates) `path`, compression level 1 as MRPT's default. Messages
    /// name `name` (the final name of a part file), `path` when empty. Throws
    /// std::runtime_error "<name>: cannot write (<reason>)" (as every other failure).
    explicit GzFileOutput(std::string path, std::string name = {});
    /// Closes without checking (an error path: declared after its travel::PartFile, the stream
    /// is closed before the part file is removed); call close() on success.
    ~GzFileOutput() override;

    /// Throws std::runtime_error "<name>: cannot write (<reason>)" on a short write.
    size_t Write(const void* buffer, size_t count) override;
    /// Flushes and closes; throws std::runtime_error "<name>: cannot write (...)" when the file
    /// does not end with the gzip trailer of the bytes written (a full disk ...).
    void close();

    const std::string& path() const { return path_; }
    /// Uncompressed bytes written so far (also after close()).
    uint64_t getPosition() const override { return written_; }
    uint64_t getTotalBytesCount() const override { return written_; }
    /// Write-only, forward-only: these throw std::logic_error.
    size_t Read(void* buffer, size_t count) override;
    uint64_t Seek(int64_t offset, CStream::TSeekOrigin origin = sFromBeginning) override;

  private:
    std::string path_, name_;
    mrpt::io::CFileGZOutputStream file_;
    uint64_t written_ = 0;
};

}  // namespace travel_mrpt
