// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/BirdsEyeView.hpp"

#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "travel/io/BinaryFile.hpp"
#include "travel_mrpt/MrptMessage.hpp"

namespace travel_mrpt {

using mrpt::img::CImage;
using mrpt::img::TColor;

void toImage(const travel::viz::Raster& raster, CImage& out) {
    out.resize(raster.width, raster.height, mrpt::img::CH_RGB);
    // CImage stores BGR (OpenCV order).
    for (int v = 0; v < raster.height; ++v) {
        for (int u = 0; u < raster.width; ++u) {
            const travel::viz::Rgb c = raster.at(u, v);
            uint8_t* q = out.ptr<uint8_t>(static_cast<unsigned>(u), static_cast<unsigned>(v));
            q[0] = c.b, q[1] = c.g, q[2] = c.r;
        }
    }
}

void toImage(const travel::viz::Picture& picture, CImage& out) {
    toImage(picture.raster, out);
    out.selectTextFont("9x15");
    for (const travel::viz::TextLabel& label : picture.text)
        out.textOut(label.x, label.y, label.text, TColor(0, 0, 0));
}

void renderBirdsEye(const travel::AlignedCloud& points,
                    const std::vector<travel::PointClass>& labels,
                    const std::vector<uint32_t>& cluster_id, const travel::TerrainModel* terrain,
                    const BirdsEyeOptions& opt, CImage& out) {
    toImage(travel::viz::renderBirdsEye(points, labels, cluster_id, terrain, opt), out);
}

void sideBySide(const CImage& a, const CImage& b, const std::string& title_a,
                const std::string& title_b, CImage& out) {
    const int gap = 6;
    const int band = title_a.empty() && title_b.empty() ? 0 : 26;
    const int wa = static_cast<int>(a.getWidth()), wb = static_cast<int>(b.getWidth());
    const int h = band + static_cast<int>(std::max(a.getHeight(), b.getHeight()));
    out.resize(wa + gap + wb, h, mrpt::img::CH_RGB);
    out.filledRectangle(0, 0, wa + gap + wb - 1, h - 1, TColor(255, 255, 255));
    out.filledRectangle(wa, 0, wa + gap - 1, h - 1, TColor(60, 60, 60));  // divider
    out.drawImage(0, band, a);
    out.drawImage(wa + gap, band, b);
    if (band) {
        out.selectTextFont("10x20");
        out.textOut(8, 3, title_a, TColor(0, 0, 0));
        out.textOut(wa + gap + 8, 3, title_b, TColor(0, 0, 0));
    }
}

namespace {

/// The extension of `path` in lower case.
std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

/// True when the file ends as its encoder ends a picture: PNG with the IEND chunk, JPEG with
/// the EOI marker. OpenCV does not check its close: a picture cut there (a full disk) is
/// written without an error.
bool endsAsAPicture(const std::string& path, bool png) {
    static const std::string png_end("\0\0\0\0IEND\xAE\x42\x60\x82", 12), jpeg_end("\xFF\xD9");
    const std::string& end = png ? png_end : jpeg_end;
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in || in.tellg() < std::streamoff(end.size())) return false;
    std::string tail(end.size(), '\0');
    in.seekg(-std::streamoff(end.size()), std::ios::end);
    return in.read(tail.data(), std::streamsize(tail.size())) && tail == end;
}

}  // namespace

void requirePictureName(const std::string& path) {
    // OpenCV picks the format by the extension and throws (or fails) on any other name.
    const std::string extension = lowerExtension(path);
    if (extension != ".png" && extension != ".jpg" && extension != ".jpeg")
        throw std::runtime_error(path +
                                 ": not a picture name (the format is told by the extension: "
                                 ".png, .jpg or .jpeg)");
}

void savePicture(const CImage& image, const std::string& path) {
    requirePictureName(path);
    // The part file keeps the extension, which tells OpenCV the format.
    travel::PartFile part(path, travel::PartFile::Name::BeforeExtension);
    std::string reason;
    try {
        errno = 0;
        if (!image.saveToFile(part.part()))
            reason = errno ? std::strerror(errno) : "the picture could not be encoded";
    } catch (const std::exception& e) {
        reason = mrptMessage(e.what());
    }
    if (reason.empty() && !endsAsAPicture(part.part(), lowerExtension(path) == ".png"))
        reason = "the file ends before the picture does: disk full?";
    if (!reason.empty()) throw std::runtime_error(travel::cannotWriteMessage(path, reason));
    part.commit();
}

}  // namespace travel_mrpt
