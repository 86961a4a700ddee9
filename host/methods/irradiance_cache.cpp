#include "methods/irradiance_cache.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <regex>
#include <unordered_map>

#include "methods/irradiance_cache_file.h"
#include "methods/scene_arguments.h"
#include "scene/camera.h"
#include "util/error.h"

namespace rc {

const char* const kIrradianceCacheAovs[7] = {"beauty", "direct",   "indirect", "albedo",
                                             "normal", "coverage", "records"};

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr size_t kFilmSlots = 7;      // float4 per pixel (kernels/irradiance_cache.cl)
constexpr float kMaxWeight = 1.0e4f;  // weight cap near a record's centre
constexpr size_t kMaxBatchCells = size_t{1} << 23;  // hemisphere cells per record launch
constexpr int kFinestPasses = 16;  // passes at stride 1 before every sample is covered

shared::float4 float4_of(glm::vec3 v, float w = 0.0f) { return {v.x, v.y, v.z, w}; }
glm::vec3 vec3_of(const shared::float4& v) { return {v.x, v.y, v.z}; }

// The device copy of a record store: records and their grid.
struct DeviceRecords {
    DeviceRecords(Context& context, const RecordStore& store) {
        const RecordGridData data = store.build_grid();
        grid = data.grid;
        records = Buffer<shared::IrradianceRecord>(context, store.device_records(), "ic_records");
        cell_start = Buffer<int>(context, data.cell_start, "ic_cell_start");
        cell_records = Buffer<int>(context, data.cell_records, "ic_cell_records");
    }
    size_t bytes() const { return records.bytes() + cell_start.bytes() + cell_records.bytes(); }

    shared::RecordGrid grid{};
    Buffer<shared::IrradianceRecord> records;
    Buffer<int> cell_start;
    Buffer<int> cell_records;
};

// Keeps, in order, the candidates farther than their minimum influence radius from the ones
// kept before (with similar normals): one batch then places no two records where one would do.
std::vector<size_t> thin_candidates(const std::vector<shared::GBufferSample>& gbuffer,
                                    const std::vector<size_t>& candidates,
                                    const std::vector<float>& min_influence) {
    float cell = 0.0f;
    for (float r : min_influence) {
        cell = std::max(cell, r);
    }
    if (!(cell > 0.0f)) {
        return candidates;
    }
    std::unordered_map<long long, std::vector<size_t>> kept_in_cell;
    auto key = [](long long x, long long y, long long z) {
        return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
    };
    std::vector<size_t> kept;
    for (size_t c = 0; c < candidates.size(); ++c) {
        const shared::GBufferSample& g = gbuffer[candidates[c]];
        const glm::vec3 p = vec3_of(g.position);
        const glm::vec3 n = vec3_of(g.normal);
        const long long cx = static_cast<long long>(std::floor(p.x / cell));
        const long long cy = static_cast<long long>(std::floor(p.y / cell));
        const long long cz = static_cast<long long>(std::floor(p.z / cell));
        bool near = false;
        for (long long dz = -1; dz <= 1 && !near; ++dz) {
            for (long long dy = -1; dy <= 1 && !near; ++dy) {
                for (long long dx = -1; dx <= 1 && !near; ++dx) {
                    const auto found = kept_in_cell.find(key(cx + dx, cy + dy, cz + dz));
                    if (found == kept_in_cell.end()) {
                        continue;
                    }
                    for (size_t other : found->second) {
                        const shared::GBufferSample& o = gbuffer[candidates[other]];
                        const float d = glm::length(p - vec3_of(o.position));
                        if (d < std::max(min_influence[c], min_influence[other]) &&
                            glm::dot(n, vec3_of(o.normal)) > 0.9f) {
                            near = true;
                            break;
                        }
                    }
                }
            }
        }
        if (!near) {
            kept_in_cell[key(cx, cy, cz)].push_back(c);
            kept.push_back(candidates[c]);
        }
    }
    return kept;
}

}  // namespace

Spacing parse_spacing(const std::string& text, const std::string& option) {
    static const std::regex form(R"(^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(px|u)?\s*$)");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw Error(option +
                        ": expected a length in pixels (\"4\", \"4px\") or scene units "
                        "(\"0.5u\"), got '" +
                        text + "'",
                    kExitUsage);
    }
    Spacing spacing;
    spacing.value = std::stof(match[1].str());
    spacing.world = match[2].str() == "u";
    if (!(spacing.value > 0.0f) || !std::isfinite(spacing.value)) {
        throw Error(option + ": must be positive, got '" + text + "'", kExitUsage);
    }
    return spacing;
}

RecordSampling strata_for(int rays) {
    RecordSampling sampling;
    const double pi = 3.14159265358979;
    sampling.m = std::max(1, static_cast<int>(std::lround(std::sqrt(rays / pi))));
    sampling.n = std::max(1, static_cast<int>(std::lround(static_cast<double>(rays) / sampling.m)));
    return sampling;
}

IrradianceCache::IrradianceCache(Context& context, const Scene& scene, const DeviceBvh& bvh,
                                 const DeviceScene& device_scene)
    : context_(context),
      scene_(scene),
      bvh_(bvh),
      device_scene_(device_scene),
      gbuffer_kernel_(context.kernel("irradiance_cache.cl", "ic_gbuffer")),
      cells_kernel_(context.kernel("irradiance_cache.cl", "ic_record_cells")),
      reduce_kernel_(context.kernel("irradiance_cache.cl", "ic_record_reduce")),
      gather_kernel_(context.kernel("irradiance_cache.cl", "ic_gather")),
      shade_kernel_(context.kernel("irradiance_cache.cl", "ic_shade")) {}

std::vector<CacheRecord> IrradianceCache::compute_records(const std::vector<RecordSite>& sites,
                                                          uint32_t first_index,
                                                          const RecordSampling& sampling,
                                                          uint64_t* rays) {
    std::vector<CacheRecord> computed;
    computed.reserve(sites.size());
    const size_t per_record = static_cast<size_t>(sampling.m) * sampling.n;
    const size_t batch_limit = std::max<size_t>(1, kMaxBatchCells / per_record);
    const SceneArguments scene(bvh_, device_scene_);
    Buffer<unsigned> counters(context_, 1, "ic_record_counters");
    for (size_t begin = 0; begin < sites.size(); begin += batch_limit) {
        const size_t count = std::min(batch_limit, sites.size() - begin);
        std::vector<shared::IrradianceRecord> records(count);
        std::vector<shared::float4> origins(count);
        for (size_t b = 0; b < count; ++b) {
            const RecordSite& site = sites[begin + b];
            records[b].position = float4_of(site.position);
            records[b].normal = float4_of(site.normal);
            origins[b] = float4_of(site.origin);
        }
        Buffer<shared::IrradianceRecord> record_buffer(context_, records, "ic_batch_records");
        const Buffer<shared::float4> origin_buffer(context_, origins, "ic_batch_origins");
        Buffer<shared::float4> cells(context_, count * per_record, "ic_cells");
        Buffer<shared::float4> distances(context_, count, "ic_distances");
        counters.fill_zero();
        shared::IcParams params{};
        params.sampling = {sampling.m, sampling.n, static_cast<int>(first_index + begin),
                           sampling.include_emission ? 1 : 0};
        params.depth = {sampling.max_depth, sampling.rr_depth, 0, 0};
        params.seed = {static_cast<unsigned>(sampling.seed),
                       static_cast<unsigned>(sampling.seed >> 32), 0, 0};
        context_.launch(cells_kernel_, count * per_record, params, scene, record_buffer,
                        origin_buffer, cells, counters);
        context_.launch(reduce_kernel_, count, params, cells, record_buffer, distances);
        const std::vector<shared::IrradianceRecord> result = record_buffer.download();
        const std::vector<shared::float4> distance = distances.download();
        if (rays != nullptr) {
            *rays += counters.download()[0];
        }
        for (size_t b = 0; b < count; ++b) {
            const RecordSite& site = sites[begin + b];
            CacheRecord r;
            r.position = site.position;
            r.normal = site.normal;
            r.irradiance = vec3_of(result[b].irradiance);
            r.rotation[0] = vec3_of(result[b].rotation_r);
            r.rotation[1] = vec3_of(result[b].rotation_g);
            r.rotation[2] = vec3_of(result[b].rotation_b);
            r.translation[0] = vec3_of(result[b].translation_r);
            r.translation[1] = vec3_of(result[b].translation_g);
            r.translation[2] = vec3_of(result[b].translation_b);
            r.harmonic_distance = distance[b].x;
            r.min_distance = distance[b].y;
            r.r_min = site.r_min;
            r.r_max = site.r_max;
            computed.push_back(r);
        }
    }
    return computed;
}

std::vector<shared::float4> IrradianceCache::gather(
    const RecordStore& store, const std::vector<shared::GBufferSample>& queries) {
    const DeviceRecords records(context_, store);
    const Buffer<shared::GBufferSample> samples(context_, queries, "ic_queries");
    std::vector<int> indices(queries.size());
    for (size_t i = 0; i < indices.size(); ++i) {
        indices[i] = static_cast<int>(i);
    }
    const Buffer<int> index_buffer(context_, indices, "ic_query_indices");
    Buffer<shared::float4> out(context_, queries.size(), "ic_gathered");
    shared::IcParams params{};
    params.weights = {store.accuracy(), kMaxWeight, 0.0f, 0.0f};
    context_.launch(gather_kernel_, queries.size(), params, records.grid, records.cell_start,
                    records.cell_records, records.records, samples, index_buffer, out);
    return out.download();
}

Image IrradianceCache::render(const IrradianceCacheOptions& options, IrradianceCacheStats* stats) {
    IrradianceCacheStats result;
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    const size_t pixels = static_cast<size_t>(width) * height;
    const size_t samples = pixels * static_cast<size_t>(options.spp);
    if (options.spp < 1) {
        throw Error("irradiance caching needs at least one camera sample per pixel", kExitUsage);
    }
    if (!(options.accuracy > 0.0f && options.accuracy <= 1.0f)) {
        throw Error("--accuracy must lie in (0, 1], got " + std::to_string(options.accuracy),
                    kExitUsage);
    }
    if (options.min_spacing.world == options.max_spacing.world &&
        options.min_spacing.value > options.max_spacing.value) {
        throw Error("--ic-min-spacing exceeds --ic-max-spacing", kExitUsage);
    }
    if (options.bounces != 1) {
        throw Error("--ic-bounces " + std::to_string(options.bounces) +
                        ": only 1 is implemented (deeper bounces by path tracing)",
                    kExitUsage);
    }
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    const SceneArguments scene(bvh_, device_scene_);
    shared::IcParams params{};
    params.image = {width, height, options.spp, 0};
    params.depth = {options.max_depth, options.rr_depth, 0, 0};
    params.seed = {static_cast<unsigned>(options.seed), static_cast<unsigned>(options.seed >> 32),
                   0, 0};
    params.weights = {options.accuracy, kMaxWeight, 0.0f, 0.0f};

    // 1. G-buffer.
    auto start = Clock::now();
    Buffer<shared::GBufferSample> gbuffer_buffer(context_, samples, "ic_gbuffer");
    context_.launch(gbuffer_kernel_, samples, params, camera, scene, gbuffer_buffer);
    const std::vector<shared::GBufferSample> gbuffer = gbuffer_buffer.download();
    result.gbuffer_seconds = seconds_since(start);

    // 2.-4. Placement, coarse to fine, with record computation and insertion.
    store_ = RecordStore(options.accuracy);
    if (!options.cache_in.empty()) {
        store_.restore(read_irradiance_cache(options.cache_in, scene_, options.accuracy));
        result.loaded_records = store_.size();
    }
    RecordSampling sampling = strata_for(options.rays);
    sampling.max_depth = options.max_depth;
    sampling.rr_depth = options.rr_depth;
    sampling.seed = options.seed;
    result.strata_m = sampling.m;
    result.strata_n = sampling.n;
    auto bound = [&](const Spacing& spacing, float footprint) {
        return (spacing.world ? spacing.value : spacing.value * footprint) / options.accuracy;
    };
    for (int stride : {16, 8, 4, 2, 1}) {
        std::vector<size_t> candidates;
        for (size_t p = 0; p < pixels; ++p) {
            const int x = static_cast<int>(p % width);
            const int y = static_cast<int>(p / width);
            if (x % stride != 0 || y % stride != 0) {
                continue;
            }
            const int sample_count = stride == 1 ? options.spp : 1;
            for (int s = 0; s < sample_count; ++s) {
                const size_t i = p * options.spp + s;
                if (gbuffer[i].info.w != 0) {
                    candidates.push_back(i);
                }
            }
        }
        for (int pass = 0; pass < (stride == 1 ? kFinestPasses : 1) && !candidates.empty();
             ++pass) {
            start = Clock::now();
            std::vector<size_t> uncovered;
            if (store_.size() == 0) {
                uncovered = candidates;
            } else {
                const DeviceRecords records(context_, store_);
                std::vector<int> queries(candidates.begin(), candidates.end());
                const Buffer<int> query_buffer(context_, queries, "ic_candidates");
                Buffer<shared::float4> coverage(context_, queries.size(), "ic_coverage");
                context_.launch(gather_kernel_, queries.size(), params, records.grid,
                                records.cell_start, records.cell_records, records.records,
                                gbuffer_buffer, query_buffer, coverage);
                const std::vector<shared::float4> covered = coverage.download();
                for (size_t c = 0; c < candidates.size(); ++c) {
                    if (!(covered[c].w > 0.0f)) {
                        uncovered.push_back(candidates[c]);
                    }
                }
            }
            candidates = uncovered;
            std::vector<float> min_influence(uncovered.size());
            for (size_t c = 0; c < uncovered.size(); ++c) {
                min_influence[c] =
                    options.accuracy * bound(options.min_spacing, gbuffer[uncovered[c]].position.w);
            }
            const std::vector<size_t> chosen = thin_candidates(gbuffer, uncovered, min_influence);
            result.placement_seconds += seconds_since(start);
            if (chosen.empty()) {
                break;
            }
            start = Clock::now();
            std::vector<RecordSite> sites;
            sites.reserve(chosen.size());
            for (size_t i : chosen) {
                const shared::GBufferSample& g = gbuffer[i];
                RecordSite site;
                site.position = vec3_of(g.position);
                site.normal = vec3_of(g.normal);
                site.origin = vec3_of(g.origin);
                site.r_min = bound(options.min_spacing, g.position.w);
                site.r_max = std::max(site.r_min, bound(options.max_spacing, g.position.w));
                sites.push_back(site);
            }
            const std::vector<CacheRecord> computed = compute_records(
                sites, static_cast<uint32_t>(store_.size()), sampling, &result.record_rays);
            result.record_seconds += seconds_since(start);
            start = Clock::now();
            for (const CacheRecord& record : computed) {
                store_.insert(record);
            }
            result.insertion_seconds += seconds_since(start);
            result.level_strides.push_back(stride);
            result.level_records.push_back(computed.size());
        }
    }
    result.records = store_.size();
    if (!options.cache_out.empty()) {
        write_irradiance_cache(options.cache_out, scene_, store_);
    }

    // 5. Shading.
    start = Clock::now();
    const DeviceRecords records(context_, store_);
    result.cache_bytes = records.bytes();
    result.insertion_seconds += seconds_since(start);
    start = Clock::now();
    params.image.w = static_cast<int>(store_.size());
    Buffer<shared::float4> film(context_, pixels * kFilmSlots, "ic_film");
    Buffer<unsigned> counters(context_, 3, "ic_counters");
    counters.upload({0u, 0u, 0xffffffffu});
    context_.launch(shade_kernel_, pixels, params, camera, scene, records.grid, records.cell_start,
                    records.cell_records, records.records, film, counters);
    const std::vector<shared::float4> sums = film.download();
    const std::vector<unsigned> c = counters.download();
    result.shading_rays = c[0];
    result.nonfinite_samples = c[1];
    result.first_nonfinite_pixel = c[1] > 0 ? static_cast<int64_t>(c[2]) : -1;
    result.shading_seconds = seconds_since(start);

    Image image(width, height, 19);
    image.channel_names = {"R",          "G",          "B",          "direct.R",   "direct.G",
                           "direct.B",   "indirect.R", "indirect.G", "indirect.B", "albedo.R",
                           "albedo.G",   "albedo.B",   "normal.R",   "normal.G",   "normal.B",
                           "coverage.Y", "records.R",  "records.G",  "records.B"};
    for (size_t p = 0; p < pixels; ++p) {
        const shared::float4* s = &sums[kFilmSlots * p];
        float* out = &image.pixels[p * 19];
        for (int k = 0; k < 5; ++k) {
            out[3 * k + 0] = s[k].x;
            out[3 * k + 1] = s[k].y;
            out[3 * k + 2] = s[k].z;
        }
        out[15] = s[5].x;
        out[16] = s[6].x;
        out[17] = s[6].y;
        out[18] = s[6].z;
    }
    if (stats != nullptr) {
        *stats = result;
    }
    return image;
}

}  // namespace rc
