#include "methods/radiance_cache/radiance_cache.h"

#include <algorithm>
#include <cmath>

#include "methods/caching/cache_file.h"
#include "methods/caching/glossy_mix.h"
#include "methods/caching/record_grid.h"
#include "methods/radiance_cache/radiance_records.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "shared/sh_rotation_zxz.h"
#include "util/error.h"
#include "util/glm_helpers.h"
#include "util/timing.h"

namespace rc {
namespace {

constexpr size_t kMaxBatchCells = size_t{1} << 22;  // hemisphere cells per record launch

// The scene's BRDF tables for these options (their options checked first), the seconds taken
// into *seconds and whether they were built now into *built_now; `built` when given.
std::shared_ptr<const BrdfTables> build_tables(const FrameScene& frame,
                                               const RadianceCacheOptions& options,
                                               std::shared_ptr<const BrdfTables> built,
                                               double* seconds, bool* built_now) {
    check_radiance_cache_options(options);
    if (built) {
        return built;
    }
    BrdfTableOptions table;
    table.max_order = options.order > 0 ? options.order : RC_SH_MAX_ORDER;
    table.max_error = options.max_error;
    const auto start = SteadyClock::now();
    auto tables = shared_brdf_tables(frame.context, frame.scene.materials, table, built_now);
    frame.context.finish();
    *seconds = seconds_since(start);
    return tables;
}

// The highest order any served material's table represents: the records' order (TVCG §4.2
// projects each record at the order its surface needs; one order for all keeps the payloads
// uniform).
int records_order(const BrdfTables& tables, const ServedMaterials& served) {
    int order = 0;
    const std::vector<shared::BrdfTableInfo>& infos = tables.infos();
    for (size_t m = 0; m < infos.size(); ++m) {
        if (served.empty() || (m < served.size() && served[m] != 0)) {
            order = std::max(order, infos[m].order);
        }
    }
    return order;
}

// A store's records, their payloads and the world-space grid over them, on the device.
struct DeviceRadianceRecords {
    DeviceRadianceRecords(Context& context, const RecordStore& store, int order) {
        const RecordGridData data = build_record_grid(store.records(), store.accuracy());
        grid = data.grid;
        records = Buffer<shared::Record>(context, store.records(), "rc_records");
        payloads = Buffer<float>(context, device_radiance_payloads(store, order), "rc_payloads");
        cell_start = Buffer<int>(context, data.cell_start, "rc_cell_start");
        cell_records = Buffer<int>(context, data.cell_records, "rc_cell_records");
    }

    shared::RecordGrid grid{};
    Buffer<shared::Record> records;
    Buffer<float> payloads;
    Buffer<int> cell_start;
    Buffer<int> cell_records;
};

}  // namespace

void check_radiance_cache_options(const RadianceCacheOptions& options) {
    if (options.order < 0 || options.order > RC_SH_MAX_ORDER) {
        throw Error("--rc-order must be auto or 1.." + std::to_string(RC_SH_MAX_ORDER) + ", got " +
                        std::to_string(options.order),
                    kExitUsage);
    }
    if (!(options.max_error > 0.0 && options.max_error < 1.0)) {
        throw Error("--rc-max-error must lie in (0, 1), got " + std::to_string(options.max_error),
                    kExitUsage);
    }
    if (options.rays < 16) {
        throw Error("--rc-rays must be at least 16, got " + std::to_string(options.rays),
                    kExitUsage);
    }
    if (!(options.accuracy > 0.0f && options.accuracy <= 1.0f)) {
        throw Error("--accuracy must lie in (0, 1], got " + std::to_string(options.accuracy),
                    kExitUsage);
    }
}

void radiance_strata(int rays, int* m, int* n) {
    *m = std::max(2, static_cast<int>(std::lround(std::sqrt(rays / 4.0))));
    *n = std::max(2, static_cast<int>(std::lround(static_cast<double>(rays) / *m)));
}

RadianceCache::RadianceCache(const FrameScene& frame, const RadianceCacheOptions& options,
                             std::shared_ptr<const BrdfTables> tables)
    : FrameBound(frame),
      options_(options),
      tables_(build_tables(frame, options, std::move(tables), &stats_.table_seconds,
                           &stats_.tables_built)),
      order_(records_order(*tables_, options.materials)),
      store_(radiance_store(options.accuracy, std::max(order_, 1))),
      queries_kernel_(frame.context.kernel("radiance_cache/rc_cache.cl", "rc_glossy_queries")),
      project_kernel_(frame.context.kernel("radiance_cache/rc_cache.cl", "rc_record_project")),
      splat_kernel_(frame.context.kernel("radiance_cache/rc_cache.cl", "rc_glossy_splat")),
      placement_(frame.context) {
    radiance_strata(options.rays, &strata_m_, &strata_n_);
    stats_.materials = tables_->summaries();
    stats_.order = order_;
    stats_.strata_m = strata_m_;
    stats_.strata_n = strata_n_;
    if (!options.cache_in.empty()) {
        store_ =
            std::move(read_cache_file(options.cache_in, radiance_cache_key(scene_, options.accuracy,
                                                                           std::max(order_, 1)))
                          .at(0));
        stats_.loaded_records = store_.size();
    }
    next_stream_ = static_cast<unsigned>(store_.size());
}

Kernel& RadianceCache::cells_kernel(const RadianceSource& source) {
    return source_kernel(context_, &cells_kernels_, "radiance_cache/rc_record_cells.cl",
                         "rc_record_cells", source);
}

shared::RcParams RadianceCache::record_params() const {
    shared::RcParams params{};
    params.order = std::max(order_, 1);
    params.strata_m = strata_m_;
    params.strata_n = strata_n_;
    set_kernel_path_settings(options_, &params);
    params.accuracy = options_.accuracy;
    params.max_weight = kRecordMaxWeight;
    params.count_emission = options_.count_emission ? 1 : 0;
    return params;
}

void RadianceCache::set_store(RecordStore store, unsigned next_stream) {
    store_ = std::move(store);
    next_stream_ = next_stream;
}

void RadianceCache::add_records(const std::vector<shared::RcQuery>& sites,
                                const std::vector<unsigned>& streams,
                                const RadianceSource& diffuse) {
    const size_t per_record = static_cast<size_t>(strata_m_) * strata_n_;
    const size_t batch_limit = std::max<size_t>(1, kMaxBatchCells / per_record);
    const size_t floats = radiance_payload_floats(std::max(order_, 1));
    const SceneArguments scene(bvh_, device_scene_);
    const shared::RcParams params = record_params();
    Buffer<unsigned> counters(context_, 1, "rc_record_counters");
    for (size_t begin = 0; begin < sites.size(); begin += batch_limit) {
        const size_t count = std::min(batch_limit, sites.size() - begin);
        const std::vector<shared::RcQuery> batch(sites.begin() + begin,
                                                 sites.begin() + begin + count);
        const std::vector<unsigned> batch_streams(streams.begin() + begin,
                                                  streams.begin() + begin + count);
        const Buffer<shared::RcQuery> site_buffer(context_, batch, "rc_batch_sites");
        const Buffer<unsigned> stream_buffer(context_, batch_streams, "rc_batch_streams");
        Buffer<shared::float4> cells(context_, count * per_record, "rc_cells");
        Buffer<float> payloads(context_, count * floats, "rc_batch_payloads");
        Buffer<shared::float4> distances(context_, count, "rc_distances");
        counters.fill_zero();
        context_.launch(cells_kernel(diffuse), count * per_record, params, scene, site_buffer,
                        stream_buffer, diffuse, cells, counters);
        if (observer_ != nullptr) {
            observer_->observe({params, site_buffer, stream_buffer, cells, batch.data(),
                                batch_streams.data(), count});
        }
        context_.launch(project_kernel_, count, params, stream_buffer, cells, payloads, distances);
        const std::vector<float> payload = payloads.download();
        const std::vector<shared::float4> distance = distances.download();
        stats_.record_rays += counters.download()[0];
        std::vector<NewRecord> inserted(count);
        for (size_t b = 0; b < count; ++b) {
            const shared::RcQuery& q = sites[begin + b];
            RecordHostData host;
            host.harmonic_distance = distance[b].x;
            host.min_distance = distance[b].y;
            host.r_min = spacing_bound(options_.min_spacing, q.footprint);
            host.r_max = std::max(host.r_min, spacing_bound(options_.max_spacing, q.footprint));
            const std::vector<float> own(payload.begin() + b * floats,
                                         payload.begin() + (b + 1) * floats);
            inserted[b] = {make_record(vec3_of(q.position), vec3_of(q.normal)), host,
                           payload.data() + b * floats,
                           radiance_radius_limit(own, std::max(order_, 1))};
        }
        store_.insert_batch(inserted);
    }
}

std::vector<uint8_t> RadianceCache::records_used(const Buffer<shared::RcQuery>& queries,
                                                 const RecordStore& store) {
    return placement_.records_used(queries, store);
}

Buffer<shared::RcQuery> RadianceCache::queries(const shared::IcParams& params,
                                               const shared::CameraParams& camera) {
    const size_t samples =
        static_cast<size_t>(params.width) * params.height * static_cast<size_t>(params.camera_spp);
    const auto start = SteadyClock::now();
    Buffer<shared::RcQuery> device(context_, samples, "rc_queries");
    context_.launch(queries_kernel_, samples, params, camera, SceneArguments(bvh_, device_scene_),
                    tables_->device_infos(), tables_->orders(), device);
    restrict_glossy_queries(context_, options_.materials, device);
    stats_.query_seconds += seconds_since(start);
    return device;
}

void RadianceCache::place(const Buffer<shared::RcQuery>& queries, const shared::IcParams& params,
                          const RadianceSource& diffuse) {
    placement_.place(
        queries, store_, static_cast<uint32_t>(params.width),
        static_cast<uint32_t>(params.camera_spp), options_.min_spacing,
        [&](const std::vector<shared::RcQuery>& sites) {
            add_records(sites, next_streams(sites.size(), &next_stream_), diffuse);
        },
        &stats_.placement);
    stats_.records = store_.size();
}

Buffer<shared::RcGlossySample> RadianceCache::splat(const Buffer<shared::RcQuery>& queries) {
    const auto start = SteadyClock::now();
    const DeviceRadianceRecords records(context_, store_, std::max(order_, 1));
    std::vector<float> x90(RC_SH_X90_TABLE_SIZE);
    shared::rc_sh_x90_table(x90.data());
    const Buffer<float> x90_buffer(context_, x90, "rc_x90");
    Buffer<shared::RcGlossySample> glossy(context_, queries.size(), "rc_glossy");
    Buffer<unsigned> counters(context_, 1, "rc_splat_counters");
    counters.fill_zero();
    context_.launch(splat_kernel_, queries.size(), record_params(), records.grid,
                    records.cell_start, records.cell_records, records.records, records.payloads,
                    queries, tables_->device_infos(), tables_->coefficients(), x90_buffer, glossy,
                    counters);
    stats_.reflections = counters.download()[0];
    stats_.records = store_.size();
    stats_.splat_seconds = seconds_since(start);
    return glossy;
}

Buffer<shared::RcGlossySample> RadianceCache::glossy_samples(const shared::IcParams& params,
                                                             const shared::CameraParams& camera,
                                                             const RadianceSource& diffuse) {
    // 1. The camera samples as radiance caching sees them.
    const Buffer<shared::RcQuery> device = queries(params, camera);
    // 2. Placement, coarse to fine as irradiance caching's (GlossyPlacement).
    place(device, params, diffuse);
    if (!options_.cache_out.empty()) {
        write_cache_file(options_.cache_out,
                         radiance_cache_key(scene_, options_.accuracy, std::max(order_, 1)),
                         {store_});
    }
    // 3. The glossy buffer: every served sample's interpolated reflection.
    return splat(device);
}

}  // namespace rc
