#include "methods/decomposition/decomp_device_split.h"

#include <memory>

#include "methods/device_shares.h"
#include "methods/device_split.h"
#include "methods/scene_arguments.h"
#include "shared/film.h"
#include "util/timing.h"

namespace rc {
namespace {

constexpr const char* kProgram = "decomposition/decomposition.cl";
constexpr int kChunksPerDevice = 16;  // enough for the faster devices to take more

// The first device's pass-1 buffers as the host downloaded them, once, for the peers.
struct FieldValues {
    explicit FieldValues(const DecompPassInput& input)
        : far_start(input.fields.far_start.download()),
          far_list(input.fields.far_list.download()),
          far_records(input.fields.far_records.download()),
          far_coefficients(input.fields.far_coefficients.download()),
          far_gradients(input.fields.far_gradients.download()),
          near_start(input.fields.near_start.download()),
          near_list(input.fields.near_list.download()),
          triangles(input.fields.triangles.download()),
          radiance(input.fields.radiance.download()) {}

    std::vector<int> far_start;
    std::vector<int> far_list;
    std::vector<shared::Record> far_records;
    std::vector<shared::ShSample> far_coefficients;
    std::vector<shared::ShGradient> far_gradients;
    std::vector<int> near_start;
    std::vector<int> near_list;
    std::vector<shared::NearTriangle> triangles;
    std::vector<shared::float4> radiance;
};

// A peer's copies of what pass 2 reads.
struct PeerCopies {
    PeerCopies(Context& context, const DecompPassInput& input, const FieldValues& values)
        : gbuffer(context, input.samples, "decomp_gbuffer"),
          far_start(context, values.far_start, "decomp_far_start"),
          far_list(context, values.far_list, "decomp_far_list"),
          far_records(context, values.far_records, "decomp_far_records"),
          far_coefficients(context, values.far_coefficients, "decomp_far_sh"),
          far_gradients(context, values.far_gradients, "decomp_far_gradients"),
          near_start(context, values.near_start, "decomp_near_start"),
          near_list(context, values.near_list, "decomp_near_list"),
          triangles(context, values.triangles, "decomp_triangles"),
          radiance(context, values.radiance, "decomp_radiance") {}

    DecompFields fields(const DecompPassInput& input) const {
        return {input.fields.far_grid,
                far_start,
                far_list,
                far_records,
                far_coefficients,
                far_gradients,
                input.fields.near_grid,
                near_start,
                near_list,
                triangles,
                radiance};
    }

    Buffer<shared::GBufferSample> gbuffer;
    Buffer<int> far_start;
    Buffer<int> far_list;
    Buffer<shared::Record> far_records;
    Buffer<shared::ShSample> far_coefficients;
    Buffer<shared::ShGradient> far_gradients;
    Buffer<int> near_start;
    Buffer<int> near_list;
    Buffer<shared::NearTriangle> triangles;
    Buffer<shared::float4> radiance;
};

// One device: its frame, kernels, what it reads (the first device's buffers or its copies) and
// the terms, film and counters of the whole image it writes (only its chunks).
struct PassDevice {
    PassDevice(const FrameScene& frame, const DecompPassInput& input, const FieldValues* values)
        : frame(frame),
          evaluate(frame.context.kernel(kProgram, "decomp_irradiance", input.build_options)),
          shade(frame.context.kernel(kProgram, "decomp_shade", input.build_options)),
          copies(values != nullptr ? std::make_unique<PeerCopies>(frame.context, input, *values)
                                   : nullptr),
          gbuffer(copies ? copies->gbuffer : input.gbuffer),
          fields(copies ? copies->fields(input) : input.fields),
          terms(frame.context, input.samples.size(), "decomp_irradiance"),
          film(frame.context,
               static_cast<size_t>(input.params.width) * input.params.height * RC_DECOMP_FILM_SLOTS,
               "decomp_film"),
          counters(frame.context, std::vector<unsigned>{0u, 0u, 0xffffffffu}, "decomp_counters") {}

    // Both terms at the camera samples of pixels [begin, end), then their render pass.
    void run(const DecompPassInput& input, size_t begin, size_t end) {
        const size_t spp = static_cast<size_t>(input.params.camera_spp);
        const SceneArguments scene(frame.bvh, frame.device_scene);
        const DecompFields& f = fields;
        frame.context.launch_range(evaluate, begin * spp, end * spp, input.params, scene, gbuffer,
                                   f.far_grid.grid, f.far_start, f.far_list, f.far_records,
                                   f.far_coefficients, f.far_gradients, f.near_grid.grid,
                                   f.near_start, f.near_list, f.triangles, f.radiance, terms);
        frame.context.launch_range(shade, begin, end, input.params, input.camera, scene, terms,
                                   film, counters);
    }

    FrameScene frame;
    Kernel evaluate;
    Kernel shade;
    std::unique_ptr<PeerCopies> copies;
    const Buffer<shared::GBufferSample>& gbuffer;
    DecompFields fields;
    Buffer<shared::DecompIrradiance> terms;
    Buffer<shared::float4> film;
    Buffer<unsigned> counters;
};

// Adds `device`'s chunks of terms and film, its counters and its share to `out`.
void merge_device(const PassDevice& device, const PixelChunks& chunks,
                  const std::vector<size_t>& items, size_t spp, DecompDeviceShare& share,
                  DecompPassOutput& out) {
    share.chunks = items.size();
    share.pixels =
        copy_chunks(chunks, items, device.film.download(), RC_DECOMP_FILM_SLOTS, out.film);
    copy_chunks(chunks, items, device.terms.download(), spp, out.terms);
    const std::vector<unsigned> c = device.counters.download();
    share.shading_rays = c[0];
    out.shading_rays += c[0];
    out.nonfinite_samples += c[1];
    out.first_nonfinite_pixel =
        first_nonfinite_of(out.first_nonfinite_pixel, c[1] > 0 ? int64_t{c[2]} : -1);
}

}  // namespace

DecompPassOutput decomp_device_pass(const FrameScene& frame, const DecompPassInput& input) {
    const auto start = SteadyClock::now();
    const size_t pixels = static_cast<size_t>(input.params.width) * input.params.height;
    const size_t spp = static_cast<size_t>(input.params.camera_spp);
    const FieldValues values(input);
    std::vector<std::unique_ptr<PassDevice>> devices;
    devices.push_back(std::make_unique<PassDevice>(frame, input, nullptr));
    for (const FrameScene& peer : *frame.peers) {
        devices.push_back(std::make_unique<PassDevice>(peer, input, &values));
    }
    std::vector<Context*> contexts;
    for (const auto& device : devices) {
        contexts.push_back(&device->frame.context);
    }
    const PixelChunks chunks(input.params.width, input.params.height, devices.size(),
                             kChunksPerDevice);
    const DeviceSplit split =
        run_device_split(contexts, chunks.count,
                         [&](size_t d, size_t chunk, const std::atomic<bool>&) {
                             const auto [begin, end] = chunks.range(chunk);
                             devices[d]->run(input, begin, end);
                         },
                         {});
    DecompPassOutput out;
    out.terms.resize(pixels * spp);
    out.film.resize(pixels * RC_DECOMP_FILM_SLOTS);
    for (size_t d = 0; d < devices.size(); ++d) {
        const Context& context = devices[d]->frame.context;
        DecompDeviceShare share;
        share.device = context.device().spec() + " " + context.device().name;
        share.seconds = split.seconds[d];
        merge_device(*devices[d], chunks, split.items[d], spp, share, out);
        out.shares.push_back(share);
    }
    out.evaluation_seconds = seconds_since(start);
    return out;
}

}  // namespace rc
