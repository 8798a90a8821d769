// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/GzFileOutput.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "travel/io/BinaryFile.hpp"

namespace travel_mrpt {

GzFileOutput::GzFileOutput(std::string path, std::string name)
    : path_(std::move(path)), name_(name.empty() ? path_ : std::move(name)) {
    errno = 0;
    if (!file_.open(path_))
        throw std::runtime_error(
            travel::cannotWriteMessage(name_, errno ? std::strerror(errno) : "unknown reason"));
}

GzFileOutput::~GzFileOutput() = default;  // CFileGZOutputStream closes itself

size_t GzFileOutput::Write(const void* buffer, size_t count) {
    errno = 0;
    const size_t written = file_.Write(buffer, count);
    if (written != count)
        throw std::runtime_error(
            travel::cannotWriteMessage(name_, errno ? std::strerror(errno) : "short write"));
    written_ += written;
    return written;
}

void GzFileOutput::close() {
    if (!file_.fileOpenCorrectly()) return;
    file_.close();
    if (!travel::gzipEndsWithSize(path_, written_))
        throw std::runtime_error(
            travel::cannotWriteMessage(name_, "the file ends before its gzip trailer: disk full?"));
}

size_t GzFileOutput::Read(void*, size_t) {
    throw std::logic_error(name_ + ": GzFileOutput is write-only");
}

uint64_t GzFileOutput::Seek(int64_t, CStream::TSeekOrigin) {
    throw std::logic_error(name_ + ": GzFileOutput cannot seek");
}

}  // namespace travel_mrpt
