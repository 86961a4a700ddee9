#include "app/render_devices.h"

#include "device/device_features.h"
#include "device/device_list.h"
#include "util/error.h"

namespace rc {

std::vector<std::unique_ptr<Context>> open_render_devices(const ContextOptions& options,
                                                          const Method& method,
                                                          const std::string& name) {
    const std::vector<DeviceInfo> devices = select_devices(list_devices(), options.device_spec);
    if (devices.size() > 1 && !method.splits_across_devices()) {
        throw Error("--device names " + std::to_string(devices.size()) + " devices; --method " +
                        name +
                        " renders on one (the other methods split their work across devices)",
                    kExitUsage);
    }
    std::vector<std::unique_ptr<Context>> contexts;
    for (const DeviceInfo& device : devices) {
        ContextOptions one = options;
        // Each context its one device, by index ("all" or a list naming one device included).
        one.device_spec = options.device_spec.empty() ? "" : device.spec();
        contexts.push_back(std::make_unique<Context>(one));
        if (!one.allow_loop_cap) {
            // The loop probe's program first, one of the render's: a refused device waits for no
            // other build.
            contexts.back()->prebuild({{kDeviceFeaturesProgram, ""}});
            refuse_loop_capped_device(*contexts.back());
        }
        contexts.back()->prebuild(method.programs());  // all at once, in the background
    }
    return contexts;
}

PeerFrames::PeerFrames(const std::vector<std::unique_ptr<Context>>& contexts, const Scene& scene,
                       const Bvh& bvh, int frame) {
    for (size_t i = 1; i < contexts.size(); ++i) {
        Context& context = *contexts[i];
        const Bvh* own = &bvh;
        if (context.bvh_layout() != contexts[0]->bvh_layout()) {
            bvhs_.push_back(std::make_unique<Bvh>(build_bvh(scene.mesh, context.bvh_layout())));
            own = bvhs_.back().get();
        }
        device_bvhs_.push_back(std::make_unique<DeviceBvh>(context, *own));
        device_scenes_.push_back(std::make_unique<DeviceScene>(context, scene));
    }
    for (size_t i = 1; i < contexts.size(); ++i) {
        frames_.push_back(
            {*contexts[i], scene, *device_bvhs_[i - 1], *device_scenes_[i - 1], frame, nullptr});
    }
}

}  // namespace rc
