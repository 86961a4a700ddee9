// The cache files' trailing checksum (record caches, irradiance vector grids): a 64-bit
// fingerprint (farmhash) of every byte before it. It guards against accidents (a truncated or
// damaged file), not against a forged one.
#pragma once

#include <string>

namespace rc {

// Appends the checksum of `bytes` to them.
void append_checksum(std::string& bytes);

// Whether the last 8 bytes of `bytes` (at least 8) are the checksum of the bytes before them.
bool has_valid_checksum(const std::string& bytes);

}  // namespace rc
