// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// How far this process has read into a file that a library opened itself and gives no byte
// offset for (zlib's gzip stream: MRPT's CFileGZInputStream reports the uncompressed offset;
// libpcap's capture behind CVelodyneScanner: none). The kernel knows the offset of the
// descriptor: /proc/self/fdinfo (Linux). Used for the progress line's fraction and ETA.
#pragma once

#include <string>

namespace travel::io {

class OpenFileOffset {
  public:
    /// Finds the descriptor open on `path`: construct it after the library opened the file.
    explicit OpenFileOffset(const std::string& path);

    /// Bytes read over the file size, in [0, 1]; -1 when unknown (no /proc, no descriptor on
    /// `path`, an empty file).
    double fraction() const;

  private:
    int fd_ = -1;
    double size_ = 0;
};

}  // namespace travel::io
