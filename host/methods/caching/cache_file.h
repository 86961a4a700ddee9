// Record cache files (--cache-out / --cache-in): a versioned binary list of a caching method's
// records, cache level by cache level, that another view of the same scene reuses. The file knows
// only the shared part of a record (shared::Record), the host-only data (RecordHostData) and the
// payload's size; the method names itself with a tag. A missing file, a file of another version,
// of another method or payload size, made for another scene or with another accuracy, and a
// truncated or corrupt file are refused with an error naming the file.
//
// Layout (little-endian), version 2: magic "RCIRCACH" (version 1 held irradiance records only),
// uint32 version, uint32 record bytes (shared::Record and RecordHostData, 68), char[16] method tag
// (NUL-padded), uint32 payload bytes P, uint32 cache levels L, uint64 scene fingerprint, float32
// accuracy, uint32 0, uint64 record count, L uint64 record counts (one per level), the records
// level by level (each: shared::Record, RecordHostData, P payload bytes), uint64 checksum of
// everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "methods/caching/record_store.h"

namespace rc {

// What a cache file must match to be read: written into it, checked on reading.
struct CacheFileKey {
    std::string method;  // tag, at most 15 characters ("irradiance")
    size_t payload_bytes = 0;
    uint64_t scene = 0;      // scene_fingerprint
    std::string scene_name;  // for the error when the scene differs
    float accuracy = 0.0f;   // of every level
};

// Writes the levels' records (every store of key.payload_bytes payloads).
void write_cache_file(const std::filesystem::path& path, const CacheFileKey& key,
                      const std::vector<RecordStore>& levels);

// The levels stored in the file, as stores of key.accuracy.
std::vector<RecordStore> read_cache_file(const std::filesystem::path& path,
                                         const CacheFileKey& key);

// The same from the file's bytes (`name` names it in errors): the fuzz target's entry. Every
// size is checked against the bytes there are before anything is allocated, and every record's
// values against their ranges.
std::vector<RecordStore> parse_cache_file(const std::string& bytes, const std::string& name,
                                          const CacheFileKey& key);

}  // namespace rc
