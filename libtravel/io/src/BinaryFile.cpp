// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/BinaryFile.hpp"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <utility>

#include "travel/Errors.hpp"

namespace travel {

namespace {
struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;
}  // namespace

void readFileBytes(const std::string& path, std::vector<unsigned char>& bytes) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a file");
    FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file) throw InputError(path + ": cannot open: " + std::strerror(errno));
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot get the size: " + ec.message());
    bytes.resize(static_cast<std::size_t>(size));
    if (size > 0 && std::fread(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) {
        throw InputError(path + ": cannot read: " +
                         (std::ferror(file.get()) ? std::strerror(errno) : "file shrank"));
    }
}

void writeFileBytes(const std::string& path, const unsigned char* data, std::size_t size) {
    FilePtr file(std::fopen(path.c_str(), "wb"));
    if (!file) throw std::runtime_error(cannotWriteMessage(path, std::strerror(errno)));
    const bool written = size == 0 || std::fwrite(data, 1, size, file.get()) == size;
    // fclose flushes: a full disk may only show up here.
    const bool closed = std::fclose(file.release()) == 0;
    if (!written || !closed) {
        const std::string reason = std::strerror(errno);
        removeCutFile(path);  // no half a file under the final name
        throw std::runtime_error(cannotWriteMessage(path, reason));
    }
}

void writeFileBytes(const std::string& path, const std::string& bytes) {
    writeFileBytes(path, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

void removeCutFile(const std::string& path) noexcept {
    std::error_code ec;
    if (std::filesystem::symlink_status(path, ec).type() == std::filesystem::file_type::regular)
        std::filesystem::remove(path, ec);
}

std::string cannotWriteMessage(const std::string& path, const std::string& reason) {
    return path + ": cannot write (" + reason + ")";
}

void movePartInPlace(const std::string& part, const std::string& path) {
    std::error_code ec;
    std::filesystem::rename(part, path, ec);
    if (!ec) return;
    std::error_code ignored;
    std::filesystem::remove(part, ignored);
    throw std::runtime_error(
        cannotWriteMessage(path, "moving " + part + " there: " + ec.message()));
}

bool gzipEndsWithSize(const std::string& path, uint64_t uncompressed_bytes) {
    const FilePtr file(std::fopen(path.c_str(), "rb"));
    unsigned char trailer[8];
    // The smallest gzip file: a 10-byte header, an empty deflate block (2), the trailer (8).
    if (!file || std::fseek(file.get(), 0, SEEK_END) != 0 || std::ftell(file.get()) < 20 ||
        std::fseek(file.get(), -8, SEEK_END) != 0 ||
        std::fread(trailer, 1, sizeof(trailer), file.get()) != sizeof(trailer))
        return false;
    return le::load<uint32_t>(trailer + 4) == uint32_t(uncompressed_bytes);
}

PartFile::PartFile(std::string path, Name name)
    : path_(std::move(path)), part_(partOf(path_, name)) {
    // Moving a file over a device would replace it (as root: /dev/null for the whole machine),
    // and over a symbolic link would replace the link, not what it points at (following it
    // here would bypass the kernel's protection of links in shared folders): both refused.
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status link = fs::symlink_status(path_, ec);
    if (fs::is_symlink(link))
        throw std::runtime_error(
            cannotWriteMessage(path_, "a symbolic link; give the name of the file it points at"));
    if (fs::exists(link) && !fs::is_regular_file(link) && !fs::is_directory(link))
        throw std::runtime_error(
            cannotWriteMessage(path_, "not a regular file (a device, FIFO or socket)"));
}

std::string PartFile::partOf(const std::string& path, Name name) {
    if (name == Name::Appended) return path + ".part";
    const std::string extension = std::filesystem::path(path).extension().string();
    return path.substr(0, path.size() - extension.size()) + ".part" + extension;
}

PartFile::~PartFile() {
    if (done_) return;
    removeCutFile(part_);  // a regular file only: never a folder or a link named so
}

void PartFile::commit() {
    done_ = true;  // movePartInPlace removes the part file itself when the move fails
    movePartInPlace(part_, path_);
}

void writeThroughPartFile(const std::string& path,
                          const std::function<void(std::ostream&)>& write) {
    PartFile file(path);
    {
        errno = 0;
        std::ofstream out(file.part(), std::ios::binary);
        if (out) write(out);
        if (out) out.close();  // flushes: a full disk may only show up here
        if (!out)
            throw std::runtime_error(
                cannotWriteMessage(path, errno ? std::strerror(errno) : "write error"));
    }
    file.commit();
}

}  // namespace travel
