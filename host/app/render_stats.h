// The figures of a `radcache render` run: totals over its frames, warnings for dropped samples,
// and the --stats JSON file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "bvh/bvh.h"
#include "device/context.h"
#include "device/memory_need.h"
#include "methods/method.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

namespace rc {

class RenderTotals {
   public:
    // Seconds of the phases every render has: load, device, bvh, upload, render, write.
    double& phase(const std::string& name) { return seconds_[name]; }

    // Adds a frame (its output, counts, the method's figures, and the host and device memory of
    // the frame: now, and the peak since the previous frame); warns about dropped samples.
    void add_frame(int frame, const std::filesystem::path& output, const FrameResult& result,
                   Context& context);

    // The device memory the next frame was checked to need before its buffers were made
    // (device/memory_need.h), reported with the frame's measured peak.
    void set_frame_need(const DeviceMemoryNeed& need) { frame_need_ = need; }

    // The stats file's JSON.
    nlohmann::json json(const RenderSettings& settings, const Scene& scene, const Context& context,
                        const Bvh& bvh, double total_seconds) const;

   private:
    std::map<std::string, double> seconds_;
    nlohmann::json frames_ = nlohmann::json::array();
    uint64_t rays_ = 0;
    uint64_t nonfinite_ = 0;
    int64_t first_nonfinite_pixel_ = -1;
    int spp_ = 0;
    int width_ = 0;
    int height_ = 0;
    uint64_t host_peak_ = 0;
    size_t device_peak_ = 0;
    DeviceMemoryNeed frame_need_;
    uint64_t device_need_ = 0;
};

}  // namespace rc
