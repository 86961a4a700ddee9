#include "methods/grid/irradiance_vector_grid_file.h"

#include <cmath>
#include <cstring>

#include "methods/grid/irradiance_vector_grid.h"
#include "scene/scene_fingerprint.h"
#include "util/error.h"
#include "util/file_checksum.h"
#include "util/file_io.h"

namespace rc {
namespace {

constexpr char kMagic[8] = {'R', 'C', 'I', 'V', 'G', 'R', 'I', 'D'};
// 2: the scene fingerprint hashes the named-field scene structs (files of version 1 would read as
// another scene).
constexpr uint32_t kVersion = 2;

struct Header {
    char magic[8];
    uint32_t version;
    uint32_t values_per_vertex;
    uint64_t scene;
    int32_t cells[3];
    uint32_t include_direct;
    float origin[3];
    float cell[3];
    uint64_t photons;
    int32_t max_depth;
    uint32_t reserved;
};
static_assert(sizeof(Header) == 80);

std::string resolution(const std::array<int, 3>& cells) {
    return std::to_string(cells[0]) + "x" + std::to_string(cells[1]) + "x" +
           std::to_string(cells[2]);
}

}  // namespace

void write_grid_file(const std::filesystem::path& path, const Scene& scene, const GridFile& grid) {
    Header header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kVersion;
    header.values_per_vertex = RC_IVG_VALUES_PER_VERTEX;
    header.scene = scene_fingerprint(scene);
    for (int axis = 0; axis < 3; ++axis) {
        header.cells[axis] = grid.cells[axis];
        header.origin[axis] = grid.origin[axis];
        header.cell[axis] = grid.cell[axis];
    }
    header.include_direct = grid.include_direct ? 1 : 0;
    header.photons = grid.photons;
    header.max_depth = grid.max_depth;
    std::string bytes;
    bytes.append(reinterpret_cast<const char*>(&header), sizeof header);
    bytes.append(reinterpret_cast<const char*>(grid.values.data()),
                 grid.values.size() * sizeof(float));
    append_checksum(bytes);
    write_file_atomically(path, bytes);
}

GridFile read_grid_file(const std::filesystem::path& path, const Scene& scene) {
    const std::string name = path.string();
    if (!std::filesystem::is_regular_file(path)) {
        throw Error(name + ": irradiance vector grid file " +
                    (std::filesystem::exists(path) ? "is not a regular file (a folder, a device "
                                                     "or a FIFO)"
                                                   : "not found"));
    }
    return parse_grid_file(read_file(path, kDefaultMaxFileBytes, "irradiance vector grid"), name,
                           scene_fingerprint(scene), scene.path.string());
}

GridFile parse_grid_file(const std::string& bytes, const std::string& name, uint64_t scene,
                         const std::string& scene_name) {
    Header header;
    if (bytes.size() < sizeof header + sizeof(uint64_t) ||
        std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
        throw Error(name + ": not a radcache irradiance vector grid file");
    }
    std::memcpy(&header, bytes.data(), sizeof header);
    if (header.version != kVersion) {
        throw Error(name + ": irradiance vector grid version " + std::to_string(header.version) +
                    "; this radcache reads version " + std::to_string(kVersion));
    }
    bool sizes_fit = header.values_per_vertex == RC_IVG_VALUES_PER_VERTEX;
    uint64_t vertices = 1;
    for (int axis = 0; axis < 3; ++axis) {
        sizes_fit = sizes_fit && header.cells[axis] >= 1 && header.cells[axis] <= 1024;
        vertices *= static_cast<uint64_t>(std::max(header.cells[axis], 0)) + 1;
    }
    sizes_fit =
        sizes_fit && bytes.size() == sizeof header +
                                         vertices * RC_IVG_VALUES_PER_VERTEX * sizeof(float) +
                                         sizeof(uint64_t);
    if (!sizes_fit) {
        throw Error(name + ": corrupt irradiance vector grid (" + std::to_string(bytes.size()) +
                    " bytes do not match its header)");
    }
    if (!has_valid_checksum(bytes)) {
        throw Error(name + ": corrupt irradiance vector grid (checksum mismatch)");
    }
    if (header.scene != scene) {
        throw Error(name +
                    ": irradiance vector grid was made for another scene (or another frame of "
                    "it) than " +
                    scene_name);
    }
    GridFile grid;
    for (int axis = 0; axis < 3; ++axis) {
        grid.cells[axis] = header.cells[axis];
        grid.origin[axis] = header.origin[axis];
        grid.cell[axis] = header.cell[axis];
    }
    grid.include_direct = header.include_direct != 0;
    grid.photons = header.photons;
    grid.max_depth = header.max_depth;
    grid.values.resize(vertices * RC_IVG_VALUES_PER_VERTEX);
    std::memcpy(grid.values.data(), bytes.data() + sizeof header,
                grid.values.size() * sizeof(float));
    // The values where they must lie (the checksum guards against accidents only).
    bool sound = grid.max_depth >= 0;
    for (int axis = 0; axis < 3; ++axis) {
        const float far =
            grid.origin[axis] + static_cast<float>(grid.cells[axis]) * grid.cell[axis];
        sound = sound && std::fabs(grid.origin[axis]) <= kMaxWorldCoordinate &&
                std::fabs(far) <= kMaxWorldCoordinate && grid.cell[axis] > 0.0f;
    }
    for (size_t i = 0; sound && i < grid.values.size(); ++i) {
        sound = std::isfinite(grid.values[i]);
    }
    if (!sound) {
        throw Error(name + ": corrupt irradiance vector grid (values out of range)");
    }
    return grid;
}

void check_grid_file(const GridFile& grid, const IvgOptions& options, const std::string& name) {
    if (options.cells[0] > 0 && options.cells != grid.cells) {
        throw Error(name + ": irradiance vector grid is " + resolution(grid.cells) + ", not the " +
                    resolution(options.cells) + " --grid asks for");
    }
    if (grid.include_direct != options.include_direct) {
        throw Error(name + ": irradiance vector grid was made " +
                    (grid.include_direct ? "with" : "without") +
                    " direct light; --ivg-include-direct must match");
    }
    if (grid.max_depth != options.max_depth) {
        throw Error(name + ": irradiance vector grid was made with max_depth " +
                    std::to_string(grid.max_depth) + ", not " + std::to_string(options.max_depth));
    }
}

}  // namespace rc
