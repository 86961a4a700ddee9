#include "methods/sdrc/sdrc_cache.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "methods/caching/glossy_mix.h"
#include "methods/caching/record_grid.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "util/error.h"
#include "util/glm_helpers.h"
#include "util/timing.h"

namespace rc {
namespace {

constexpr size_t kMaxRecordSamples = size_t{1} << 22;  // record samples per launch
constexpr size_t kRoundBatch = size_t{1} << 20;        // camera samples per interpolation launch

// Builds trees[i] for every i in [0, count) on the host's threads (the records are independent;
// each build is deterministic, so the thread count does not change the result).
void build_trees_in_parallel(std::vector<LTree*>& trees) {
    const size_t threads =
        std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), trees.size());
    std::vector<std::thread> pool;
    for (size_t t = 0; t < threads; ++t) {
        pool.emplace_back([&, t] {
            for (size_t i = t; i < trees.size(); i += threads) {
                build_ltree(&trees[i]->tree);
            }
        });
    }
    for (std::thread& thread : pool) {
        thread.join();
    }
}

// The store's records and the world-space grid over them, with the records' sites and L-trees,
// on the device.
struct DeviceSdrcCache {
    DeviceSdrcCache(Context& context, const RecordStore& store,
                    const std::vector<shared::RcQuery>& sites, const std::vector<LTree>& trees) {
        const RecordGridData data = build_record_grid(store.records(), store.accuracy());
        const PackedLTrees packed = pack_ltrees(trees);
        grid = data.grid;
        records = Buffer<shared::Record>(context, store.records(), "sdrc_records");
        cell_start = Buffer<int>(context, data.cell_start, "sdrc_cell_start");
        cell_records = Buffer<int>(context, data.cell_records, "sdrc_cell_records");
        site_buffer = Buffer<shared::RcQuery>(context, sites, "sdrc_sites");
        tree_buffer = Buffer<shared::SdrcTree>(context, packed.trees, "sdrc_trees");
        nodes = Buffer<shared::LTreeNode>(context, packed.nodes, "sdrc_nodes");
    }

    shared::RecordGrid grid{};
    Buffer<shared::Record> records;
    Buffer<int> cell_start;
    Buffer<int> cell_records;
    Buffer<shared::RcQuery> site_buffer;
    Buffer<shared::SdrcTree> tree_buffer;
    Buffer<shared::LTreeNode> nodes;
};

}  // namespace

int sdrc_record_samples(const SdrcOptions& options, int spp) {
    if (options.samples > 0) {
        return options.samples;
    }
    const double n = 3.0 * options.interp * spp;
    return static_cast<int>(std::clamp(n, 64.0, 8192.0));
}

SdrcCache::SdrcCache(const FrameScene& frame, const SdrcOptions& options)
    : FrameBound(frame),
      options_(options),
      store_(options.accuracy, 0),
      queries_kernel_(frame.context.kernel("sdrc/sdrc.cl", "sdrc_queries")),
      radius_kernel_(frame.context.kernel("sdrc/sdrc.cl", "sdrc_record_radius")),
      interpolate_kernel_(frame.context.kernel("sdrc/sdrc.cl", "sdrc_interpolate")),
      add_misses_kernel_(frame.context.kernel("sdrc/sdrc.cl", "sdrc_add_misses")),
      placement_(frame.context) {}

Kernel& SdrcCache::trace_kernel(const RadianceSource& source, const char* name) {
    const std::string options = source.build_options();
    const std::string key = std::string(name) + " " + options;
    auto found = trace_kernels_.find(key);
    if (found == trace_kernels_.end()) {
        Kernel kernel = context_.kernel("sdrc/sdrc_trace.cl", name, options);
        found = trace_kernels_.emplace(key, std::move(kernel)).first;
    }
    return found->second;
}

shared::SdrcParams SdrcCache::kernel_params(const shared::IcParams& params) const {
    shared::SdrcParams p{};
    p.samples = sdrc_record_samples(options_, params.camera_spp);
    p.interp = options_.interp;
    p.pixel_interp = static_cast<float>(options_.interp) * static_cast<float>(params.camera_spp);
    p.max_radius = options_.max_radius;
    set_kernel_path_settings(options_, &p);
    p.accuracy = options_.accuracy;
    p.max_weight = kRecordMaxWeight;
    p.count_emission = options_.count_emission ? 1 : 0;
    return p;
}

void SdrcCache::check_memory() {
    uint64_t nodes = 0;
    for (const LTree& t : trees_) {
        nodes += t.size();
    }
    stats_.ltree_nodes = nodes;
    const double mib = static_cast<double>(nodes * sizeof(shared::LTreeNode)) / (1024.0 * 1024.0);
    if (mib > options_.memory_mib) {
        throw Error("sdrc: the L-trees need " + std::to_string(static_cast<long long>(mib)) +
                    " MiB, more than --sdrc-memory " +
                    std::to_string(static_cast<long long>(options_.memory_mib)) +
                    " MiB (raise it, or lower --sdrc-samples or --sdrc-interp)");
    }
}

void SdrcCache::add_records(const std::vector<shared::RcQuery>& sites,
                            const std::vector<unsigned>& streams, const shared::IcParams& params,
                            const RadianceSource& diffuse) {
    add_batches(sites, streams, kernel_params(params), diffuse);
}

void SdrcCache::set_records(RecordStore store, std::vector<shared::RcQuery> sites,
                            std::vector<LTree> trees, unsigned next_stream) {
    if (sites.size() != store.size() || trees.size() != store.size()) {
        throw Error("sdrc: " + std::to_string(store.size()) + " records with " +
                    std::to_string(sites.size()) + " sites and " + std::to_string(trees.size()) +
                    " L-trees");
    }
    store_ = std::move(store);
    sites_ = std::move(sites);
    trees_ = std::move(trees);
    next_stream_ = next_stream;
    check_memory();
}

void SdrcCache::add_batches(const std::vector<shared::RcQuery>& sites,
                            const std::vector<unsigned>& streams, const shared::SdrcParams& base,
                            const RadianceSource& diffuse) {
    const size_t n = static_cast<size_t>(base.samples);
    const size_t batch_limit = options_.record_batch > 0
                                   ? options_.record_batch
                                   : std::max<size_t>(1, kMaxRecordSamples / n);
    const SceneArguments scene(bvh_, device_scene_);
    Buffer<unsigned> counters(context_, 1, "sdrc_record_counters");
    for (size_t begin = 0; begin < sites.size(); begin += batch_limit) {
        const size_t count = std::min(batch_limit, sites.size() - begin);
        const std::vector<shared::RcQuery> batch(sites.begin() + begin,
                                                 sites.begin() + begin + count);
        const std::vector<unsigned> batch_streams(streams.begin() + begin,
                                                  streams.begin() + begin + count);
        const Buffer<shared::RcQuery> site_buffer(context_, batch, "sdrc_batch_sites");
        const Buffer<unsigned> stream_buffer(context_, batch_streams, "sdrc_batch_streams");
        Buffer<shared::float4> samples(context_, count * n, "sdrc_record_samples");
        Buffer<shared::LTreeNode> nodes(context_, count * n, "sdrc_record_nodes");
        Buffer<shared::float4> radii(context_, count, "sdrc_record_radii");
        // With an observer, each record's uniform cells too (temporal caching's reprojection).
        const int cell_m = observer_ != nullptr ? observer_->cell_rows() : 0;
        const int cell_n = observer_ != nullptr ? observer_->cell_columns() : 0;
        const size_t cell_items = count * static_cast<size_t>(cell_m) * cell_n;
        Buffer<shared::float4> cells(context_, std::max<size_t>(1, cell_items), "sdrc_cells");
        counters.fill_zero();
        context_.launch(trace_kernel(diffuse, "sdrc_record_samples"), count * n + cell_items, base,
                        static_cast<unsigned>(count * n), cell_m, cell_n, scene, site_buffer,
                        stream_buffer, diffuse, samples, nodes, cells, counters);
        context_.launch(radius_kernel_, count, base, device_scene_.materials, site_buffer,
                        stream_buffer, samples, radii);
        if (observer_ != nullptr) {
            observer_->observe({base, site_buffer, stream_buffer, samples, nodes, cells,
                                batch.data(), batch_streams.data(), diffuse, count});
        }
        const std::vector<shared::LTreeNode> all_nodes = nodes.download();
        const std::vector<shared::float4> radius = radii.download();
        stats_.record_rays += counters.download()[0];
        const auto build_start = SteadyClock::now();
        const size_t first_tree = trees_.size();
        trees_.resize(first_tree + count);
        std::vector<LTree*> built;
        for (size_t b = 0; b < count; ++b) {
            trees_[first_tree + b].tree.assign(all_nodes.begin() + b * n,
                                               all_nodes.begin() + (b + 1) * n);
            built.push_back(&trees_[first_tree + b]);
        }
        build_trees_in_parallel(built);
        stats_.tree_build_seconds += seconds_since(build_start);
        std::vector<NewRecord> inserted(count);
        const char none = 0;
        for (size_t b = 0; b < count; ++b) {
            const shared::RcQuery& q = batch[b];
            RecordHostData host;
            host.harmonic_distance = radius[b].x;
            host.min_distance = radius[b].y;
            host.r_min = spacing_bound(options_.min_spacing, q.footprint);
            host.r_max = std::max(host.r_min, spacing_bound(options_.max_spacing, q.footprint));
            inserted[b] = {make_record(vec3_of(q.position), vec3_of(q.normal)), host, &none,
                           radius[b].z};
            sites_.push_back(q);
        }
        store_.insert_batch(inserted);
        check_memory();
    }
}

void SdrcCache::interpolate_round(const std::vector<uint32_t>& samples,
                                  const shared::SdrcParams& params,
                                  const Buffer<shared::RcQuery>& queries,
                                  Buffer<shared::RcGlossySample>& glossy,
                                  const RadianceSource& diffuse) {
    const DeviceSdrcCache cache(context_, store_, sites_, trees_);
    const size_t m = static_cast<size_t>(params.interp);
    Buffer<unsigned> counters(context_, 2, "sdrc_interpolation_counters");
    Buffer<unsigned> ray_counters(context_, 1, "sdrc_miss_counters");
    std::vector<std::pair<int, shared::LTreeNode>> inserts;  // in sample, then direction order
    const size_t batch_limit = options_.round_batch > 0 ? options_.round_batch : kRoundBatch;
    for (size_t begin = 0; begin < samples.size(); begin += batch_limit) {
        const size_t count = std::min(batch_limit, samples.size() - begin);
        const Buffer<unsigned> batch(
            context_,
            std::vector<uint32_t>(samples.begin() + begin, samples.begin() + begin + count),
            "sdrc_round_samples");
        Buffer<shared::SdrcMiss> misses(context_, count * m, "sdrc_misses");
        Buffer<shared::float4> radiance(context_, count * m, "sdrc_miss_radiance");
        Buffer<shared::LTreeNode> nodes(context_, count * m, "sdrc_miss_nodes");
        counters.fill_zero();
        ray_counters.fill_zero();
        context_.launch(interpolate_kernel_, count, params, device_scene_.materials, cache.grid,
                        cache.cell_start, cache.cell_records, cache.records, cache.site_buffer,
                        cache.tree_buffer, cache.nodes, queries, batch, glossy, misses, counters);
        context_.launch(trace_kernel(diffuse, "sdrc_trace_misses"), count * m, params,
                        SceneArguments(bvh_, device_scene_), cache.site_buffer, queries, misses,
                        diffuse, radiance, nodes, ray_counters);
        context_.launch(add_misses_kernel_, count, params, batch, misses, radiance, glossy);
        stats_.directions += count * m;
        const std::vector<unsigned> counted = counters.download();
        stats_.answered += counted[0];
        stats_.range_queries += counted[1];
        stats_.miss_rays += ray_counters.download()[0];
        const std::vector<shared::SdrcMiss> miss = misses.download();
        const std::vector<shared::LTreeNode> node = nodes.download();
        for (size_t k = 0; k < miss.size(); ++k) {
            if (miss[k].record == -2) {
                continue;
            }
            ++stats_.misses;
            if (miss[k].record < 0) {
                ++stats_.unstored;
            } else {
                inserts.emplace_back(miss[k].record, node[k]);
            }
        }
    }
    // The round's misses into their L-trees, in sample order (SDRC §4.4: buffered, the tree
    // rebuilt when its buffer fills).
    const auto start = SteadyClock::now();
    for (const auto& [record, node] : inserts) {
        LTree& tree = trees_[static_cast<size_t>(record)];
        const size_t before = tree.rebuilds;
        tree.insert(node, kLTreeBufferCapacity);
        stats_.rebuilds += tree.rebuilds - before;
    }
    stats_.tree_build_seconds += seconds_since(start);
    check_memory();
}

SdrcQueries SdrcCache::queries(const shared::IcParams& params, const shared::CameraParams& camera) {
    const size_t samples =
        static_cast<size_t>(params.width) * params.height * static_cast<size_t>(params.camera_spp);
    stats_.samples = sdrc_record_samples(options_, params.camera_spp);
    const auto start = SteadyClock::now();
    SdrcQueries q{Buffer<shared::RcQuery>(context_, samples, "sdrc_queries"),
                  Buffer<shared::RcGlossySample>(context_, samples, "sdrc_glossy")};
    context_.launch(queries_kernel_, samples, params, camera, SceneArguments(bvh_, device_scene_),
                    q.queries, q.glossy);
    restrict_glossy_queries(context_, options_.materials, q.queries);
    stats_.query_seconds = seconds_since(start);
    return q;
}

void SdrcCache::place(const Buffer<shared::RcQuery>& queries, const shared::IcParams& params,
                      const RadianceSource& diffuse) {
    const shared::SdrcParams base = kernel_params(params);
    placement_.place(
        queries, store_, static_cast<uint32_t>(params.width),
        static_cast<uint32_t>(params.camera_spp), options_.min_spacing,
        [&](const std::vector<shared::RcQuery>& sites) {
            add_batches(sites, next_streams(sites.size(), &next_stream_), base, diffuse);
        },
        &stats_.placement);
    stats_.records = store_.size();
}

void SdrcCache::interpolate(SdrcQueries& queries, const shared::IcParams& params,
                            const RadianceSource& diffuse) {
    const shared::SdrcParams base = kernel_params(params);
    const uint32_t width = static_cast<uint32_t>(params.width);
    const uint32_t spp = static_cast<uint32_t>(params.camera_spp);
    const auto start = SteadyClock::now();
    for (int stride : {16, 8, 4, 2, 1}) {
        std::vector<uint32_t> round;
        for (uint32_t i : placement_.served()) {
            if (first_candidate_stride(i, width, spp) == stride) {
                round.push_back(i);
            }
        }
        if (!round.empty()) {
            interpolate_round(round, base, queries.queries, queries.glossy, diffuse);
        }
    }
    stats_.interpolation_seconds = seconds_since(start);
}

Buffer<shared::RcGlossySample> SdrcCache::glossy_samples(const shared::IcParams& params,
                                                         const shared::CameraParams& camera,
                                                         const RadianceSource& diffuse) {
    // 1. The camera samples as SDRC sees them; every glossy-buffer entry cleared.
    SdrcQueries q = queries(params, camera);
    // 2. Placement, coarse to fine (GlossyPlacement; SDRC §4.2: a new record where S(p) is empty).
    place(q.queries, params, diffuse);
    // 3. The interpolation, round by round (SDRC §4.4, Algorithm 1).
    interpolate(q, params, diffuse);
    return std::move(q.glossy);
}

}  // namespace rc
