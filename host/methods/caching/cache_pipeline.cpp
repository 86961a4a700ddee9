#include "methods/caching/cache_pipeline.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <utility>

#include "image/film.h"
#include "methods/caching/cache_file.h"
#include "methods/caching/device_splat.h"
#include "methods/caching/placement_passes.h"
#include "methods/caching/record_level_source.h"
#include "methods/caching/splat_tiles.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "scene/camera.h"
#include "scene/mesh_bounds.h"
#include "shared/film.h"
#include "util/error.h"
#include "util/glm_helpers.h"
#include "util/log.h"
#include "util/number_with_unit.h"
#include "util/timing.h"

namespace rc {

const char* const kCachePipelineAovs[7] = {"beauty", "direct",   "indirect", "albedo",
                                           "normal", "coverage", "records"};

namespace {

constexpr size_t kMaxBatchCells = size_t{1} << 23;  // hemisphere cells per record launch

}  // namespace

Spacing parse_spacing(const std::string& text, const std::string& option) {
    const NumberWithUnit number = parse_number_with_unit(
        option, text, "px|u", "a length in pixels (\"4\", \"4px\") or scene units (\"0.5u\")");
    Spacing spacing;
    spacing.value = number.value;
    spacing.world = number.unit == "u";
    if (!(spacing.value > 0.0f) || !std::isfinite(spacing.value)) {
        throw Error(option + ": must be positive, got '" + text + "'", kExitUsage);
    }
    return spacing;
}

float spacing_bound(const Spacing& spacing, float footprint) {
    return spacing.world ? spacing.value : spacing.value * footprint;
}

RecordSampling strata_for(int rays) {
    RecordSampling sampling;
    const double pi = 3.14159265358979;
    sampling.m = std::max(1, static_cast<int>(std::lround(std::sqrt(rays / pi))));
    sampling.n = std::max(1, static_cast<int>(std::lround(static_cast<double>(rays) / sampling.m)));
    sampling.deeper_m = sampling.m;
    sampling.deeper_n = sampling.n;
    return sampling;
}

CachePipeline::CachePipeline(const FrameScene& frame, PipelinePlugins plugins)
    : FrameBound(frame),
      gbuffer_kernel_(frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_gbuffer")),
      hits_kernel_(frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_record_hits")),
      reduce_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_record_reduce")),
      gather_kernel_(frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_gather")),
      splat_kernel_(frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_splat")),
      tile_depths_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_tile_depths")),
      uncovered_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_uncovered")),
      select_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_gbuffer_select")),
      shade_kernel_(frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_shade")),
      records_used_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_records_used")),
      plugins_(std::move(plugins)) {
    if (frame.peers != nullptr && !frame.peers->empty()) {
        split_ = std::make_unique<PipelineDeviceSplit>(frame);
    }
    // The smallest record radius: a millionth of the scene's extent, some ten float steps at its
    // far end. Below it (a camera whose pixel is narrower, "fov": 1e-30) a record's weight would
    // divide by a radius that float precision cannot tell from zero.
    smallest_radius_ = 1e-6f * mesh_diagonal(frame.scene.mesh);
}

void CachePipeline::reset(const RecordSampling& sampling) {
    if (sampling.levels < 1 || sampling.m < 1 || sampling.n < 1 || sampling.deeper_m < 1 ||
        sampling.deeper_n < 1) {
        throw Error("irradiance cache: needs at least one level and one hemisphere stratum",
                    kExitUsage);
    }
    sampling_ = sampling;
    stores_.assign(static_cast<size_t>(sampling.levels), irradiance_store(sampling.accuracy));
    next_streams_.assign(stores_.size(), 0);
    restart_stats();
}

void CachePipeline::restart_stats() {
    stats_ = PipelineStats{};
    stats_.strata_m = sampling_.m;
    stats_.strata_n = sampling_.n;
    stats_.deeper_strata_m = sampling_.deeper_m;
    stats_.deeper_strata_n = sampling_.deeper_n;
}

Kernel& CachePipeline::cells_kernel(const RadianceSource& source) {
    return source_kernel(context_, &cells_kernels_, "irradiance_cache/ic_record_cells.cl",
                         "ic_record_cells", source);
}

shared::IcParams CachePipeline::level_params(int level) const {
    shared::IcParams params{};
    params.width = width_;
    params.height = height_;
    params.camera_spp = camera_spp_;
    params.first_sample = first_sample_;
    params.strata_m = level == 0 ? sampling_.m : sampling_.deeper_m;
    params.strata_n = level == 0 ? sampling_.n : sampling_.deeper_n;
    params.count_emission = sampling_.include_emission ? 1 : 0;
    set_kernel_path_settings(sampling_, &params);
    params.level = level;
    params.light_samples = 1;
    params.accuracy = sampling_.accuracy;
    params.max_weight = kRecordMaxWeight;
    return params;
}

std::vector<ComputedRecord> CachePipeline::compute_records(const std::vector<RecordSite>& sites,
                                                           uint32_t first_index,
                                                           const RecordSampling& sampling,
                                                           uint64_t* rays) {
    reset(sampling);
    next_streams_[0] = first_index;
    std::vector<ComputedRecord> computed = compute_level(0, sites);
    if (rays != nullptr) {
        *rays += stats_.record_rays;
    }
    return computed;
}

std::vector<ComputedRecord> CachePipeline::compute_level(int level,
                                                         const std::vector<RecordSite>& sites) {
    std::vector<ComputedRecord> computed;
    computed.reserve(sites.size());
    const bool cached = level + 1 < sampling_.levels;
    const shared::IcParams params = level_params(level);
    const size_t per_record = static_cast<size_t>(params.strata_m) * params.strata_n;
    // Reading a deeper level needs the hemisphere hits on the host side too: smaller batches.
    const size_t cells_limit = cached ? kMaxBatchCells / 8 : kMaxBatchCells;
    const size_t batch_limit = std::max<size_t>(1, cells_limit / per_record);
    // Random streams: a site's own (all sites have one or none do), else the level's next ones.
    const bool own_streams = !sites.empty() && sites.front().stream >= 0;
    for (size_t begin = 0, count = 0; begin < sites.size(); begin += count) {
        count = std::min(batch_limit, sites.size() - begin);
        std::vector<shared::Record> records(count);
        std::vector<shared::float4> origins(count);
        std::vector<unsigned> streams(count);
        for (size_t b = 0; b < count; ++b) {
            const RecordSite& site = sites[begin + b];
            records[b] = make_record(site.position, site.normal);
            origins[b] = float4_of(site.origin);
            streams[b] = own_streams ? static_cast<unsigned>(site.stream)
                                     : next_streams_[static_cast<size_t>(level)] +
                                           static_cast<unsigned>(begin + b);
        }
        const RecordBatchInput batch{params, records, origins, streams};
        const RecordStore* next = cached ? &stores_[static_cast<size_t>(level) + 1] : nullptr;
        const bool shared_batch = split_ && plugins_.observer == nullptr &&
                                  (next != nullptr || sampling_.source == nullptr);
        // The batch on the first device: for its hits, or for all of it.
        std::optional<BatchBuffers> here;
        if (cached || !shared_batch) {
            here.emplace(context_, batch);
        }
        if (cached) {
            // The next level must cover every hit of these rays before they read it.
            Buffer<shared::GBufferSample> hits(context_, count * per_record, "ic_record_hits");
            context_.launch(hits_kernel_, count * per_record, params,
                            SceneArguments(bvh_, device_scene_), here->records, here->origins,
                            here->streams, hits);
            cover(level + 1, hits, {0, 1, 1}, count * per_record, true);
        }
        RecordBatchOutput out;
        if (shared_batch) {
            const std::optional<HostRecords> below =
                next != nullptr ? std::optional<HostRecords>(*next) : std::nullopt;
            out = split_->compute_batch(batch, below ? &*below : nullptr);
        } else {
            out = compute_batch(batch, *here, next, sites.data() + begin);
        }
        stats_.record_rays += out.rays;
        for (size_t b = 0; b < count; ++b) {
            const RecordSite& site = sites[begin + b];
            ComputedRecord r;
            r.record = records[b];
            r.payload = out.payloads[b];
            r.host.harmonic_distance = out.distances[b].x;
            r.host.min_distance = out.distances[b].y;
            r.host.r_min = site.r_min;
            r.host.r_max = site.r_max;
            computed.push_back(r);
        }
    }
    if (!own_streams) {
        next_streams_[static_cast<size_t>(level)] += static_cast<uint32_t>(sites.size());
    }
    return computed;
}

CachePipeline::BatchBuffers::BatchBuffers(Context& context, const RecordBatchInput& batch)
    : records(context, batch.records, "ic_batch_records"),
      origins(context, batch.origins, "ic_batch_origins"),
      streams(context, batch.streams, "ic_batch_streams") {}

RecordBatchOutput CachePipeline::compute_batch(const RecordBatchInput& batch,
                                               const BatchBuffers& buffers, const RecordStore* next,
                                               const RecordSite* sites) {
    const size_t count = batch.records.size();
    const size_t per_record = static_cast<size_t>(batch.params.strata_m) * batch.params.strata_n;
    const Buffer<shared::Record>& record_buffer = buffers.records;
    const Buffer<shared::float4>& origin_buffer = buffers.origins;
    const Buffer<unsigned>& stream_buffer = buffers.streams;
    Buffer<shared::IrradiancePayload> payload_buffer(context_, count, "ic_batch_payloads");
    Buffer<shared::float4> cells(context_, count * per_record, "ic_cells");
    Buffer<shared::float4> distances(context_, count, "ic_distances");
    Buffer<unsigned> counters(context_, 1, "ic_record_counters");
    counters.fill_zero();
    const SceneArguments scene(bvh_, device_scene_);
    if (next != nullptr) {
        const RecordLevelSource source(context_, *next, kRecordMaxWeight);
        context_.launch(cells_kernel(source), count * per_record, batch.params, scene,
                        record_buffer, origin_buffer, stream_buffer, source, cells, counters);
    } else {
        const RadianceSource& source =
            sampling_.source != nullptr ? *sampling_.source : path_continuation_;
        context_.launch(cells_kernel(source), count * per_record, batch.params, scene,
                        record_buffer, origin_buffer, stream_buffer, source, cells, counters);
    }
    context_.launch(reduce_kernel_, count, batch.params, cells, record_buffer, stream_buffer,
                    payload_buffer, distances);
    if (plugins_.observer != nullptr) {
        plugins_.observer->observe({batch.params, record_buffer, batch.records.data(),
                                    origin_buffer, stream_buffer, batch.streams.data(), cells,
                                    sites, count});
    }
    RecordBatchOutput out;
    out.payloads = payload_buffer.download();
    out.distances = distances.download();
    out.rays = counters.download()[0];
    return out;
}

shared::IcParams CachePipeline::candidate_params(int level, Candidates placement) const {
    shared::IcParams params = level_params(level);
    if (level > 0) {
        // A deeper level's candidates are the hits of the level above's hemisphere rays: their
        // "pixel" (rc_ic_deeper_pixel_width) is that hemisphere's stratum.
        const shared::IcParams above = level_params(level - 1);
        params.strata_m = above.strata_m;
        params.strata_n = above.strata_n;
    }
    params.placement_stride = placement.stride;
    params.placement_spp = placement.spp;
    params.placement_columns = placement.columns;
    return params;
}

Buffer<shared::float4> CachePipeline::weighted_sums(const RecordStore& store,
                                                    const DeviceRecords& records,
                                                    const Buffer<shared::GBufferSample>& samples,
                                                    const shared::IcParams& params,
                                                    size_t candidates,
                                                    const shared::CameraParams* camera) {
    Buffer<shared::float4> sums(context_, candidates, "ic_sums");
    if (camera != nullptr) {
        const DeviceSplat splat(context_, store, *camera, &tile_depths_);
        context_.launch(splat_kernel_, candidates, params, splat.tiles, splat.tile_start,
                        splat.tile_records, records.records, records.payloads, samples, sums);
    } else {
        context_.launch(gather_kernel_, candidates, params, records.grid, records.cell_start,
                        records.cell_records, records.records, records.payloads, samples, sums);
    }
    return sums;
}

void CachePipeline::measure_tile_depths(const Buffer<shared::GBufferSample>& samples,
                                        const shared::IcParams& params,
                                        const shared::CameraParams& camera) {
    const shared::SplatTileGrid tiles = {
        RC_SPLAT_TILE_SIZE, (params.width + RC_SPLAT_TILE_SIZE - 1) / RC_SPLAT_TILE_SIZE,
        (params.height + RC_SPLAT_TILE_SIZE - 1) / RC_SPLAT_TILE_SIZE, 0};
    const size_t count = static_cast<size_t>(tiles.tiles_x) * tiles.tiles_y;
    Buffer<shared::TileDepths> depths(context_, count, "ic_tile_depths");
    context_.launch(tile_depths_kernel_, count, params, camera, tiles, samples, depths);
    tile_depths_ = depths.download();
}

void CachePipeline::drop_uncached(std::vector<shared::GBufferSample>* hits) const {
    if (plugins_.uncached_primitives.empty()) {
        return;
    }
    const auto uncached = [&](const shared::GBufferSample& g) {
        return g.primitive >= 0 &&
               static_cast<size_t>(g.primitive) < plugins_.uncached_primitives.size() &&
               plugins_.uncached_primitives[static_cast<size_t>(g.primitive)] != 0;
    };
    hits->erase(std::remove_if(hits->begin(), hits->end(), uncached), hits->end());
}

float CachePipeline::min_radius(float footprint) const {
    return std::max(spacing_bound(sampling_.min_spacing, footprint), smallest_radius_);
}

RecordSite CachePipeline::site_of(const shared::GBufferSample& g) const {
    RecordSite site;
    site.position = vec3_of(g.position);
    site.normal = vec3_of(g.normal);
    site.origin = vec3_of(g.origin);
    site.r_min = min_radius(g.footprint);
    site.r_max = std::max(site.r_min, spacing_bound(sampling_.max_spacing, g.footprint));
    site.primitive = g.primitive;
    return site;
}

std::vector<shared::GBufferSample> CachePipeline::uncovered_samples(
    int level, const Buffer<shared::GBufferSample>& samples, const shared::IcParams& params,
    size_t candidates) {
    Buffer<unsigned> uncovered_buffer(context_, candidates, "ic_uncovered");
    Buffer<unsigned> uncovered_count(context_, 1, "ic_uncovered_count");
    // Level 0's candidates are camera samples: splatted; deeper levels' are hemisphere hits:
    // gathered.
    uncovered_count.fill_zero();
    if (level == 0) {
        const DeviceSplat splat(context_, stores_[level], camera_, &tile_depths_);
        const DeviceRecords records(context_, stores_[level], false);
        context_.launch(uncovered_kernel_, candidates, params, splat.tiles, records.grid,
                        splat.tile_start, splat.tile_records, records.records, records.payloads,
                        samples, uncovered_buffer, uncovered_count);
    } else {
        const DeviceRecords records(context_, stores_[level]);
        const shared::SplatTileGrid no_tiles{};
        context_.launch(uncovered_kernel_, candidates, params, no_tiles, records.grid,
                        records.cell_start, records.cell_records, records.records, records.payloads,
                        samples, uncovered_buffer, uncovered_count);
    }
    const size_t count = uncovered_count.download()[0];
    std::vector<shared::GBufferSample> uncovered;
    if (count > 0) {
        std::vector<unsigned> indices(count);
        uncovered_buffer.read(indices.data(), count * sizeof(unsigned));
        std::sort(indices.begin(), indices.end());  // appended in any order
        const Buffer<unsigned> index_buffer(context_, indices, "ic_uncovered_sorted");
        Buffer<shared::GBufferSample> selected(context_, count, "ic_uncovered_samples");
        context_.launch(select_kernel_, count, samples, index_buffer, selected);
        uncovered = selected.download();
    }
    if (level > 0) {
        drop_uncached(&uncovered);
    }
    return uncovered;
}

void CachePipeline::cover(int level, const Buffer<shared::GBufferSample>& samples,
                          Candidates placement, size_t candidates, bool until_covered) {
    const shared::IcParams params = candidate_params(level, placement);
    const float a = sampling_.accuracy;
    const bool timed = level == 0;
    std::vector<shared::GBufferSample> uncovered;
    auto start = SteadyClock::now();
    // Step 1 of a pass: the candidates no record covers, with their minimum influence radii.
    const auto find = [&]() {
        start = SteadyClock::now();
        uncovered = uncovered_samples(level, samples, params, candidates);
        UncoveredCandidates open;
        open.positions.resize(uncovered.size());
        open.normals.resize(uncovered.size());
        open.min_influence.resize(uncovered.size());
        for (size_t c = 0; c < uncovered.size(); ++c) {
            open.positions[c] = vec3_of(uncovered[c].position);
            open.normals[c] = vec3_of(uncovered[c].normal);
            open.min_influence[c] = a * min_radius(uncovered[c].footprint);
        }
        return open;
    };
    // Step 2: records at the candidates thinning kept, listed in the order passes start (deeper
    // levels' passes follow the pass they serve).
    const auto add = [&](const std::vector<size_t>& chosen) {
        if (timed) {
            stats_.placement_seconds += seconds_since(start);
        }
        const size_t entry = stats_.passes.size();
        stats_.passes.push_back(
            {level, placement.stride, candidates, uncovered.size(), chosen.size()});
        start = SteadyClock::now();
        std::vector<RecordSite> sites;
        sites.reserve(chosen.size());
        for (size_t c : chosen) {
            sites.push_back(site_of(uncovered[c]));
        }
        const std::vector<ComputedRecord> computed = compute_level(level, sites);
        if (timed) {
            stats_.record_seconds += seconds_since(start);
            insert_level0(computed);
        } else {
            insert_irradiance_records(stores_[level], computed);
        }
        stats_.passes[entry].records = computed.size();
        start = SteadyClock::now();
    };
    const size_t left = run_placement_passes(until_covered, find, add);
    if (timed) {
        stats_.placement_seconds += seconds_since(start);
    }
    if (left > 0) {
        log_warning("irradiance caching: " + std::to_string(left) + " sample(s) of cache level " +
                    std::to_string(level) + " left uncovered after " +
                    std::to_string(kMaxPlacementPasses) +
                    " placement passes (records smaller than the scene's float precision?)");
    }
}

std::vector<shared::float4> CachePipeline::gather(
    const RecordStore& store, const std::vector<shared::GBufferSample>& queries) {
    const Buffer<shared::GBufferSample> samples(context_, queries, "ic_queries");
    shared::IcParams params{};
    params.accuracy = store.accuracy();
    params.max_weight = kRecordMaxWeight;
    const DeviceRecords records(context_, store);
    return weighted_sums(store, records, samples, params, queries.size(), nullptr).download();
}

std::vector<shared::float4> CachePipeline::splat(
    const RecordStore& store, const shared::CameraParams& camera, int spp,
    const std::vector<shared::GBufferSample>& samples) {
    const Buffer<shared::GBufferSample> buffer(context_, samples, "ic_queries");
    shared::IcParams params{};
    params.width = camera.resolution.x;
    params.height = camera.resolution.y;
    params.camera_spp = spp;
    params.accuracy = store.accuracy();
    params.max_weight = kRecordMaxWeight;
    params.placement_stride = 1;
    params.placement_spp = spp;
    params.placement_columns = camera.resolution.x;
    measure_tile_depths(buffer, params, camera);
    const DeviceRecords records(context_, store, false);
    return weighted_sums(store, records, buffer, params, samples.size(), &camera).download();
}

namespace {

// Error (exit status 2) for options render() cannot honour; `samples` camera samples in all.
// `beyond`: the plug-in the last level's hemisphere rays read.
void check_options(const PipelineSettings& options, const RadianceSource* beyond, size_t samples) {
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
    if (options.bounces < 1) {
        throw Error("--ic-bounces must be at least 1", kExitUsage);
    }
    if (options.light_samples < 1) {
        throw Error("--light-samples must be at least 1", kExitUsage);
    }
    if (beyond != nullptr && options.bounces > 1) {
        throw Error("the hemisphere rays read the " + beyond->source_name() +
                        " at their hits: it needs --ic-bounces 1",
                    kExitUsage);
    }
    if (samples > std::numeric_limits<uint32_t>::max()) {
        throw Error("irradiance caching: width x height x spp exceeds 2^32 camera samples",
                    kExitUsage);
    }
}

}  // namespace

std::vector<ProgramRequest> cache_pipeline_programs(const PipelineSettings& options,
                                                    int last_source) {
    std::vector<ProgramRequest> programs = {{"irradiance_cache/irradiance_cache.cl", ""}};
    if (options.bounces > 1) {
        programs.push_back(
            {"irradiance_cache/ic_record_cells.cl", radiance_source_define(RC_RADIANCE_RECORDS)});
    }
    programs.push_back(
        {"irradiance_cache/ic_record_cells.cl", radiance_source_define(last_source)});
    return programs;
}

namespace {

RecordSampling sampling_of(const PipelineSettings& options, const RadianceSource* beyond) {
    RecordSampling sampling = strata_for(options.rays);
    const RecordSampling deeper =
        strata_for(options.deeper_rays > 0 ? options.deeper_rays : std::max(4, options.rays / 4));
    sampling.deeper_m = deeper.m;
    sampling.deeper_n = deeper.n;
    sampling.max_depth = options.max_depth;
    sampling.rr_depth = options.rr_depth;
    sampling.seed = options.seed;
    sampling.levels = options.bounces;
    sampling.source = beyond;
    sampling.accuracy = options.accuracy;
    sampling.min_spacing = options.min_spacing;
    sampling.max_spacing = options.max_spacing;
    return sampling;
}

}  // namespace

void CachePipeline::insert_level0(const std::vector<ComputedRecord>& computed) {
    const auto start = SteadyClock::now();
    insert_irradiance_records(stores_[0], computed);
    stats_.insertion_seconds += seconds_since(start);
}

std::vector<uint8_t> CachePipeline::records_used(const RecordStore& store) {
    std::vector<uint8_t> used(store.size(), 0);
    if (store.size() == 0) {
        return used;
    }
    const DeviceSplat splat(context_, store, camera_, &tile_depths_);
    const DeviceRecords records(context_, store, false);
    Buffer<unsigned> flags(context_, store.size(), "ic_records_used");
    flags.fill_zero();
    const shared::IcParams params = candidate_params(0, {1, camera_spp_, width_});
    const size_t samples = static_cast<size_t>(width_) * height_ * camera_spp_;
    context_.launch(records_used_kernel_, samples, params, splat.tiles, splat.tile_start,
                    splat.tile_records, records.records, records.payloads, gbuffer_, flags);
    const std::vector<unsigned> downloaded = flags.download();
    for (size_t i = 0; i < used.size(); ++i) {
        used[i] = downloaded[i] != 0 ? 1 : 0;
    }
    return used;
}

void CachePipeline::set_records(int level, RecordStore store, uint32_t next_stream) {
    stores_.at(static_cast<size_t>(level)) = std::move(store);
    next_streams_[static_cast<size_t>(level)] = next_stream;
}

void CachePipeline::add_records(const std::vector<RecordSite>& sites) {
    auto start = SteadyClock::now();
    const std::vector<ComputedRecord> computed = compute_level(0, sites);
    stats_.record_seconds += seconds_since(start);
    insert_level0(computed);
}

void CachePipeline::place() {
    // Candidates: the first camera sample of every stride-th pixel of every stride-th row; at
    // stride 1 every camera sample. Coarser strides take one pass. At stride 1 passes repeat
    // until every sample is covered: neighbor clamping may shrink records placed earlier and
    // uncover samples that were covered, so every pass checks all candidates again. (Indirect
    // light needs two bounces; below that the cache is never read.)
    if (sampling_.max_depth < 2) {
        return;
    }
    for (int stride : {16, 8, 4, 2, 1}) {
        const int columns = (width_ + stride - 1) / stride;
        const int rows = (height_ + stride - 1) / stride;
        const int per_pixel = stride == 1 ? camera_spp_ : 1;
        cover(0, gbuffer_, {stride, per_pixel, columns},
              static_cast<size_t>(columns) * rows * per_pixel, stride == 1);
    }
}

std::vector<shared::float4> CachePipeline::shade(const shared::IcParams& params,
                                                 bool records_overlay,
                                                 const Buffer<shared::RcGlossySample>& glossy) {
    const size_t pixels = static_cast<size_t>(width_) * height_;
    const size_t samples = pixels * static_cast<size_t>(camera_spp_);
    // The splat buffer: every record splatted over every camera sample. The records go to the
    // device once for the splat and the render pass, with the world-space grid only for the
    // records overlay.
    auto start = SteadyClock::now();
    const DeviceRecords records(context_, stores_[0], records_overlay);
    const Buffer<shared::float4> splat =
        weighted_sums(stores_[0], records, gbuffer_, candidate_params(0, {1, camera_spp_, width_}),
                      samples, &camera_);
    context_.finish();
    stats_.splatting_seconds = seconds_since(start);
    // The render pass.
    start = SteadyClock::now();
    stats_.cache_bytes = records.bytes() + splat.bytes();
    Buffer<shared::float4> film(context_, pixels * RC_CACHED_FILM_SLOTS, "ic_film");
    Buffer<unsigned> counters(context_, 3, "ic_counters");
    counters.upload({0u, 0u, 0xffffffffu});
    context_.launch(shade_kernel_, pixels, params, camera_, SceneArguments(bvh_, device_scene_),
                    records.grid, records.cell_start, records.cell_records, records.records,
                    records.payloads, splat, glossy, film, counters);
    std::vector<shared::float4> sums = film.download();
    const std::vector<unsigned> c = counters.download();
    stats_.shading_rays = c[0];
    stats_.nonfinite_samples = c[1];
    stats_.first_nonfinite_pixel = c[1] > 0 ? static_cast<int64_t>(c[2]) : -1;
    stats_.shading_seconds = seconds_since(start);
    return sums;
}

std::vector<shared::float4> CachePipeline::shade_split(
    const shared::IcParams& params, bool records_overlay,
    const Buffer<shared::RcGlossySample>& glossy) {
    // The records, grid and splat tiles made once on the host for every device.
    auto start = SteadyClock::now();
    const HostRecords records(stores_[0], records_overlay);
    const SplatTiles tiles = store_splat_tiles(stores_[0], camera_, &tile_depths_);
    stats_.splatting_seconds = seconds_since(start);
    start = SteadyClock::now();
    const FinalPassOutput out =
        split_->final_pass({candidate_params(0, {1, camera_spp_, width_}), params, camera_, records,
                            tiles, gbuffer_, glossy, width_, height_, camera_spp_});
    stats_.cache_bytes = out.cache_bytes;
    stats_.shading_rays = out.rays;
    stats_.nonfinite_samples = out.nonfinite_samples;
    stats_.first_nonfinite_pixel = out.first_nonfinite_pixel;
    stats_.shading_seconds = seconds_since(start);
    return out.film;
}

void CachePipeline::begin(const PipelineSettings& options) {
    sample_camera(options, [&] { reset(sampling_of(options, plugins_.beyond)); });
}

void CachePipeline::sample_camera(const PipelineSettings& options,
                                  const std::function<void()>& checked) {
    width_ = options.width > 0 ? options.width : scene_.camera.width;
    height_ = options.height > 0 ? options.height : scene_.camera.height;
    const size_t samples = static_cast<size_t>(width_) * height_ * std::max(options.spp, 0);
    check_options(options, plugins_.beyond, samples);
    if (checked) {
        checked();
    }
    camera_spp_ = options.spp;
    first_sample_ = options.first_sample;
    camera_ = camera_params(scene_.camera, width_, height_);
    // 1. G-buffer.
    const auto start = SteadyClock::now();
    const shared::IcParams params = level_params(0);
    gbuffer_ = Buffer<shared::GBufferSample>(context_, samples, "ic_gbuffer");
    context_.launch(gbuffer_kernel_, samples, params, camera_, SceneArguments(bvh_, device_scene_),
                    gbuffer_);
    measure_tile_depths(gbuffer_, params, camera_);
    context_.finish();
    stats_.gbuffer_seconds = seconds_since(start);
}

PipelineStats CachePipeline::current_stats() const {
    PipelineStats stats = stats_;
    if (split_) {
        stats.devices = split_->shares();
    }
    stats.level_records.clear();
    for (const RecordStore& store : stores_) {
        stats.level_records.push_back(store.size());
    }
    stats.records = stores_[0].size();
    return stats;
}

Image CachePipeline::finish(PipelineSettings options, PipelineStats* stats) {
    shared::IcParams params = level_params(0);
    params.draw_records = options.records_overlay ? 1 : 0;
    params.light_samples = options.light_samples;
    // The glossy lobes' cache, when one serves them.
    Buffer<shared::RcGlossySample> glossy(context_, 1, "ic_no_glossy");
    glossy.fill_zero();
    if (plugins_.lobes != nullptr) {
        const RecordLevelSource first_level(context_, stores_[0], kRecordMaxWeight);
        glossy = plugins_.lobes->glossy_samples(params, camera_, first_level);
        params.glossy_cache = 1;
    }
    // 5.-6. Splatting and the render pass.
    const std::vector<shared::float4> sums =
        split_ ? shade_split(params, options.records_overlay, glossy)
               : shade(params, options.records_overlay, glossy);

    std::vector<FilmLayer> layers = {
        {"beauty", RC_CACHED_FILM_BEAUTY},     {"direct", RC_CACHED_FILM_DIRECT},
        {"indirect", RC_CACHED_FILM_INDIRECT}, {"albedo", RC_CACHED_FILM_ALBEDO},
        {"normal", RC_CACHED_FILM_NORMAL},     {"coverage", RC_CACHED_FILM_COVERAGE, 1}};
    if (options.records_overlay) {
        layers.push_back({"records", RC_CACHED_FILM_LAYER});
    }
    if (plugins_.lobes != nullptr) {
        layers.push_back({"glossy-indirect", RC_CACHED_FILM_GLOSSY});
        for (const FilmLayer& layer : plugins_.lobes->layers()) {
            layers.push_back(layer);
        }
    }
    Image image = unpack_film(sums, RC_CACHED_FILM_SLOTS, width_, height_, layers);
    if (stats != nullptr) {
        *stats = current_stats();
    }
    return image;
}

Image CachePipeline::render_more(const PipelineSettings& options, PipelineStats* stats) {
    restart_stats();
    sample_camera(options);
    place();
    if (!options.cache_out.empty()) {
        write_cache_file(options.cache_out, irradiance_cache_key(scene_, options.accuracy),
                         stores_);
    }
    return finish(options, stats);
}

Image CachePipeline::render(const PipelineSettings& options, PipelineStats* stats) {
    begin(options);
    // 2.-4. Placement, coarse to fine, with record computation and insertion, from the records
    // of a saved cache when one is given.
    if (!options.cache_in.empty()) {
        std::vector<RecordStore> loaded =
            read_cache_file(options.cache_in, irradiance_cache_key(scene_, options.accuracy));
        for (size_t level = 0; level < loaded.size() && level < stores_.size(); ++level) {
            stats_.loaded_records += loaded[level].size();
            stores_[level] = std::move(loaded[level]);
        }
        for (size_t level = 0; level < stores_.size(); ++level) {
            next_streams_[level] = static_cast<uint32_t>(stores_[level].size());
        }
    }
    place();
    if (!options.cache_out.empty()) {
        write_cache_file(options.cache_out, irradiance_cache_key(scene_, options.accuracy),
                         stores_);
    }
    return finish(options, stats);
}

}  // namespace rc
