// gzip-compressed data (RFC 1952) inflated through zlib: pbrt-v4's ".ply.gz" meshes.
#pragma once

#include <cstdint>
#include <string>

namespace rc {

// Whether `bytes` start with gzip's magic number (1f 8b).
bool is_gzip(const std::string& bytes);

// The inflated bytes of gzip data (every member, concatenated, as gzip -d gives them). Error
// naming `what` when the data is corrupt or truncated, or inflates to more than max_bytes.
std::string gunzip(const std::string& bytes, uint64_t max_bytes, const std::string& what);

}  // namespace rc
