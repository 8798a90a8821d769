// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/RawlogReader.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>

#include "travel/Errors.hpp"
#include "travel/io/OpenFileOffset.hpp"
#include "travel_mrpt/MrptMessage.hpp"

namespace fs = std::filesystem;

namespace travel_mrpt {

struct RawlogReader::Stream {
    mrpt::io::CFileGZInputStream file;
    mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream> archive{file};
    std::optional<travel::io::OpenFileOffset> gzip_offset;
};

RawlogReader::RawlogReader(const std::string& path) : path_(path), stream_(new Stream) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw travel::InputError(path + ": no such file");
    if (fs::is_directory(path, ec))
        throw travel::InputError(path + ": is a directory, not a rawlog");
    if (!stream_->file.open(path)) throw travel::InputError(path + ": cannot open for reading");
    char magic[2] = {};
    std::ifstream(path, std::ios::binary).read(magic, 2);
    if (magic[0] == '\x1f' && magic[1] == '\x8b') stream_->gzip_offset.emplace(path);
    // Externally stored observations (images, point clouds, depth) are loaded from the rawlog's
    // "<name>_Images" folder, as in MRPT's own tools (a process-wide MRPT setting). MRPT 2.5.8's
    // fallback when no such folder exists lacks a '/' ("<dir>Images"): name the usual one.
    std::string images = mrpt::obs::CRawlog::detectImagesDirectory(path);
    if (!fs::is_directory(images, ec))
        images =
            (fs::path(path).parent_path() / (fs::path(path).stem().string() + "_Images")).string();
    mrpt::img::CImage::setImagesPathBase(images);
}

double RawlogReader::fractionRead() const {
    // MRPT 2.5.8: a gzip stream's getPosition() is the uncompressed offset (zlib's gztell),
    // its getTotalBytesCount() the compressed size: the descriptor's offset instead.
    if (stream_->gzip_offset) return stream_->gzip_offset->fraction();
    const auto size = stream_->file.getTotalBytesCount();
    return size ? double(stream_->file.getPosition()) / double(size) : -1.0;
}

bool RawlogReader::wholeFileRead() const {
    if (stream_->gzip_offset) return stream_->gzip_offset->fraction() >= 1.0;
    const auto size = stream_->file.getTotalBytesCount();
    return size > 0 && stream_->file.getPosition() >= size;
}

RawlogReader::~RawlogReader() = default;

std::shared_ptr<mrpt::serialization::CSerializable> RawlogReader::next() {
    const std::string record = where(path_, index_);
    const uint64_t start = stream_->file.getPosition();
    try {
        auto object = stream_->archive.ReadObject();
        if (!object) throw std::runtime_error("null object");
        ++index_;
        return object;
    } catch (const mrpt::serialization::CExceptionEOF&) {
        // End of file exactly at a record boundary is the normal end; anywhere else the record
        // was cut.
        if (stream_->file.getPosition() != start)
            throw travel::InputError(record + ": truncated (end of file inside the record)");
    } catch (const std::bad_alloc&) {
        throw travel::InputError(record +
                                 ": corrupt record (it announces more data than --max-memory "
                                 "allows); is it a rawlog?");
    } catch (const std::exception& e) {
        const std::string what = mrptMessage(e.what());
        // MRPT reports a short read inside an object as a generic error, not CExceptionEOF; an
        // object that reads its own bytes (CObservationTravelLabels) fails on a short read with
        // its own message, after the whole file was read.
        if (what.find("EOF") != std::string::npos ||
            what.find("Cannot read object class name") != std::string::npos || wholeFileRead())
            throw travel::InputError(record + ": truncated (end of file inside the record)");
        throw travel::InputError(
            record + (index_ == 0 ? ": cannot read (is it an MRPT rawlog?): " : ": cannot read: ") +
            what);
    }
    if (index_ == 0) {
        std::error_code ec;
        throw travel::InputError(path_ + (fs::file_size(path_, ec) == 0
                                              ? ": empty file, not a rawlog"
                                              : ": no record could be read (not an MRPT rawlog, "
                                                "or a corrupt gzip stream)"));
    }
    return nullptr;
}

}  // namespace travel_mrpt
