// The irradiance vector grid (Pacanowski et al., INRIA RR-6983; DESIGN.md §6.3): a uniform grid
// over the scene whose vertices hold six irradiance vectors per colour channel, filled by photon
// tracing on the device, normalised, optionally compressed, saved and loaded. Owns the grid's
// buffers and reports its statistics; ivg_method.h renders with it, and as a radiance source
// (kernels/common/ivg_source.h) the hemisphere rays of a caching method read it
// (--ic-ivg).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "device/kernel.h"
#include "device/memory_need.h"
#include "methods/frame_scene.h"
#include "methods/grid/ivg_cell_planes.h"
#include "methods/radiance_source.h"
#include "methods/shared_settings.h"
#include "shared/types.h"

namespace rc {

// Of the shared settings, the seed and depth limits apply.
struct IvgOptions : SharedSettings {
    std::array<int, 3> cells{0, 0, 0};  // voxels per axis; all 0: chosen from the scene (auto)
    uint64_t photons = 0;               // 0: chosen from the grid's size
    bool include_direct = false;        // record unbounced photon segments (direct light)
    int interpolation = RC_IVG_TRILINEAR;
    bool compressed = false;         // read the 16-bit colour + direction layout (§4.2)
    std::filesystem::path grid_in;   // load instead of tracing photons
    std::filesystem::path grid_out;  // save after building
};

// "NxMxK" or "auto"; Error (exit status 2) naming --grid otherwise.
std::array<int, 3> parse_grid_resolution(const std::string& text);

// One device's share of the photons when the grid is traced on several devices.
struct IvgDeviceShare {
    std::string device;  // "P:D name"
    size_t batches = 0;
    uint64_t photons = 0;
    double seconds = 0.0;
};

struct IvgStats {
    std::vector<IvgDeviceShare> devices;  // with the frame's peers: per device, the first first
    std::array<int, 3> cells{0, 0, 0};
    uint64_t photons = 0;
    uint64_t crossings = 0;
    uint64_t rays = 0;
    bool loaded = false;    // from --grid-in
    size_t grid_bytes = 0;  // the normalised grid (and the compressed copy) on the device
    double trace_seconds = 0.0;
    double normalize_seconds = 0.0;  // normalisation, compression and the file
    // The cells' planes (ivg_cell_planes.h): cells with a supporting plane, with triangles but
    // none, with no triangle; the oriented planes stored.
    size_t plane_cells = 0;
    size_t unsupported_cells = 0;
    size_t empty_cells = 0;
    size_t planes = 0;
    double planes_seconds = 0.0;
};

// A photon segment for the deposition tests: from -> to carrying flux.
struct PhotonSegment {
    glm::vec3 from{0.0f};
    glm::vec3 to{0.0f};
    glm::vec3 flux{0.0f};
};

// The voxels per axis `auto` picks for a box of this size: cubic cells, about
// kAutoGridVertices vertices, at least 2 voxels per axis.
std::array<int, 3> auto_grid_cells(glm::vec3 extent);
constexpr int kAutoGridVertices = 32768;

// The device memory a frame's grid holds (device/memory_need.h), for `scene` posed at the frame:
// while it is built (the fixed-point sums beside the normalised values) and once built (the
// values and their compressed copy). A grid read from --grid-in is only known when read.
struct IvgDeviceNeed {
    DeviceMemoryNeed building;
    DeviceMemoryNeed built;
};
IvgDeviceNeed ivg_device_need(const IvgOptions& options, const Scene& scene);
// The device memory of a frame whose grid is built first and then read while `after` is held:
// the larger of building the grid and `after` beside the built grid.
DeviceMemoryNeed with_grid_need(const IvgOptions& options, const Scene& scene,
                                DeviceMemoryNeed after);
// Photons `auto` traces per grid vertex.
constexpr uint64_t kAutoPhotonsPerVertex = 8;

class IrradianceVectorGrid : public RadianceSource, private FrameBound {
   public:
    explicit IrradianceVectorGrid(const FrameScene& frame);

    // Traces photons into the grid (or loads it), normalises it and prepares what the options
    // ask to read (the compressed layout); saves it when asked.
    void build(const IvgOptions& options, IvgStats* stats = nullptr);

    // The grid's placement and the fixed-point scale for the scene and options (no photons).
    shared::IvgParams layout(const IvgOptions& options) const;
    const shared::IvgParams& params() const { return params_; }
    void set_params(const shared::IvgParams& params) { params_ = params; }

    // Kernel arguments (IvgParams, values, packed, cell planes, planes), in that order.
    unsigned set_kernel_args(Kernel& kernel, unsigned first) const override;
    std::string build_options() const override { return radiance_source_define(RC_RADIANCE_GRID); }
    std::string source_name() const override { return "irradiance vector grid"; }

    // The normalised grid (RC_IVG_VALUES_PER_VERTEX floats per vertex).
    std::vector<float> values() const;
    void set_values(const std::vector<float>& values);

    // Tests: the fixed-point sums of segments deposited into an empty grid with these params.
    std::vector<int64_t> deposit(const shared::IvgParams& params,
                                 const std::vector<PhotonSegment>& segments);
    // Tests: fixed-point sums normalised by the kernel with these params.
    std::vector<float> normalize(const shared::IvgParams& params,
                                 const std::vector<int64_t>& accum);
    // Tests: the irradiance the current grid gives points with unit normals.
    std::vector<glm::vec3> lookup(const std::vector<glm::vec3>& positions,
                                  const std::vector<glm::vec3>& normals);

   private:
    void upload_values(const std::vector<float>& values);
    // The cells' planes for params_ and the scene, classified and uploaded; params_'s margins set.
    void upload_cell_planes(IvgStats* stats);
    // Photons 0 .. photons - 1 of params_ traced into `accum` (fixed-point sums, zeroed; counters:
    // the launches' two counters): on the frame's device, or in batches shared with its peers
    // (ivg_photon_split.cpp), each device into its own sums, added on the host (integer sums:
    // bitwise the same in any order).
    void trace_photons(uint64_t photons, Buffer<int64_t>& accum, Buffer<unsigned>& counters,
                       IvgStats* stats);
    void trace_photons_split(uint64_t photons, Buffer<int64_t>& accum, IvgStats* stats);

    FrameScene frame_;

    Kernel trace_kernel_;
    Kernel deposit_kernel_;
    Kernel normalize_kernel_;
    Kernel lookup_kernel_;
    shared::IvgParams params_{};
    Buffer<float> values_;
    Buffer<uint16_t> packed_;
    Buffer<shared::IvgCellPlanes> cell_planes_;
    Buffer<shared::IvgPlane> planes_;
};

}  // namespace rc
