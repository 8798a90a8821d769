// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// PCD v0.7 reader (https://pointclouds.org/documentation/tutorials/pcd_file_format.html):
// header lines VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA;
// data ascii (a point per line), binary (packed points) or binary_compressed (two uint32
// sizes, then LZF of the fields one after another: all x, then all y, ...).
#include <cstdlib>
#include <sstream>

#include "Readers.hpp"
#include "travel/io/BinaryFile.hpp"

namespace travel::io_detail {

namespace {

std::vector<std::string> splitWords(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

bool parseCount(const std::string& s, std::size_t& out) {
    if (s.empty() || s.size() > 18 || s.find_first_not_of("0123456789") != std::string::npos)
        return false;
    out = std::strtoull(s.c_str(), nullptr, 10);
    return true;
}

bool pcdType(std::size_t size, char type, ValueType& out) {
    struct Entry {
        char type;
        std::size_t size;
        ValueType value;
    };
    static const Entry kTypes[] = {{'F', 4, ValueType::F32}, {'F', 8, ValueType::F64},
                                   {'U', 1, ValueType::U8},  {'U', 2, ValueType::U16},
                                   {'U', 4, ValueType::U32}, {'I', 1, ValueType::I8},
                                   {'I', 2, ValueType::I16}, {'I', 4, ValueType::I32}};
    for (const Entry& e : kTypes) {
        if (e.type == type && e.size == size) {
            out = e.value;
            return true;
        }
    }
    return false;
}

}  // namespace

void readPcd(const std::string& path, const std::vector<unsigned char>& bytes, PointCloud& cloud) {
    std::vector<std::string> names, types;
    std::vector<std::size_t> sizes, counts;
    std::size_t width = 0, height = 0, points = 0, points_line = 0;
    bool has_version = false, has_width = false, has_height = false, has_points = false;
    std::string data;
    std::size_t line_no = 0, pos = 0;
    while (data.empty()) {
        if (pos >= bytes.size()) fail(path, "the header ends without a DATA line");
        std::size_t eol = pos;
        while (eol < bytes.size() && bytes[eol] != '\n') ++eol;
        const std::string line(bytes.begin() + static_cast<std::ptrdiff_t>(pos),
                               bytes.begin() + static_cast<std::ptrdiff_t>(eol));
        pos = eol + 1;
        ++line_no;
        const std::vector<std::string> w = splitWords(line);
        if (w.empty() || w[0][0] == '#') continue;
        const std::string& key = w[0];
        const std::size_t n = w.size() - 1;
        auto need = [&](bool ok, const std::string& message) {
            if (!ok) failAt(path, line_no, message);
        };
        // SIZE, TYPE and COUNT give one entry per FIELDS name.
        auto perField = [&](const char* what) {
            need(!names.empty(), std::string(what) + " before FIELDS");
            need(n == names.size(), "FIELDS has " + std::to_string(names.size()) + " names but " +
                                        what + " has " + std::to_string(n));
        };
        if (key == "VERSION") {
            need(
                n == 1 && (w[1] == "0.7" || w[1] == ".7"),
                "VERSION " + quotedExcerpt(n ? w[1] : "", 24) + " is not supported (expected 0.7)");
            has_version = true;
        } else if (key == "FIELDS") {
            need(n > 0, "FIELDS names no field");
            names.assign(w.begin() + 1, w.end());
        } else if (key == "SIZE") {
            perField("SIZE");
            sizes.resize(n);
            for (std::size_t k = 0; k < n; ++k)
                need(parseCount(w[k + 1], sizes[k]) && sizes[k] > 0,
                     "SIZE " + quotedExcerpt(w[k + 1], 24) + " of field '" + names[k] +
                         "' is not a size");
        } else if (key == "TYPE") {
            perField("TYPE");
            types.assign(w.begin() + 1, w.end());
        } else if (key == "COUNT") {
            perField("COUNT");
            counts.resize(n);
            for (std::size_t k = 0; k < n; ++k)
                need(parseCount(w[k + 1], counts[k]) && counts[k] > 0 && counts[k] < 65536,
                     "COUNT " + quotedExcerpt(w[k + 1], 24) + " of field '" + names[k] +
                         "' is not a count");
        } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
            std::size_t value = 0;
            need(n == 1 && parseCount(w[1], value), key + " is not a number of points");
            if (key == "WIDTH") width = value, has_width = true;
            if (key == "HEIGHT") height = value, has_height = true;
            if (key == "POINTS") points = value, has_points = true, points_line = line_no;
        } else if (key == "VIEWPOINT") {
            need(n == 7, "VIEWPOINT has " + std::to_string(n) + " numbers, expected 7");
        } else if (key == "DATA") {
            need(n == 1 && (w[1] == "ascii" || w[1] == "binary" || w[1] == "binary_compressed"),
                 "DATA " + quotedExcerpt(n ? w[1] : "", 24) +
                     " is not ascii, binary or binary_compressed");
            data = w[1];
        } else {
            failAt(path, line_no, quotedExcerpt(line, 24) + " is not a PCD header line");
        }
    }
    // The header is complete: check it as a whole (messages point at the DATA line).
    auto need = [&](bool ok, const std::string& message) {
        if (!ok) failAt(path, line_no, message);
    };
    need(has_version, "the header has no VERSION line");
    need(!names.empty(), "the header has no FIELDS line");
    need(!sizes.empty(), "the header has no SIZE line");
    need(!types.empty(), "the header has no TYPE line");
    need(has_width && has_height, "the header has no WIDTH or HEIGHT line");
    if (counts.empty()) counts.assign(names.size(), 1);
    if (height != 0 && width > static_cast<std::size_t>(-1) / height)
        need(false, "WIDTH*HEIGHT overflows");
    if (!has_points) points = width * height;
    if (width * height != points) {
        failAt(path, points_line,
               "POINTS " + std::to_string(points) +
                   " but WIDTH*HEIGHT = " + std::to_string(width * height));
    }
    std::vector<Field> fields(names.size());
    bool seen[kTargets] = {};
    std::size_t row = 0;
    for (std::size_t k = 0; k < names.size(); ++k) {
        Field& f = fields[k];
        f.name = names[k];
        need(types[k].size() == 1 && pcdType(sizes[k], types[k][0], f.type),
             "field '" + f.name + "' has SIZE " + std::to_string(sizes[k]) + " TYPE " +
                 quotedExcerpt(types[k], 24) + ", not one of F4 F8 U1 U2 U4 I1 I2 I4");
        f.count = static_cast<unsigned>(counts[k]);
        f.target = targetOf(f.name, f.type, f.scale);
        if (f.target != Target::Skip) {
            need(!seen[static_cast<int>(f.target)], "field '" + f.name + "' given twice");
            need(f.count == 1,
                 "field '" + f.name + "' has COUNT " + std::to_string(f.count) + ", expected 1");
            seen[static_cast<int>(f.target)] = true;
        }
        row += sizes[k] * f.count;
    }
    need(seen[static_cast<int>(Target::X)] && seen[static_cast<int>(Target::Y)] &&
             seen[static_cast<int>(Target::Z)],
         "FIELDS has no x, y and z");

    const unsigned char* begin = bytes.data() + std::min(pos, bytes.size());
    const unsigned char* end = bytes.data() + bytes.size();
    const std::size_t left = static_cast<std::size_t>(end - begin);
    if (data == "ascii") {
        checkRecordsFit(path, fields, points, true, left, "point");
        ValueSource src(path, true, begin, end, line_no + 1);
        decodeRecords(path, fields, points, src, cloud, "point");
        src.expectEnd(points, "point");
        return;
    }
    if (data == "binary") {
        // Bytes after the last point are ignored, as PCL does: its writer pads binary files
        // (kitti_raw_pcd/*.pcd end with 3906 zero bytes).
        if (points > left / row) {
            fail(path, "DATA binary needs " + std::to_string(points) + " points of " +
                           std::to_string(row) + " bytes but " + std::to_string(left) +
                           " bytes follow the header");
        }
        ValueSource src(path, false, begin, begin + points * row, 0);
        decodeRecords(path, fields, points, src, cloud, "point");
        return;
    }
    // binary_compressed: LZF of the fields one after another; transposed back to packed points.
    if (left < 8)
        fail(path, "binary_compressed data has no sizes (" + std::to_string(left) + " bytes)");
    const std::size_t packed = le::load<uint32_t>(begin), unpacked = le::load<uint32_t>(begin + 4);
    if (packed > left - 8) {
        fail(path, "binary_compressed data claims " + std::to_string(packed) +
                       " compressed bytes but " + std::to_string(left - 8) + " follow");
    }
    if (points > unpacked / row || points * row != unpacked) {
        fail(path, "binary_compressed data unpacks to " + std::to_string(unpacked) +
                       " bytes, but POINTS " + std::to_string(points) + " of " +
                       std::to_string(row) + " bytes need " + std::to_string(points * row));
    }
    thread_local std::vector<unsigned char> soa, aos;
    soa.resize(unpacked);
    if (!lzfDecompress(begin + 8, packed, soa.data(), unpacked))
        fail(path, "binary_compressed data is corrupt (LZF does not decode to " +
                       std::to_string(unpacked) + " bytes)");
    aos.resize(unpacked);
    std::size_t column = 0, field_offset = 0;
    for (std::size_t k = 0; k < names.size(); ++k) {
        const std::size_t width_k = sizes[k] * counts[k];
        for (std::size_t i = 0; i < points; ++i)
            std::memcpy(aos.data() + i * row + field_offset, soa.data() + column + i * width_k,
                        width_k);
        column += points * width_k;
        field_offset += width_k;
    }
    ValueSource src(path, false, aos.data(), aos.data() + aos.size(), 0);
    decodeRecords(path, fields, points, src, cloud, "point");
}

}  // namespace travel::io_detail
