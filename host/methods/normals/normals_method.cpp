// `--method normals`: the geometry preview as a registered method.
#include <memory>

#include "methods/method.h"
#include "methods/normals/normals.h"

namespace rc {
namespace {

class NormalsPreview final : public Method {
   public:
    explicit NormalsPreview(const MethodSettings& settings) : settings_(settings) {}

    FrameResult render_frame(const FrameScene& frame, const FrameHooks&) override {
        NormalsMethod method(frame);
        NormalsOptions options;
        options.width = settings_.width;
        options.height = settings_.height;
        options.samples_per_pixel = static_cast<unsigned>(settings_.spp);
        options.seed = settings_.seed;
        FrameResult result;
        std::vector<NormalsDeviceShare> devices;
        result.image = method.render(options, &devices);
        result.spp = settings_.spp;
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

    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override { return {{"normals/normals.cl", ""}}; }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        DeviceMemoryNeed need;
        need.add("film", buffer_bytes(image_pixels(settings_.width, settings_.height, scene),
                                      sizeof(shared::float4)));
        return need;
    }

   private:
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
