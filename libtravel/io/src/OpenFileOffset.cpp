// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/OpenFileOffset.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace travel::io {

OpenFileOffset::OpenFileOffset(const std::string& path) {
    std::error_code ec;
    const fs::path target = fs::weakly_canonical(path, ec);
    const auto size = fs::file_size(path, ec);
    if (ec || size == 0) return;
    size_ = double(size);
    // The newest descriptor on the file: the library's, opened last.
    for (const auto& entry : fs::directory_iterator("/proc/self/fd", ec)) {
        std::error_code link_ec;
        if (fs::read_symlink(entry.path(), link_ec) != target || link_ec) continue;
        fd_ = std::max(fd_, std::atoi(entry.path().filename().c_str()));
    }
}

double OpenFileOffset::fraction() const {
    if (fd_ < 0) return -1.0;
    std::ifstream info("/proc/self/fdinfo/" + std::to_string(fd_));
    std::string key;
    long long position = -1;
    while (info >> key && key != "pos:") info.ignore(1 << 16, '\n');
    if (!(info >> position) || position < 0) return -1.0;
    return std::min(1.0, double(position) / size_);
}

}  // namespace travel::io
