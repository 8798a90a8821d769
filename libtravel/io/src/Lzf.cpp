// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// LZF, the compression of PCD's binary_compressed data (PCL uses liblzf). Written here rather
// than linking Debian's liblzf: the decoder is this short and libtravel stays Eigen-only.
// Format: a control byte c < 32 starts a literal run of c + 1 bytes; otherwise its top 3 bits
// are a length (7 = "add the next byte") and, with the next byte, its low 5 bits an offset
// back into the output; a back-reference copies length + 2 bytes from offset + 1 back.
#include <cstring>

#include "Readers.hpp"

namespace travel::io_detail {

bool lzfDecompress(const unsigned char* in, std::size_t in_size, unsigned char* out,
                   std::size_t out_size) {
    const unsigned char* ip = in;
    const unsigned char* const in_end = in + in_size;
    std::size_t op = 0;
    while (ip < in_end) {
        const unsigned ctrl = *ip++;
        if (ctrl < 32) {
            const std::size_t len = ctrl + 1;
            if (len > static_cast<std::size_t>(in_end - ip) || len > out_size - op) return false;
            std::memcpy(out + op, ip, len);
            ip += len, op += len;
            continue;
        }
        std::size_t len = ctrl >> 5;
        if (len == 7) {
            if (ip >= in_end) return false;
            len += *ip++;
        }
        if (ip >= in_end) return false;
        const std::size_t back = ((static_cast<std::size_t>(ctrl & 0x1f) << 8) | *ip++) + 1;
        len += 2;
        if (back > op || len > out_size - op) return false;
        // Byte by byte: the source may overlap the bytes being written (a repeated pattern).
        for (std::size_t k = 0; k < len; ++k, ++op) out[op] = out[op - back];
    }
    return op == out_size;
}

std::vector<unsigned char> lzfCompress(const unsigned char* in, std::size_t size) {
    constexpr std::size_t kMaxBack = 8192, kMaxLen = 264, kHashBits = 14;
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<std::size_t> last(std::size_t{1} << kHashBits, kNone);
    std::vector<unsigned char> out;
    out.reserve(size + size / 32 + 8);
    std::size_t literal_start = 0;
    auto flushLiterals = [&](std::size_t end) {
        while (literal_start < end) {
            const std::size_t run = std::min<std::size_t>(32, end - literal_start);
            out.push_back(static_cast<unsigned char>(run - 1));
            out.insert(out.end(), in + literal_start, in + literal_start + run);
            literal_start += run;
        }
    };
    std::size_t i = 0;
    while (i + 2 < size) {
        const uint32_t key = (uint32_t{in[i]} << 16) | (uint32_t{in[i + 1]} << 8) | in[i + 2];
        const std::size_t h = (key * 2654435761u) >> (32 - kHashBits);
        const std::size_t candidate = last[h];
        last[h] = i;
        if (candidate != kNone && i - candidate <= kMaxBack &&
            std::memcmp(in + candidate, in + i, 3) == 0) {
            const std::size_t max_len = std::min(kMaxLen, size - i);
            std::size_t len = 3;
            while (len < max_len && in[candidate + len] == in[i + len]) ++len;
            flushLiterals(i);
            const std::size_t offset = i - candidate - 1, code = len - 2;
            if (code < 7) {
                out.push_back(static_cast<unsigned char>((code << 5) | (offset >> 8)));
            } else {
                out.push_back(static_cast<unsigned char>((7 << 5) | (offset >> 8)));
                out.push_back(static_cast<unsigned char>(code - 7));
            }
            out.push_back(static_cast<unsigned char>(offset & 0xff));
            i += len;
            literal_start = i;
        } else {
            ++i;
        }
    }
    flushLiterals(size);
    return out;
}

}  // namespace travel::io_detail
