// The method interface (DESIGN.md §2, "Methods share one interface"). A method is named,
// declares its command-line options and its AOV layers, is created once per render from the
// options (which it validates), renders frame after frame — keeping whatever state it wants from
// one frame to the next — and reports each frame's statistics. Methods are listed in one place,
// methods/registry.cpp; the render command loops over frames and knows no method by name.
#pragma once

#include <any>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "device/memory_need.h"
#include "device/program.h"
#include "image/image.h"
#include "methods/frame_scene.h"
#include "methods/shared_settings.h"
#include "util/cli.h"
#include "util/option_table.h"

namespace rc {

// The settings every method reads: the scene's render defaults, overridden by -D and the
// command line's shared options.
struct MethodSettings : SharedSettings {
    double time = 0.0;    // the scene's or -D's time budget (seconds); methods may ignore it
    int frame_count = 1;  // frames of the clip from first_frame (the render may ask for fewer:
                          // --clip-end)
    int first_frame = 0;  // the first of them (they come in order, one apart)
    std::vector<std::string> layers;  // the AOV layers that will be written (empty: all)
    bool write_sums = false;          // --write-sums: the frame's FrameResult::sums are written too

    // Whether `layer` will be written.
    bool writes_layer(const std::string& layer) const;

    // Sets the shared settings of a method's own options struct.
    void apply_to(SharedSettings& options) const { options.share(*this); }
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
    // Of the frame's time, the seconds that built its cache (the rest grows with the samples);
    // a render by time (methods/sample_passes.h) plans its passes from it. 0: not told.
    double cache_seconds = 0.0;
    // With MethodSettings::write_sums, the per-pixel sums of the frame's samples
    // (image/sample_sums.h), of the same pixels as `image`.
    Image sums;
};

class Method {
   public:
    virtual ~Method() = default;
    // Renders one frame. Called for the frames in order; a method may keep state between calls.
    virtual FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) = 0;
    // Every program its frames will build (Context::program's entry and options), for the
    // render to start them all at once in the background. Exactly those: a test
    // renders every method and compares (tests/methods/prebuild_test.cpp).
    virtual std::vector<ProgramRequest> programs() const = 0;
    // The device memory its buffers hold together at their peak while it renders a frame of
    // `scene`, beside the scene's and the BVH's (device/memory_need.h), from its options before
    // any is made. What grows with what the method finds (cache records) it names in `excludes`.
    // Settings that cannot work on `device` (an image larger than its largest allocation) are
    // refused here (Error, exit status 2), before any device memory is used.
    virtual DeviceMemoryNeed device_memory_need(const Scene& scene,
                                                const DeviceInfo& device) const = 0;
    // What it would do with `frame` without rendering it (render --dry-run), for a method that
    // decides as it renders (auto: its pilot and plan); none: its options say it all.
    virtual std::optional<nlohmann::json> plan(const FrameScene& frame, const FrameHooks& hooks) {
        (void)frame;
        (void)hooks;
        return std::nullopt;
    }
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

// A method's options as read from the command line, once (its own options struct).
using MethodOptions = std::any;

// A method as the registry lists it.
struct MethodEntry {
    std::string name;     // --method NAME
    std::string summary;  // one line for --help
    // Its own option table (those shared by every method are the render command's), defaults
    // filled in; `options` is the same as CLI11 declares them, each help line with its default.
    // An option that several methods declare is one option; given to a method that does not
    // declare it, it is refused by name.
    std::vector<OptionInfo> table;
    std::vector<OptionSpec> options;
    std::vector<std::string> aovs;  // its layers, in channel order ("beauty" first)
    // Reads its options into its options struct (Error with exit status 2 naming the option for
    // a combination that cannot work); reads no scene and no device.
    std::function<MethodOptions(const ParsedArguments& arguments)> read;
    // Checks its options against the shared settings (Error with exit status 2 naming the
    // option); `create` checks them too.
    std::function<void(const MethodOptions& options, const MethodSettings& settings)> check;
    std::function<std::unique_ptr<Method>(const MethodOptions& options,
                                          const MethodSettings& settings)>
        create;
    // The value of each option of `table` in `options`, in the table's order, as the option
    // takes it ("0.35", "auto", "8px").
    std::function<std::vector<std::string>(const MethodOptions& options)> values;
    Beauty beauty = Beauty::kRadiance;
};

// What a method's folder declares: its table over its options struct, the rules its options
// follow between themselves (`finish`: defaults that depend on other options, combinations that
// cannot work; it sees which options were given) and with the shared settings (`check`), and how
// the method is made from them.
template <class Options>
struct MethodDefinition {
    std::string name;
    std::string summary;
    std::vector<std::string> aovs;
    Beauty beauty = Beauty::kRadiance;
    OptionTable<Options> table;
    std::function<void(Options& options, const ParsedArguments& arguments)> finish;
    std::function<void(const Options& options, const MethodSettings& settings)> check;
    std::function<std::unique_ptr<Method>(const Options& options, const MethodSettings& settings)>
        create;
};

template <class Options>
MethodEntry method_entry(MethodDefinition<Options> definition) {
    MethodEntry entry;
    entry.name = definition.name;
    entry.summary = definition.summary;
    entry.aovs = definition.aovs;
    entry.beauty = definition.beauty;
    entry.table = definition.table.infos();
    for (const OptionInfo& info : entry.table) {
        entry.options.push_back(info.spec);
        entry.options.back().help = info.help_with_default();
    }
    const auto shared = std::make_shared<MethodDefinition<Options>>(std::move(definition));
    entry.read = [shared](const ParsedArguments& arguments) -> MethodOptions {
        Options options{};
        shared->table.read(arguments, &options);
        if (shared->finish) {
            shared->finish(options, arguments);
        }
        return options;
    };
    entry.check = [shared](const MethodOptions& options, const MethodSettings& settings) {
        if (shared->check) {
            shared->check(std::any_cast<const Options&>(options), settings);
        }
    };
    entry.create = [shared](const MethodOptions& options, const MethodSettings& settings) {
        const Options& typed = std::any_cast<const Options&>(options);
        if (shared->check) {
            shared->check(typed, settings);
        }
        return shared->create(typed, settings);
    };
    entry.values = [shared](const MethodOptions& options) {
        std::vector<std::string> values;
        for (const auto& table_entry : shared->table.entries()) {
            values.push_back(table_entry.text(std::any_cast<const Options&>(options)));
        }
        return values;
    };
    return entry;
}

}  // namespace rc
