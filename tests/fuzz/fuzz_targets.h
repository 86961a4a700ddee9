// The fuzz targets (docs/reliability.md): one entry per parser of untrusted bytes. Each takes one
// input, must return 0 for every input, and may only fail with rc::Error (a refusal with a
// message); anything else (a crash, a sanitizer report, another exception, a hang or unbounded
// memory) is a bug. libFuzzer drives them in the fuzz build (RADCACHE_FUZZ); the test suite runs
// them over their seeds and every input the fuzzers have found (fuzz_regression_test).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_files.h"
#include "util/error.h"

namespace rc::fuzz {

// A scene file with its meshes, libraries and textures in memory: the input split into files.
int scene(const uint8_t* data, size_t size);
// An OBJ file with its MTL libraries in memory.
int obj(const uint8_t* data, size_t size);
// A glTF 2.0 file (or .glb bytes) with its buffers and images in memory.
int gltf(const uint8_t* data, size_t size);
// A pbrt-v4 scene with its included files, PLY meshes and images in memory.
int pbrt(const uint8_t* data, size_t size);
// An irradiance (or any method's) record cache file, its checksum made to match.
int cache_file(const uint8_t* data, size_t size);
// An irradiance vector grid file, its checksum made to match.
int grid_file(const uint8_t* data, size_t size);
// A kernel binary-cache entry, its checksum made to match for half the inputs.
int kernel_cache(const uint8_t* data, size_t size);

struct Target {
    const char* name;
    int (*run)(const uint8_t*, size_t);
};
inline constexpr Target kTargets[] = {{"scene", scene},
                                      {"obj", obj},
                                      {"gltf", gltf},
                                      {"pbrt", pbrt},
                                      {"cache_file", cache_file},
                                      {"grid_file", grid_file},
                                      {"kernel_cache", kernel_cache}};

// The files of a multi-file input: the first is named `first_name`; every line
// "#@file NAME" starts the next file, named NAME.
std::vector<std::pair<std::string, std::string>> split_files(const uint8_t* data, size_t size,
                                                             const std::string& first_name);

// What the multi-file targets do: `load(first_name, files)` over the input split into files held
// in memory (split_files), a refusal (rc::Error) being a valid outcome.
template <class Load>
int load_from_memory(const uint8_t* data, size_t size, const std::string& first_name,
                     const Load& load) {
    MemoryFiles files;
    for (auto& [name, bytes] : split_files(data, size, first_name)) {
        files.add(name, std::move(bytes));
    }
    try {
        load(first_name, files);
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
