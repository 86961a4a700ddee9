// `--method normals`: the geometry preview as a registered method.
#include <memory>

#include "methods/method.h"
#include "methods/normals/normals.h"
#include "methods/sample_passes.h"

namespace rc {
namespace {

class NormalsPreview final : public Method {
   public:
    explicit NormalsPreview(const MethodSettings& settings) : settings_(settings) {}

    // Without --time: --spp samples per pixel (one at the pixel's centre when 1). With --time:
    // passes of jittered samples (methods/sample_passes.h; there is no cache to build), at most
    // --spp a pass, drawing the samples one render of as many would.
    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        NormalsMethod method(frame);
        if (!(settings_.time > 0.0)) {
            return render_pass(method, {0, settings_.spp}, false);
        }
        FrameResult result = render_sample_passes(
            {settings_.time, settings_.spp, {}}, hooks,
            [&](const SamplePass& pass) { return render_pass(method, pass, true); });
        result.stats["spp"] = result.spp;
        return result;
    }

    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override { return {{"normals/normals.cl", ""}}; }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        DeviceMemoryNeed need;
        need.add("film", buffer_bytes(image_pixels(settings_.width, settings_.height, scene),
                                      sizeof(shared::float4)));
        return need;
    }

   private:
    // Camera samples pass.first .. pass.first + pass.spp - 1 of every pixel (`jitter`: jittered
    // even when that is one sample).
    FrameResult render_pass(NormalsMethod& method, const SamplePass& pass, bool jitter) {
        NormalsOptions options;
        options.width = settings_.width;
        options.height = settings_.height;
        options.samples_per_pixel = static_cast<unsigned>(pass.spp);
        options.first_sample = static_cast<unsigned>(pass.first);
        options.jitter =
            jitter ? NormalsOptions::Jitter::kAlways : NormalsOptions::Jitter::kUnlessOneSample;
        options.seed = settings_.seed;
        FrameResult result;
        std::vector<NormalsDeviceShare> devices;
        result.image = method.render(options, &devices);
        result.spp = pass.spp;
        if (!devices.empty()) {
            nlohmann::json shares = nlohmann::json::array();
            for (const NormalsDeviceShare& d : devices) {
                shares.push_back({{"device", d.device},
                                  {"chunks", d.chunks},
                                  {"pixels", d.pixels},
                                  {"seconds", d.seconds}});
            }
            result.stats["devices"] = shares;
        }
        return result;
    }

    MethodSettings settings_;
};

}  // namespace

// The preview has no options of its own.
struct NormalsPreviewOptions {};

MethodEntry normals_method_entry() {
    return method_entry<NormalsPreviewOptions>(
        {.name = "normals",
         .summary = "geometry preview: the first hit's shading normal",
         .aovs = {"beauty"},
         .beauty = Beauty::kNormalPreview,
         .table = {},
         .finish = nullptr,
         .check = nullptr,
         .create = [](const NormalsPreviewOptions&, const MethodSettings& settings) {
             return std::make_unique<NormalsPreview>(settings);
         }});
}

}  // namespace rc
