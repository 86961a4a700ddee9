#include "methods/grid/irradiance_vector_grid.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "methods/grid/irradiance_vector_grid_file.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "util/error.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {
namespace {

constexpr uint64_t kPhotonsPerLaunch = uint64_t{1} << 22;
constexpr uint64_t kMaxPhotons = uint64_t{1} << 31;
// Crossings at grazing angles are divided by at least this |cosine| (see rc_ivg_fixed).
constexpr float kSmallestCosine = 0.1f;
// The largest fixed-point amount one crossing may add: 2^40, leaving 2^23 such amounts of
// headroom in a 64-bit sum.
constexpr double kLargestAmount = 1099511627776.0;

size_t vertex_count(const std::array<int, 3>& cells) {
    return static_cast<size_t>(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1);
}

// The largest flux (any channel) one photon can start with, divided by its light's selection
// probability: what rc_ivg_emit gives the brightest light.
float largest_photon_flux(const Scene& scene, float sphere_radius) {
    const float pi = 3.14159265f;
    float largest = 0.0f;
    const std::vector<shared::Light>& lights = scene.lights.lights;
    for (size_t l = 0; l < lights.size(); ++l) {
        const float selection = scene.lights.cdf[l] - (l > 0 ? scene.lights.cdf[l - 1] : 0.0f);
        if (!(selection > 0.0f)) {
            continue;
        }
        const shared::Light& light = lights[l];
        float scale = 0.0f;
        switch (light.kind) {
            case RC_LIGHT_AREA:
                scale = pi * light.area;
                break;
            case RC_LIGHT_POINT:
                scale = 4.0f * pi;
                break;
            case RC_LIGHT_SPOT:
                scale = 2.0f * pi * (1.0f - light.cos_cutoff);
                break;
            case RC_LIGHT_DISTANT:
                scale = pi * sphere_radius * sphere_radius;
                break;
            default:
                // The environment: 4 pi x pi r^2 x its radiance; a map's largest radiance over
                // the density of its direction (scene/environment_map.h) x pi r^2.
                scale = light.map >= 0 ? light.area * pi * sphere_radius * sphere_radius /
                                             std::max({light.radiance.x, light.radiance.y,
                                                       light.radiance.z, 1e-30f})
                                       : 4.0f * pi * pi * sphere_radius * sphere_radius;
                break;
        }
        const float brightest =
            std::max({light.radiance.x, light.radiance.y, light.radiance.z}) * scale / selection;
        largest = std::max(largest, brightest);
    }
    return largest;
}

}  // namespace

std::array<int, 3> parse_grid_resolution(const std::string& text) {
    if (text == "auto") {
        return {0, 0, 0};
    }
    static const std::regex form(R"(^(\d{1,4})x(\d{1,4})x(\d{1,4})$)");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw Error(
            "--grid: expected NxMxK (voxels per axis, e.g. 32x32x32) or auto, got '" + text + "'",
            kExitUsage);
    }
    std::array<int, 3> cells{};
    for (int axis = 0; axis < 3; ++axis) {
        cells[axis] = std::stoi(match[axis + 1].str());
        if (cells[axis] < 1 || cells[axis] > 1024) {
            throw Error("--grid: voxels per axis must be in [1, 1024], got '" + text + "'",
                        kExitUsage);
        }
    }
    if (vertex_count(cells) > (size_t{1} << 24)) {
        throw Error("--grid: " + text + " has more than 16M vertices", kExitUsage);
    }
    return cells;
}

// The longest side of a bounding box's extent, 1 for a point (no absolute floor: the grid is
// the scene's at any scale).
float longest_side(glm::vec3 extent) {
    const float longest = std::max({extent.x, extent.y, extent.z});
    return longest > 0.0f ? longest : 1.0f;
}

std::array<int, 3> auto_grid_cells(glm::vec3 extent) {
    const float longest = longest_side(extent);
    // A small scene's extent scaled by a power of two (exact) so that the volume below does not
    // underflow float; scenes longer than 1/1024 are taken as they are.
    const int shift = longest < 0x1p-10f ? -std::ilogb(longest) : 0;
    const glm::vec3 e = glm::max(extent, glm::vec3(1e-3f * longest)) * std::ldexp(1.0f, shift);
    // Cubic cells of the size that gives about kAutoGridVertices vertices, grown until it does.
    float cell = std::cbrt(e.x * e.y * e.z / static_cast<float>(kAutoGridVertices));
    std::array<int, 3> cells{};
    for (int attempt = 0; attempt < 1000; ++attempt) {
        for (int axis = 0; axis < 3; ++axis) {
            cells[axis] = std::max(2, static_cast<int>(std::ceil(e[axis] / cell)));
        }
        if (vertex_count(cells) <= static_cast<size_t>(kAutoGridVertices)) {
            break;
        }
        cell *= 1.02f;
    }
    return cells;
}

IrradianceVectorGrid::IrradianceVectorGrid(const FrameScene& frame)
    : FrameBound(frame),
      frame_(frame),
      trace_kernel_(frame.context.kernel("irradiance_vector_grid/irradiance_vector_grid.cl",
                                         "ivg_trace_photons")),
      deposit_kernel_(frame.context.kernel("irradiance_vector_grid/irradiance_vector_grid.cl",
                                           "ivg_deposit_segments")),
      normalize_kernel_(frame.context.kernel("irradiance_vector_grid/irradiance_vector_grid.cl",
                                             "ivg_normalize")),
      lookup_kernel_(
          frame.context.kernel("irradiance_vector_grid/irradiance_vector_grid.cl", "ivg_lookup")),
      values_(frame.context, 1, "ivg_values"),
      packed_(frame.context, 1, "ivg_packed"),
      cell_planes_(frame.context, 1, "ivg_cell_planes"),
      planes_(frame.context, 1, "ivg_planes") {}

namespace {

// The scene's bounding box at its frame (the origin alone when it has no vertex).
void scene_bounds(const Scene& scene, glm::vec3* lower, glm::vec3* upper) {
    *lower = *upper = glm::vec3(0.0f);
    if (!scene.mesh.positions.empty()) {
        *lower = *upper = scene.mesh.positions[0];
        for (const glm::vec3& p : scene.mesh.positions) {
            *lower = glm::min(*lower, p);
            *upper = glm::max(*upper, p);
        }
    }
}

// The voxels per axis of the grid: the options', else auto's for the scene's box.
std::array<int, 3> grid_cells(const IvgOptions& options, glm::vec3 extent) {
    return options.cells[0] > 0 ? options.cells : auto_grid_cells(extent);
}

}  // namespace

DeviceMemoryNeed with_grid_need(const IvgOptions& options, const Scene& scene,
                                DeviceMemoryNeed after) {
    const IvgDeviceNeed grid = ivg_device_need(options, scene);
    after.add_all(grid.built);
    return peak_of(grid.building, after);
}

IvgDeviceNeed ivg_device_need(const IvgOptions& options, const Scene& scene) {
    IvgDeviceNeed need;
    if (!options.grid_in.empty()) {
        need.built.excludes = "the grid of --grid-in";
        return need;
    }
    glm::vec3 lower;
    glm::vec3 upper;
    scene_bounds(scene, &lower, &upper);
    const size_t values =
        vertex_count(grid_cells(options, upper - lower)) * RC_IVG_VALUES_PER_VERTEX;
    // IrradianceVectorGrid's placeholders, then build(): accum, counters and the normalised
    // values together; then upload_values(): the values and the compressed copy.
    need.building.add("grid placeholders", sizeof(float) + sizeof(uint16_t) +
                                               sizeof(shared::IvgCellPlanes) +
                                               sizeof(shared::IvgPlane));
    need.building.add("grid sums", buffer_bytes(values, sizeof(int64_t)));
    need.building.add("grid counters", buffer_bytes(2, sizeof(unsigned)));
    need.building.add("grid values", buffer_bytes(values, sizeof(float)));
    need.built.add("grid values", buffer_bytes(values, sizeof(float)));
    need.built.add("grid compressed",
                   options.compressed
                       ? buffer_bytes(values / RC_IVG_VALUES_PER_VERTEX * RC_IVG_PACKED_PER_VERTEX,
                                      sizeof(uint16_t))
                       : sizeof(uint16_t));
    // The cells' planes (ivg_cell_planes.h): two indices per cell, at most two planes per cell
    // or triangle.
    const std::array<int, 3> cells = grid_cells(options, upper - lower);
    const size_t cell_count = static_cast<size_t>(cells[0]) * cells[1] * cells[2];
    need.built.add("grid cell planes", buffer_bytes(cell_count, sizeof(shared::IvgCellPlanes)));
    need.built.add("grid planes",
                   buffer_bytes(2 * std::min(cell_count, scene.mesh.triangle_count()),
                                sizeof(shared::IvgPlane)));
    return need;
}

shared::IvgParams IrradianceVectorGrid::layout(const IvgOptions& options) const {
    glm::vec3 lower;
    glm::vec3 upper;
    scene_bounds(scene_, &lower, &upper);
    const glm::vec3 extent = upper - lower;
    const std::array<int, 3> cells = grid_cells(options, extent);
    shared::IvgParams p{};
    // The grid's faces lie on the scene's bounding box, so walls there lie on grid planes and
    // their vertices get the photons that reach them (rc_ivg_deposit_segment).
    const float longest = longest_side(extent);
    glm::vec3 cell;
    for (int axis = 0; axis < 3; ++axis) {
        cell[axis] = std::max(extent[axis], 1e-3f * longest) / static_cast<float>(cells[axis]);
    }
    const glm::vec3 centre = 0.5f * (lower + upper);
    const float radius = 0.5f * glm::length(glm::vec3(cells[0], cells[1], cells[2]) * cell);
    p.origin = {lower.x, lower.y, lower.z, 0.0f};
    p.cell = {cell.x, cell.y, cell.z, 0.0f};
    p.min_cosine = kSmallestCosine;
    p.sphere_centre = {centre.x, centre.y, centre.z, 0.0f};
    p.sphere_radius = radius;
    p.cells = {cells[0], cells[1], cells[2], 0};
    p.vertex_count = static_cast<int>(vertex_count(cells));
    // The deposit's fixed-point units per unit of flux, as a float times a power of two: at a
    // small scale (a 1e-15 Cornell box's light carries 3e-31) the units leave float's range.
    const float flux = largest_photon_flux(scene_, p.sphere_radius);
    const double units = flux > 0.0f ? kLargestAmount * kSmallestCosine / flux : 1.0;
    p.fixed_point_scale = static_cast<float>(std::frexp(units, &p.fixed_point_exponent));
    p.include_direct = options.include_direct ? 1 : 0;
    set_kernel_path_settings(options, &p);
    p.camera_spp = 1;
    p.light_samples = 1;
    p.interpolation = options.interpolation;
    p.compressed = options.compressed ? 1 : 0;
    return p;
}

void IrradianceVectorGrid::trace_photons(uint64_t photons, Buffer<int64_t>& accum,
                                         Buffer<unsigned>& counters, IvgStats* stats) {
    if (frame_.peers != nullptr && !frame_.peers->empty()) {
        trace_photons_split(photons, accum, stats);
        return;
    }
    const SceneArguments scene(bvh_, device_scene_);
    for (uint64_t first = 0; first < photons; first += kPhotonsPerLaunch) {
        shared::IvgParams launch = params_;
        launch.first_photon = static_cast<unsigned>(first);
        counters.fill_zero();
        context_.launch(trace_kernel_, std::min(kPhotonsPerLaunch, photons - first), launch, scene,
                        accum, counters);
        const std::vector<unsigned> counted = counters.download();
        stats->crossings += counted[0];
        stats->rays += counted[1];
    }
}

void IrradianceVectorGrid::build(const IvgOptions& options, IvgStats* stats) {
    IvgStats s;
    params_ = layout(options);
    const std::array<int, 3> cells = {params_.cells.x, params_.cells.y, params_.cells.z};
    const size_t vertices = vertex_count(cells);
    std::vector<float> values;
    if (!options.grid_in.empty()) {
        const auto start = SteadyClock::now();
        const GridFile file = read_grid_file(options.grid_in, scene_);
        check_grid_file(file, options, options.grid_in.string());
        params_.origin = {file.origin.x, file.origin.y, file.origin.z, 0.0f};
        params_.cell = {file.cell.x, file.cell.y, file.cell.z, 0.0f};
        params_.cells = {file.cells[0], file.cells[1], file.cells[2], 0};
        params_.vertex_count = static_cast<int>(vertex_count(file.cells));
        params_.photon_count = static_cast<unsigned>(std::min<uint64_t>(file.photons, kMaxPhotons));
        values = file.values;
        s.loaded = true;
        s.photons = file.photons;
        s.normalize_seconds += seconds_since(start);
    } else {
        const uint64_t photons =
            options.photons > 0 ? options.photons : kAutoPhotonsPerVertex * vertices;
        if (photons > kMaxPhotons) {
            throw Error("--photons: at most " + std::to_string(kMaxPhotons) + " photons, asked " +
                            std::to_string(photons),
                        kExitUsage);
        }
        params_.photon_count = static_cast<unsigned>(photons);
        auto start = SteadyClock::now();
        Buffer<int64_t> accum(context_, vertices * RC_IVG_VALUES_PER_VERTEX, "ivg_accum");
        accum.fill_zero();
        Buffer<unsigned> counters(context_, 2, "ivg_counters");
        trace_photons(photons, accum, counters, &s);
        s.photons = photons;
        context_.finish();
        s.trace_seconds = seconds_since(start);
        start = SteadyClock::now();
        Buffer<float> normalized(context_, vertices * RC_IVG_VALUES_PER_VERTEX, "ivg_values");
        context_.launch(normalize_kernel_, vertices, params_, accum, normalized);
        values = normalized.download();
        s.normalize_seconds += seconds_since(start);
        if (!options.grid_out.empty()) {
            const auto write_start = SteadyClock::now();
            GridFile file;
            file.cells = cells;
            file.origin = {params_.origin.x, params_.origin.y, params_.origin.z};
            file.cell = {params_.cell.x, params_.cell.y, params_.cell.z};
            file.photons = photons;
            file.include_direct = options.include_direct;
            file.max_depth = options.max_depth;
            file.values = values;
            write_grid_file(options.grid_out, scene_, file);
            s.normalize_seconds += seconds_since(write_start);
        }
    }
    const auto start = SteadyClock::now();
    upload_values(values);
    s.normalize_seconds += seconds_since(start);
    upload_cell_planes(&s);
    s.cells = {params_.cells.x, params_.cells.y, params_.cells.z};
    s.grid_bytes = values_.bytes() + (options.compressed ? packed_.bytes() : 0);
    if (stats != nullptr) {
        *stats = s;
    }
}

void IrradianceVectorGrid::upload_values(const std::vector<float>& values) {
    const size_t vertices = static_cast<size_t>(params_.vertex_count);
    if (values.size() != vertices * RC_IVG_VALUES_PER_VERTEX) {
        throw Error("irradiance vector grid: " + std::to_string(values.size()) +
                    " values for a grid of " + std::to_string(vertices) + " vertices");
    }
    values_ = Buffer<float>(context_, values, "ivg_values");
    // The compressed layout (§4.2): per vertex and direction, |I_r|, |I_g|, |I_b| and the unit
    // direction of I_r + I_g + I_b, as half floats.
    std::vector<uint16_t> packed(params_.compressed != 0 ? vertices * RC_IVG_PACKED_PER_VERTEX : 1,
                                 0);
    if (params_.compressed != 0) {
        for (size_t slot = 0; slot < vertices * 6; ++slot) {
            const float* v = values.data() + slot * 9;
            glm::vec3 channel[3];
            for (int c = 0; c < 3; ++c) {
                channel[c] = glm::vec3(v[3 * c], v[3 * c + 1], v[3 * c + 2]);
            }
            const glm::vec3 sum = channel[0] + channel[1] + channel[2];
            const float length = glm::length(sum);
            const glm::vec3 unit = length > 0.0f ? sum / length : glm::vec3(0.0f);
            const float fields[6] = {glm::length(channel[0]),
                                     glm::length(channel[1]),
                                     glm::length(channel[2]),
                                     unit.x,
                                     unit.y,
                                     unit.z};
            for (int f = 0; f < 6; ++f) {
                packed[slot * 6 + f] = Imath::half(fields[f]).bits();
            }
        }
    }
    packed_ = Buffer<uint16_t>(context_, packed, "ivg_packed");
}

void IrradianceVectorGrid::upload_cell_planes(IvgStats* stats) {
    const auto start = SteadyClock::now();
    const IvgCellPlanes classified = classify_cell_planes(scene_.mesh, params_);
    if (classified.skipped_triangles > 0) {
        log_warning("irradiance vector grid: " + std::to_string(classified.skipped_triangles) +
                    " triangle(s) left out of the cells' planes after " +
                    std::to_string(classified.box_tests) +
                    " triangle-box tests (the bound); the cells they reach trace every shadow ray");
    }
    params_.cell_margin = classified.cell_margin;
    params_.origin_margin = classified.origin_margin;
    cell_planes_ =
        Buffer<shared::IvgCellPlanes>(context_, classified.cell_planes, "ivg_cell_planes");
    planes_ = Buffer<shared::IvgPlane>(
        context_, classified.planes.empty() ? std::vector<shared::IvgPlane>(1) : classified.planes,
        "ivg_planes");
    stats->empty_cells = classified.empty_cells;
    stats->unsupported_cells = classified.unsupported_cells;
    stats->plane_cells =
        classified.cell_planes.size() - classified.empty_cells - classified.unsupported_cells;
    stats->planes = classified.planes.size();
    stats->planes_seconds = seconds_since(start);
}

unsigned IrradianceVectorGrid::set_kernel_args(Kernel& kernel, unsigned first) const {
    kernel.set_arg(first, sizeof params_, &params_);
    _cl_mem* values = values_.handle();
    kernel.set_arg(first + 1, sizeof values, &values);
    _cl_mem* packed = packed_.handle();
    kernel.set_arg(first + 2, sizeof packed, &packed);
    _cl_mem* cell_planes = cell_planes_.handle();
    kernel.set_arg(first + 3, sizeof cell_planes, &cell_planes);
    _cl_mem* planes = planes_.handle();
    kernel.set_arg(first + 4, sizeof planes, &planes);
    return 5;
}

std::vector<float> IrradianceVectorGrid::values() const { return values_.download(); }

void IrradianceVectorGrid::set_values(const std::vector<float>& values) {
    upload_values(values);
    IvgStats ignored;
    upload_cell_planes(&ignored);
}

std::vector<int64_t> IrradianceVectorGrid::deposit(const shared::IvgParams& params,
                                                   const std::vector<PhotonSegment>& segments) {
    const size_t vertices = static_cast<size_t>(params.vertex_count);
    Buffer<int64_t> accum(context_, vertices * RC_IVG_VALUES_PER_VERTEX, "ivg_accum");
    accum.fill_zero();
    std::vector<shared::float4> from(segments.size());
    std::vector<shared::float4> to(segments.size());
    std::vector<shared::float4> flux(segments.size());
    for (size_t i = 0; i < segments.size(); ++i) {
        from[i] = {segments[i].from.x, segments[i].from.y, segments[i].from.z, 0.0f};
        to[i] = {segments[i].to.x, segments[i].to.y, segments[i].to.z, 0.0f};
        flux[i] = {segments[i].flux.x, segments[i].flux.y, segments[i].flux.z, 0.0f};
    }
    const Buffer<shared::float4> from_buffer(context_, from, "ivg_segment_from");
    const Buffer<shared::float4> to_buffer(context_, to, "ivg_segment_to");
    const Buffer<shared::float4> flux_buffer(context_, flux, "ivg_segment_flux");
    context_.launch(deposit_kernel_, segments.size(), params, from_buffer, to_buffer, flux_buffer,
                    accum);
    return accum.download();
}

std::vector<float> IrradianceVectorGrid::normalize(const shared::IvgParams& params,
                                                   const std::vector<int64_t>& accum) {
    const size_t vertices = static_cast<size_t>(params.vertex_count);
    const Buffer<int64_t> sums(context_, accum, "ivg_accum");
    Buffer<float> normalized(context_, vertices * RC_IVG_VALUES_PER_VERTEX, "ivg_values");
    context_.launch(normalize_kernel_, vertices, params, sums, normalized);
    return normalized.download();
}

std::vector<glm::vec3> IrradianceVectorGrid::lookup(const std::vector<glm::vec3>& positions,
                                                    const std::vector<glm::vec3>& normals) {
    std::vector<shared::float4> p(positions.size());
    std::vector<shared::float4> n(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        p[i] = {positions[i].x, positions[i].y, positions[i].z, 0.0f};
        n[i] = {normals[i].x, normals[i].y, normals[i].z, 0.0f};
    }
    const Buffer<shared::float4> position_buffer(context_, p, "ivg_lookup_positions");
    const Buffer<shared::float4> normal_buffer(context_, n, "ivg_lookup_normals");
    Buffer<shared::float4> out(context_, positions.size(), "ivg_lookup_out");
    context_.launch(lookup_kernel_, positions.size(), params_, values_, packed_, position_buffer,
                    normal_buffer, out);
    std::vector<glm::vec3> result;
    for (const shared::float4& e : out.download()) {
        result.emplace_back(e.x, e.y, e.z);
    }
    return result;
}

}  // namespace rc
