// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// PLY reader (http://paulbourke.net/dataformats/ply/): "ply", "format ascii|binary_little_endian
// 1.0", elements with scalar or list properties, "end_header". The points are the "vertex"
// element; elements before it are read past, elements after it ignored; after a last vertex
// element nothing may follow.
#include <cstdlib>
#include <sstream>

#include "Readers.hpp"

namespace travel::io_detail {

namespace {

bool plyType(const std::string& name, ValueType& out) {
    struct Entry {
        const char* name;
        ValueType type;
    };
    static const Entry kTypes[] = {
        {"char", ValueType::I8},    {"int8", ValueType::I8},     {"uchar", ValueType::U8},
        {"uint8", ValueType::U8},   {"short", ValueType::I16},   {"int16", ValueType::I16},
        {"ushort", ValueType::U16}, {"uint16", ValueType::U16},  {"int", ValueType::I32},
        {"int32", ValueType::I32},  {"uint", ValueType::U32},    {"uint32", ValueType::U32},
        {"float", ValueType::F32},  {"float32", ValueType::F32}, {"double", ValueType::F64},
        {"float64", ValueType::F64}};
    for (const Entry& e : kTypes) {
        if (name == e.name) {
            out = e.type;
            return true;
        }
    }
    return false;
}

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Field> fields;
};

}  // namespace

void readPly(const std::string& path, const std::vector<unsigned char>& bytes, PointCloud& cloud) {
    std::vector<Element> elements;
    std::string format;
    std::size_t line_no = 0, pos = 0;
    for (bool header_done = false; !header_done;) {
        if (pos >= bytes.size()) fail(path, "the header ends without end_header");
        std::size_t eol = pos;
        while (eol < bytes.size() && bytes[eol] != '\n') ++eol;
        std::string line(bytes.begin() + static_cast<std::ptrdiff_t>(pos),
                         bytes.begin() + static_cast<std::ptrdiff_t>(eol));
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pos = eol + 1;
        ++line_no;
        auto need = [&](bool ok, const std::string& message) {
            if (!ok) failAt(path, line_no, message);
        };
        if (line_no == 1) {
            need(line == "ply", quotedExcerpt(line, 24) + " is not 'ply': not a PLY file");
            continue;
        }
        std::istringstream in(line);
        std::vector<std::string> w;
        for (std::string s; in >> s;) w.push_back(s);
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "format") {
            need(w.size() == 3 && w[2] == "1.0",
                 quotedExcerpt(line, 24) + " is not a PLY 1.0 format");
            need(w[1] == "ascii" || w[1] == "binary_little_endian",
                 "format " + quotedExcerpt(w[1], 24) +
                     " is not supported (ascii or binary_little_endian only)");
            format = w[1];
        } else if (w[0] == "element") {
            Element e;
            need(w.size() == 3 && w[2].find_first_not_of("0123456789") == std::string::npos &&
                     w[2].size() < 19,
                 quotedExcerpt(line, 24) + " is not 'element NAME COUNT'");
            e.name = w[1];
            e.count = std::strtoull(w[2].c_str(), nullptr, 10);
            elements.push_back(e);
        } else if (w[0] == "property") {
            need(!elements.empty(), "property before any element");
            Element& e = elements.back();
            Field f;
            if (w.size() == 5 && w[1] == "list") {
                need(
                    plyType(w[2], f.count_type) && isInteger(f.count_type) && plyType(w[3], f.type),
                    quotedExcerpt(line, 24) + " has an unknown or non-integer list type");
                f.list = true;
                f.name = w[4];
            } else {
                need(w.size() == 3 && plyType(w[1], f.type),
                     quotedExcerpt(line, 24) + " is not 'property TYPE NAME' with a PLY type");
                f.name = w[2];
            }
            if (e.name == "vertex") {
                f.target = targetOf(f.name, f.type, f.scale);
                for (const Field& other : e.fields)
                    need(other.name != f.name, "property '" + f.name + "' given twice");
                need(!f.list || f.target == Target::Skip,
                     "vertex property '" + f.name + "' is a list, expected one value");
            }
            e.fields.push_back(f);
        } else if (w[0] == "end_header") {
            need(!format.empty(), "the header has no format line");
            header_done = true;
        } else {
            need(false, quotedExcerpt(line, 24) + " is not a PLY header line");
        }
    }
    const Element* vertex = nullptr;
    for (const Element& e : elements)
        if (e.name == "vertex") vertex = &e;
    if (!vertex) failAt(path, line_no, "the header has no vertex element");
    bool has[kTargets] = {};
    for (const Field& f : vertex->fields)
        if (f.target != Target::Skip) has[static_cast<int>(f.target)] = true;
    if (!has[0] || !has[1] || !has[2]) failAt(path, line_no, "element vertex has no x, y and z");

    const bool ascii = format == "ascii";
    const unsigned char* begin = bytes.data() + std::min(pos, bytes.size());
    ValueSource src(path, ascii, begin, bytes.data() + bytes.size(), line_no + 1);
    double ignored[kTargets];
    for (const Element& e : elements) {
        checkRecordsFit(path, e.fields, e.count, ascii, src.bytesLeft(), e.name.c_str());
        if (&e == vertex) {
            decodeRecords(path, e.fields, e.count, src, cloud, "vertex");
            // Nothing may follow the last element: more rows than the header's count would be
            // points silently lost (as in a PCD file).
            if (&e == &elements.back()) src.expectEnd(e.count, "vertex");
            return;
        }
        for (std::size_t i = 0; i < e.count; ++i) {
            src.beginRecord(i, e.count, e.name.c_str());
            readRecord(e.fields, src, ignored);
            src.endRecord();
        }
    }
}

}  // namespace travel::io_detail
