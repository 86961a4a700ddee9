// Irradiance vector grid files (--grid-out / --grid-in): the normalised grid of a scene, reused by
// later renders of the same scene and frame. A file made for another scene, frame, depth limit or
// with direct light recorded differently, a file of another version, and a truncated or corrupt
// file are refused with an error naming the file.
//
// Layout (little-endian): magic "RCIVGRID", uint32 version, uint32 values per vertex (54),
// uint64 scene fingerprint, int32 voxels per axis (3), uint32 1 when direct light is recorded,
// float32 origin (3), float32 cell size (3), uint64 photons, int32 maximum depth, uint32 0, the
// values (float32, vertex by vertex as in kernels/common/irradiance_vector_grid.h), uint64 checksum
// of everything before it.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace rc {

struct IvgOptions;

struct GridFile {
    std::array<int, 3> cells{0, 0, 0};
    glm::vec3 origin{0.0f};
    glm::vec3 cell{0.0f};
    uint64_t photons = 0;
    bool include_direct = false;
    int max_depth = 0;
    std::vector<float> values;
};

void write_grid_file(const std::filesystem::path& path, const Scene& scene, const GridFile& grid);

// The grid stored in the file; Error unless it is an intact grid file of this scene.
GridFile read_grid_file(const std::filesystem::path& path, const Scene& scene);

// The same from the file's bytes (`name` names it in errors), for the scene whose fingerprint is
// `scene` (named `scene_name` in errors): the fuzz target's entry.
GridFile parse_grid_file(const std::string& bytes, const std::string& name, uint64_t scene,
                         const std::string& scene_name);

// Error naming `name` when the grid does not fit the options: another resolution than --grid
// asks for, direct light recorded or not unlike --ivg-include-direct, another depth limit.
void check_grid_file(const GridFile& grid, const IvgOptions& options, const std::string& name);

}  // namespace rc
