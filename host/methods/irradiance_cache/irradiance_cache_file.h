// Irradiance cache files (--cache-out / --cache-in): a versioned binary record list that another
// view of the same scene reuses. A file made for another scene or with another accuracy, a file of
// another version, and a truncated or corrupt file are refused with an error naming the file.
//
// Layout (little-endian): magic "RCIRCACH", uint32 version, uint32 record size, uint64 scene
// fingerprint, float32 accuracy, uint32 cache levels L, uint64 record count, L uint64 record
// counts (one per level), the records level by level (35 float32 each: position, normal,
// irradiance, 3 rotational and 3 translational gradients, harmonic mean and minimum distance,
// R_min, R_max, R, occluder offset), uint64 checksum of everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "methods/irradiance_cache/irradiance_records.h"
#include "scene/scene.h"

namespace rc {

// Writes the levels' records (every store made with the same accuracy).
void write_irradiance_cache(const std::filesystem::path& path, const Scene& scene,
                            const std::vector<RecordStore>& levels);

// The records of each level stored in the file.
std::vector<std::vector<CacheRecord>> read_irradiance_cache(const std::filesystem::path& path,
                                                            const Scene& scene, float accuracy);

}  // namespace rc
