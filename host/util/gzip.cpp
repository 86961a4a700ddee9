#include "util/gzip.h"

#include <zlib.h>

#include <algorithm>

#include "util/error.h"

namespace rc {

bool is_gzip(const std::string& bytes) {
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gunzip(const std::string& bytes, uint64_t max_bytes, const std::string& what) {
    z_stream stream{};
    // 16 + MAX_WBITS: a gzip header and trailer (zlib's inflateInit2 documentation).
    if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) {
        throw Error(what + ": zlib could not start inflating");
    }
    std::string out;
    char chunk[1 << 16];
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream.avail_in = static_cast<uInt>(std::min<size_t>(bytes.size(), UINT32_MAX));
    int status = Z_OK;
    while (true) {
        stream.next_out = reinterpret_cast<Bytef*>(chunk);
        stream.avail_out = sizeof chunk;
        status = inflate(&stream, Z_NO_FLUSH);
        if (status != Z_OK && status != Z_STREAM_END) {
            break;
        }
        out.append(chunk, sizeof chunk - stream.avail_out);
        if (out.size() > max_bytes) {
            inflateEnd(&stream);
            throw Error(what + ": inflates to more than " + std::to_string(max_bytes) + " bytes");
        }
        if (status == Z_STREAM_END) {
            if (stream.avail_in == 0) {
                break;
            }
            inflateReset(&stream);  // another gzip member follows
        }
    }
    inflateEnd(&stream);
    if (status != Z_STREAM_END) {
        throw Error(what + ": not valid gzip data (" +
                    (status == Z_BUF_ERROR ? std::string("truncated") : "corrupt") + ")");
    }
    return out;
}

}  // namespace rc
