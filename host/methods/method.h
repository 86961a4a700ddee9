// The method interface (DESIGN.md §2, "Methods share one interface"). A method is named,
// declares its command-line options and its AOV layers, is created once per render from the
// options (which it validates), renders frame after frame — keeping whatever state it wants from
// one frame to the next — and reports each frame's statistics. Methods are listed in one place,
// methods/registry.cpp; the render command loops over frames and knows no method by name.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "device/memory_need.h"
#include "device/program.h"
#include "image/image.h"
#include "methods/frame_scene.h"
#include "util/cli.h"

namespace rc {

// The settings every method reads: the scene's render defaults, overridden by -D and the
// command line's shared options.
struct MethodSettings {
    int width = 0;  // 0: the scene camera's
    int height = 0;
    int spp = 16;
    double time = 0.0;  // the scene's or -D's time budget (seconds); methods may ignore it
    uint64_t seed = 0;
    int max_depth = 64;
    int rr_depth = 3;
    int frame_count = 1;              // frames this render will ask for
    int first_frame = 0;              // the first of them (they come in order, one apart)
    std::vector<std::string> layers;  // the AOV layers that will be written (empty: all)

    // Whether `layer` will be written.
    bool writes_layer(const std::string& layer) const;

    // Copies what a method's own options struct shares with these settings: the image size,
    // samples per pixel, seed and (where it has them) the path depth limits.
    template <class Options>
    void apply_to(Options& options) const {
        options.width = width;
        options.height = height;
        options.spp = spp;
        options.seed = seed;
        if constexpr (requires { options.max_depth; }) {
            options.max_depth = max_depth;
            options.rr_depth = rr_depth;
        }
    }
};

// Width x height of a frame's image: the scene camera's where `width` or `height` is 0.
size_t image_pixels(int width, int height, const Scene& scene);

// What the frame loop offers a method while it renders.
struct FrameHooks {
    // Progress of the frame in [0, 1], with a short note ("12 spp", "photons").
    std::function<void(double fraction, const std::string& note)> progress;
    // Writes an intermediate image of the frame after `spp` samples per pixel (name.sppN.ext).
    std::function<void(int spp, const Image& image)> intermediate;
    // Calls `use` with another frame of the render's scene posed, its BVH and scene buffers on the
    // device (for methods that look ahead: temporal caching's two passes). The frame being
    // rendered stays as it was.
    std::function<void(int frame, const std::function<void(const FrameScene&)>& use)> visit_frame;
};

// A rendered frame: its image (every layer of the method), the counts the frame loop adds up,
// and the method's own figures for the stats file (phases, records, photons, ...).
struct FrameResult {
    Image image;
    int spp = 0;
    uint64_t rays = 0;
    uint64_t nonfinite_samples = 0;  // dropped; each names a bug
    int64_t first_nonfinite_pixel = -1;
    nlohmann::json stats = nlohmann::json::object();
};

class Method {
   public:
    virtual ~Method() = default;
    // Renders one frame. Called for the frames in order; a method may keep state between calls.
    virtual FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) = 0;
    // Every program its frames will build (Context::program's entry and options), for the
    // render to start them all at once in the background (issue 14). Exactly those: a test
    // renders every method and compares (tests/methods/prebuild_test.cpp).
    virtual std::vector<ProgramRequest> programs() const = 0;
    // The device memory its buffers hold together at their peak while it renders a frame of
    // `scene`, beside the scene's and the BVH's (device/memory_need.h), from its options before
    // any is made. What grows with what the method finds (cache records) it names in `excludes`.
    // Settings that cannot work on `device` (an image larger than its largest allocation) are
    // refused here (Error, exit status 2), before any device memory is used.
    virtual DeviceMemoryNeed device_memory_need(const Scene& scene,
                                                const DeviceInfo& device) const = 0;
    // Whether its frames can share their work among several devices (FrameScene::peers) with an
    // image that does not depend on the split; a render on several devices refuses the others.
    virtual bool splits_across_devices() const { return false; }
};

// What a method's beauty layer holds.
enum class Beauty {
    kRadiance,  // the radiance the camera sees: the scene's light, in its units
    // A geometry preview, not light: the first hit's shading normal n, turned to face the
    // camera, as (n + 1) / 2 times 0.25 + 0.75 |c| (c the cosine between n and the camera ray);
    // black where the ray escapes.
    kNormalPreview,
};

// A method as the registry lists it.
struct MethodEntry {
    std::string name;     // --method NAME
    std::string summary;  // one line for --help
    // Its own options (those shared by every method are the render command's). An option that
    // several methods declare is one option; given to a method that does not declare it, it is
    // refused by name.
    std::vector<OptionSpec> options;
    std::vector<std::string> aovs;  // its layers, in channel order ("beauty" first)
    // Reads and validates the method's options (Error with exit status 2 naming the option).
    std::function<std::unique_ptr<Method>(const ParsedArguments& arguments,
                                          const MethodSettings& settings)>
        create;
    Beauty beauty = Beauty::kRadiance;
};

}  // namespace rc
