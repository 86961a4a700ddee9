#include "methods/caching/pipeline_device_split.h"

#include <algorithm>

#include "methods/caching/device_splat.h"
#include "methods/device_shares.h"
#include "methods/device_split.h"
#include "methods/radiance_source.h"
#include "methods/scene_arguments.h"
#include "shared/film.h"
#include "shared/radiance_cache.h"
#include "util/timing.h"

namespace rc {
namespace {

constexpr const char* kProgram = "irradiance_cache/irradiance_cache.cl";
// Record ranges per device a batch is split into, and chunks of rows per device of the final
// pass: enough for the faster devices to take more.
constexpr size_t kRangesPerDevice = 4;
// The fewest hemisphere cells a range holds: smaller batches go to fewer devices, each range's
// uploads and launches worth their cost.
constexpr size_t kSmallestRangeCells = size_t{1} << 15;
constexpr int kChunksPerDevice = 16;

// A buffer the final pass reads: the first device's own, or a peer's copy of it (`copy`: its
// values, downloaded once; null on the first device).
template <class T>
struct FirstDeviceBuffer {
    FirstDeviceBuffer(Context& context, const Buffer<T>& first, const std::vector<T>* copy,
                      const char* name)
        : own(copy != nullptr ? Buffer<T>(context, *copy, name) : Buffer<T>()),
          buffer(copy != nullptr ? own : first) {}

    Buffer<T> own;
    const Buffer<T>& buffer;
};

// The first device's camera samples and glossy buffer as the host downloaded them for the peers.
struct FirstDeviceValues {
    std::vector<shared::GBufferSample> gbuffer;
    std::vector<shared::RcGlossySample> glossy;
};

// What one device holds for the final pass: the records, grid and splat tiles, the camera
// samples and glossy buffer (the first device's; copies on a peer), the splat buffer and film of
// the whole image (only its chunks written) and the render pass's counters.
struct FinalPassBuffers {
    FinalPassBuffers(Context& context, const FinalPassInput& input, const FirstDeviceValues* copy)
        : records(context, input.records),
          splat(context, input.tiles),
          gbuffer(context, input.gbuffer, copy != nullptr ? &copy->gbuffer : nullptr, "ic_gbuffer"),
          glossy(context, input.glossy, copy != nullptr ? &copy->glossy : nullptr, "ic_glossy"),
          sums(context, input.gbuffer.size(), "ic_sums"),
          film(context, static_cast<size_t>(input.width) * input.height * RC_CACHED_FILM_SLOTS,
               "ic_film"),
          counters(context, std::vector<unsigned>{0u, 0u, 0xffffffffu}, "ic_counters") {
        film.fill_zero();
    }

    DeviceRecords records;
    DeviceSplat splat;
    FirstDeviceBuffer<shared::GBufferSample> gbuffer;
    FirstDeviceBuffer<shared::RcGlossySample> glossy;
    Buffer<shared::float4> sums;
    Buffer<shared::float4> film;
    Buffer<unsigned> counters;
};

std::string device_name(const Context& context) {
    return context.device().spec() + " " + context.device().name;
}

}  // namespace

// One device: its frame and kernels, and what the current batch or final pass holds on it.
struct PipelineDeviceSplit::Device {
    explicit Device(const FrameScene& frame)
        : frame(frame),
          reduce(frame.context.kernel(kProgram, "ic_record_reduce")),
          splat(frame.context.kernel(kProgram, "ic_splat")),
          shade(frame.context.kernel(kProgram, "ic_shade")) {}

    // ic_record_cells built for `source` (one program per source kind).
    Kernel& cells_kernel(const RadianceSource& radiance) {
        const std::string options = radiance.build_options();
        auto found = cells.find(options);
        if (found == cells.end()) {
            Kernel kernel = frame.context.kernel("irradiance_cache/ic_record_cells.cl",
                                                 "ic_record_cells", options);
            found = cells.emplace(options, std::move(kernel)).first;
        }
        return found->second;
    }
    SceneArguments scene() const { return SceneArguments(frame.bvh, frame.device_scene); }

    FrameScene frame;
    Kernel reduce;
    Kernel splat;
    Kernel shade;
    std::map<std::string, Kernel> cells;
    std::unique_ptr<RadianceSource> source;  // the current batch's, made by its first range
    uint64_t rays = 0;                       // the current batch's
    std::unique_ptr<FinalPassBuffers> final_pass;
};

PipelineDeviceSplit::PipelineDeviceSplit(const FrameScene& frame) {
    devices_.push_back(std::make_unique<Device>(frame));
    for (const FrameScene& peer : *frame.peers) {
        devices_.push_back(std::make_unique<Device>(peer));
    }
    for (const auto& device : devices_) {
        shares_.push_back({device_name(device->frame.context)});
    }
    record_speeds_.assign(devices_.size(), 0.0);
}

PipelineDeviceSplit::~PipelineDeviceSplit() = default;

RecordBatchOutput PipelineDeviceSplit::compute_batch(const RecordBatchInput& batch,
                                                     const HostRecords* next_level) {
    const size_t count = batch.records.size();
    const size_t per_record = static_cast<size_t>(batch.params.strata_m) * batch.params.strata_n;
    const ItemRanges ranges(count, devices_.size(), kRangesPerDevice,
                            kSmallestRangeCells / std::max<size_t>(1, per_record));
    RecordBatchOutput out;
    out.payloads.resize(count);
    out.distances.resize(count);
    std::vector<Context*> contexts;
    for (const auto& device : devices_) {
        device->source.reset();
        device->rays = 0;
        contexts.push_back(&device->frame.context);
    }
    const auto slice = [](const auto& values, size_t begin, size_t end) {
        return std::vector<typename std::decay_t<decltype(values)>::value_type>(
            values.begin() + static_cast<long>(begin), values.begin() + static_cast<long>(end));
    };
    const DeviceSplit split = run_device_split(
        contexts, ranges.count,
        [&](size_t d, size_t item, const std::atomic<bool>&) {
            Device& device = *devices_[d];
            Context& context = device.frame.context;
            if (!device.source) {
                device.source =
                    next_level != nullptr
                        ? std::unique_ptr<RadianceSource>(std::make_unique<RecordLevelSource>(
                              context, *next_level, batch.params.max_weight))
                        : std::make_unique<PathContinuation>();
            }
            const auto [begin, end] = ranges.range(item);
            const size_t n = end - begin;
            const Buffer<shared::Record> records(context, slice(batch.records, begin, end),
                                                 "ic_batch_records");
            const Buffer<shared::float4> origins(context, slice(batch.origins, begin, end),
                                                 "ic_batch_origins");
            const Buffer<unsigned> streams(context, slice(batch.streams, begin, end),
                                           "ic_batch_streams");
            Buffer<shared::float4> cells(context, n * per_record, "ic_cells");
            Buffer<shared::IrradiancePayload> payloads(context, n, "ic_batch_payloads");
            Buffer<shared::float4> distances(context, n, "ic_distances");
            Buffer<unsigned> counters(context, 1, "ic_record_counters");
            counters.fill_zero();
            context.launch(device.cells_kernel(*device.source), n * per_record, batch.params,
                           device.scene(), records, origins, streams, *device.source, cells,
                           counters);
            context.launch(device.reduce, n, batch.params, cells, records, streams, payloads,
                           distances);
            const std::vector<shared::IrradiancePayload> p = payloads.download();
            const std::vector<shared::float4> h = distances.download();
            std::copy(p.begin(), p.end(), out.payloads.begin() + static_cast<long>(begin));
            std::copy(h.begin(), h.end(), out.distances.begin() + static_cast<long>(begin));
            device.rays += counters.download()[0];
        },
        {}, record_speeds_);
    for (size_t d = 0; d < devices_.size(); ++d) {
        Device& device = *devices_[d];
        device.source.reset();
        out.rays += device.rays;
        PipelineDeviceShare& share = shares_[d];
        share.record_ranges += split.items[d].size();
        size_t records = 0;
        for (size_t item : split.items[d]) {
            const auto [begin, end] = ranges.range(item);
            records += end - begin;
        }
        share.records += records;
        share.record_seconds += split.seconds[d];
        // Its speed for the next batches' split, where it computed records in this one.
        if (records > 0 && split.seconds[d] > 0.0) {
            record_speeds_[d] = static_cast<double>(records) / split.seconds[d];
        }
    }
    return out;
}

FinalPassOutput PipelineDeviceSplit::final_pass(const FinalPassInput& input) {
    const size_t pixels = static_cast<size_t>(input.width) * input.height;
    const size_t spp = static_cast<size_t>(input.spp);
    // The camera samples and the glossy buffer go to the peers from the first device.
    const FirstDeviceValues copy{input.gbuffer.download(), input.glossy.download()};
    const PixelChunks chunks(input.width, input.height, devices_.size(), kChunksPerDevice);
    std::vector<Context*> contexts;
    for (const auto& device : devices_) {
        contexts.push_back(&device->frame.context);
    }
    const DeviceSplit split = run_device_split(
        contexts, chunks.count,
        [&](size_t d, size_t chunk, const std::atomic<bool>&) {
            Device& device = *devices_[d];
            Context& context = device.frame.context;
            if (!device.final_pass) {
                device.final_pass =
                    std::make_unique<FinalPassBuffers>(context, input, d == 0 ? nullptr : &copy);
            }
            FinalPassBuffers& b = *device.final_pass;
            const auto [begin, end] = chunks.range(chunk);
            // Radiance cache splatting over the chunk's camera samples, then its render pass.
            context.launch_range(device.splat, begin * spp, end * spp, input.splat_params,
                                 b.splat.tiles, b.splat.tile_start, b.splat.tile_records,
                                 b.records.records, b.records.payloads, b.gbuffer.buffer, b.sums);
            context.launch_range(device.shade, begin, end, input.shade_params, input.camera,
                                 device.scene(), b.records.grid, b.records.cell_start,
                                 b.records.cell_records, b.records.records, b.records.payloads,
                                 b.sums, b.glossy.buffer, b.film, b.counters);
        },
        {});
    FinalPassOutput out;
    out.film.resize(pixels * RC_CACHED_FILM_SLOTS);
    for (size_t d = 0; d < devices_.size(); ++d) {
        Device& device = *devices_[d];
        PipelineDeviceShare& share = shares_[d];
        share.final_seconds += split.seconds[d];
        share.chunks += split.items[d].size();
        if (!device.final_pass) {
            continue;
        }
        const FinalPassBuffers& b = *device.final_pass;
        if (d == 0) {
            out.cache_bytes = b.records.bytes() + b.sums.bytes();
        }
        const std::vector<shared::float4> film = b.film.download();
        share.pixels += copy_chunks(chunks, split.items[d], film, RC_CACHED_FILM_SLOTS, out.film);
        const std::vector<unsigned> c = b.counters.download();
        out.rays += c[0];
        out.nonfinite_samples += c[1];
        out.first_nonfinite_pixel =
            first_nonfinite_of(out.first_nonfinite_pixel, c[1] > 0 ? int64_t{c[2]} : -1);
        device.final_pass.reset();
    }
    return out;
}

}  // namespace rc
