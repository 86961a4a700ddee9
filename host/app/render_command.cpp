// `radcache render SCENE [options]`: loads the scene, creates the method the registry names
// (methods/registry.cpp), and renders frame after frame with it, writing one image per frame
// and, when asked, the stats file.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "app/device_options.h"
#include "app/option_reference.h"
#include "app/progress_bar.h"
#include "app/render_devices.h"
#include "app/render_job.h"
#include "app/render_parts.h"
#include "app/render_stats.h"
#include "bvh/device_bvh.h"
#include "image/denoiser.h"
#include "image/image_io.h"
#include "methods/registry.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {
namespace {

// What the frame will hold on the device (device/memory_need.h): what earlier frames left (a
// method's state), the scene's and the BVH's buffers and the method's at their peak.
DeviceMemoryNeed frame_need(const Context& context, const Scene& scene, const Bvh& bvh,
                            const Method& method) {
    DeviceMemoryNeed need;
    if (context.device_memory().in_use > 0) {
        need.add("held from earlier frames", context.device_memory().in_use);
    }
    need.add("scene", DeviceScene::bytes_for(scene));
    need.add("BVH", DeviceBvh::bytes_for(bvh));
    need.add_all(method.device_memory_need(scene, context.device()));
    return need;
}

// Warns (an error under --strict) when --frames reaches outside the scene's frame range: the
// frames there hold the poses of its nearest end, or, in a scene without animation tracks, are
// all the same picture.
void warn_unless_frames_in_range(const FrameRange& frames, const Animation& animation) {
    const auto start = static_cast<long long>(animation.frame_start);
    const auto end = static_cast<long long>(animation.frame_end);
    if (!frames.given || (frames.first >= start && frames.last <= end)) {
        return;
    }
    const std::string asked =
        "--frames " + std::to_string(frames.first) + ":" + std::to_string(frames.last);
    const std::string range = std::to_string(start) + ":" + std::to_string(end);
    if (animation.empty()) {
        log_warning(asked + ": the scene has no animation (its frame range is " + range +
                    "): every frame is the same picture");
        return;
    }
    std::string held;
    if (frames.first < start) {
        held = "frames " + std::to_string(frames.first) + " to " +
               std::to_string(std::min<long long>(frames.last, start - 1)) +
               " hold the poses of frame " + std::to_string(start);
    }
    if (frames.last > end) {
        held += (held.empty() ? "" : ", ") + std::string("frames ") +
                std::to_string(std::max<long long>(frames.first, end + 1)) + " to " +
                std::to_string(frames.last) + " hold the poses of frame " + std::to_string(end);
    }
    log_warning(asked + " reaches outside the scene's frame range " + range + ": " + held);
}

// FrameHooks::visit_frame: `scene` posed at another frame, with its BVH and scene buffers on
// `context`'s device for the call.
std::function<void(int, const std::function<void(const FrameScene&)>&)> visit_frame_hook(
    Context& context, const Scene& scene) {
    return [&context, &scene](int other, const std::function<void(const FrameScene&)>& use) {
        Scene posed = scene;
        posed.set_frame(other);
        const Bvh other_bvh = build_bvh(posed.mesh, context.bvh_layout());
        const DeviceBvh other_device_bvh(context, other_bvh);
        const DeviceScene other_device_scene(context, posed);
        use({context, posed, other_device_bvh, other_device_scene, other});
    };
}

// The layers less `name`.
std::vector<std::string> without_layer(std::vector<std::string> layers, const std::string& name) {
    layers.erase(std::remove(layers.begin(), layers.end(), name), layers.end());
    return layers;
}

// Poses the scene at `frame`, renders it with `method` (on every device of `contexts`, the
// first holding the method's state) and writes its image.
void render_frame(const RenderJob& job, int frame,
                  const std::vector<std::unique_ptr<Context>>& contexts, Scene& scene, Bvh& bvh,
                  Method& method, const Denoiser* denoiser, PartIdentity identity,
                  RenderTotals& totals) {
    Context& context = *contexts[0];
    if (static_cast<double>(frame) != scene.frame) {
        scene.set_frame(frame);
    }
    const std::filesystem::path output = frame_path(job.output_pattern, frame);
    auto start = SteadyClock::now();
    bvh = build_bvh(scene.mesh, context.bvh_layout());
    totals.phase("bvh") += seconds_since(start);
    // The whole frame is refused before its first buffer when it cannot fit.
    const DeviceMemoryNeed need = frame_need(context, scene, bvh, method);
    for (const auto& device : contexts) {
        check_device_memory_need(*device, frame_need(*device, scene, bvh, method));
    }
    totals.set_frame_need(need);
    start = SteadyClock::now();
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    const PeerFrames peers(contexts, scene, bvh, frame);
    totals.phase("upload") += seconds_since(start);

    start = SteadyClock::now();
    // The intermediate images (--save-every-pow2) are the noisy ones, even with --denoise.
    const std::vector<std::string> noisy_layers = without_layer(job.layers, "beauty_noisy");
    const auto written = [&](const Image& image) {
        return job.layers.empty()     ? image
               : noisy_layers.empty() ? select_layers(image, {"beauty"})
                                      : select_layers(image, noisy_layers);
    };
    ProgressBar progress(job.frames.given ? "frame " + std::to_string(frame) : "render", !quiet());
    FrameHooks hooks;
    hooks.progress = [&](double fraction, const std::string& note) {
        progress.update(fraction, note);
    };
    hooks.intermediate = [&](int spp, const Image& image) {
        write_image(intermediate_path(output, spp), written(image), job.write_options);
    };
    hooks.visit_frame = visit_frame_hook(context, scene);
    FrameResult result = method.render_frame(
        {context, scene, device_bvh, device_scene, frame, &peers.frames()}, hooks);
    progress.finish();
    totals.phase("render") += seconds_since(start);
    if (denoiser != nullptr && frame >= job.write_from) {
        start = SteadyClock::now();
        result.image = denoiser->denoise(result.image);
        totals.phase("denoise") += seconds_since(start);
    }

    if (frame < job.write_from) {  // --write-from: a warm-up frame, not written
        log_note("frame " + std::to_string(frame) + " rendered, not written (--write-from " +
                 std::to_string(job.write_from) + ")");
        totals.add_frame(frame, {}, result, context);
        return;
    }
    start = SteadyClock::now();
    if (job.samples.end == 0) {
        identity.samples = {0, result.spp};
    }
    write_image(output, part_image(result, job.layers, job.write_sums, identity, frame),
                job.write_options);
    totals.phase("write") += seconds_since(start);
    log_note("wrote " + output.string() + " (" + std::to_string(identity.crop.width()) + "x" +
             std::to_string(identity.crop.height()) + ", " + std::to_string(result.spp) + " spp)");
    totals.add_frame(frame, output, result, context);
}

// --dry-run: the first frame posed and on the device, and what the method would do with it
// (Method::plan) in the stats file; no image. Returns the exit status.
int dry_run(const RenderJob& job, int frame, Context& context, Scene& scene, Method& method,
            const std::string& method_name) {
    if (static_cast<double>(frame) != scene.frame) {
        scene.set_frame(frame);
    }
    const Bvh bvh = build_bvh(scene.mesh, context.bvh_layout());
    check_device_memory_need(context, frame_need(context, scene, bvh, method));
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    FrameHooks hooks;
    hooks.progress = [](double, const std::string&) {};
    hooks.intermediate = [](int, const Image&) {};
    hooks.visit_frame = visit_frame_hook(context, scene);
    const std::optional<nlohmann::json> plan =
        method.plan({context, scene, device_bvh, device_scene, frame}, hooks);
    if (!plan) {
        log_note("dry run: " + method_name + " renders as its options say; it has nothing to plan");
    }
    if (!job.stats.empty()) {
        const nlohmann::json stats = {{"dry_run", true},
                                      {"method", method_name},
                                      {"frame", frame},
                                      {"plan", plan ? *plan : nlohmann::json(nullptr)}};
        write_file_atomically(job.stats, stats.dump(2) + "\n");
    }
    return 0;
}

// --list-knobs: the quality knobs of --method, or of every method, as text or (--json) JSON.
int list_knobs(const ParsedArguments& arguments) {
    if (!arguments.positionals().empty()) {
        throw Error("--list-knobs takes no scene", kExitUsage);
    }
    std::vector<const MethodEntry*> methods;
    if (arguments.has("--method")) {
        methods.push_back(&find_method(arguments.value("--method")));
    } else {
        for (const MethodEntry& entry : method_registry()) {
            methods.push_back(&entry);
        }
    }
    if (arguments.has("--json")) {
        nlohmann::json json = nlohmann::json::array();
        for (const MethodEntry* entry : methods) {
            json.push_back(knobs_json(*entry));
        }
        std::cout << (methods.size() == 1 ? json[0] : json).dump(2) << "\n";
        return 0;
    }
    for (const MethodEntry* entry : methods) {
        std::cout << knobs_text(*entry);
    }
    return 0;
}

// --denoise: Error (exit status 2) unless the method writes the layers the denoiser reads.
void check_denoise_layers(const RenderJob& job, const MethodEntry& entry) {
    for (const char* layer : {"beauty", "albedo", "normal"}) {
        if (job.denoise.given &&
            std::find(entry.aovs.begin(), entry.aovs.end(), layer) == entry.aovs.end()) {
            throw Error("--denoise: method " + entry.name + " writes no " + layer +
                            " layer for the denoiser to read",
                        kExitUsage);
        }
    }
}

// Renders the scene of `arguments` frame after frame; returns the exit status.
int render(const ParsedArguments& arguments) {
    if (arguments.has("--list-knobs")) {
        return list_knobs(arguments);
    }
    if (arguments.has("--json")) {
        throw Error("--json applies to --list-knobs only", kExitUsage);
    }
    const auto total_start = SteadyClock::now();
    RenderJob job = read_render_job(arguments);
    set_quiet(arguments.has("--quiet"));
    set_strict(arguments.has("--strict"));
    OutputBatch outputs;  // every file is written at the end, or none
    RenderTotals totals;

    auto start = SteadyClock::now();
    const RecordedFiles scene_files;  // what the scene read: no output may overwrite it
    Scene scene = load_scene(job.scene, scene_files, arguments.value("--camera"),
                             environment_override(arguments));
    totals.phase("load") = seconds_since(start);
    if (scene.dropped_degenerate > 0) {
        log_note("dropped " + std::to_string(scene.dropped_degenerate) + " degenerate triangles");
    }
    if (scene.dropped_repeated > 0) {
        log_note("dropped " + std::to_string(scene.dropped_repeated) +
                 " triangles that repeat an earlier triangle of their shape (the same vertices)");
    }
    scene.base_camera.filter = pixel_filter(arguments, scene.base_camera.filter);
    scene.camera.filter = scene.base_camera.filter;
    scene.base_camera.sampler = pixel_sampler(arguments, scene.base_camera.sampler);
    scene.camera.sampler = scene.base_camera.sampler;
    const RenderSettings settings = render_settings(arguments, scene.render);
    job.write_options.exposure = settings.exposure;
    const MethodEntry& entry = find_method(settings.method);
    read_method_options(entry, arguments, &job);
    check_layers(entry, job.denoise.given ? without_layer(job.layers, "beauty_noisy") : job.layers);
    const int first =
        job.frames.given ? job.frames.first : static_cast<int>(scene.animation.frame_start);
    const int last = job.frames.given ? job.frames.last : first;
    check_run_files(job, entry, arguments, scene_files, first, last);
    const int width = static_cast<int>(arguments.integer("--width", scene.camera.width));
    const int height = static_cast<int>(arguments.integer("--height", scene.camera.height));
    check_part_options(job, entry, width, height, settings.time);
    const PartIdentity identity = part_identity(arguments, scene_files.content_digest(), entry.name,
                                                width, height, job.crop, job.samples);
    warn_unless_frames_in_range(job.frames, scene.animation);
    // The denoiser before any work, and its predicted time out of each frame's --time.
    check_denoise_layers(job, entry);
    const std::unique_ptr<Denoiser> denoiser = open_denoiser(job.denoise);
    RenderSettings budget = settings;
    const double denoise_seconds =
        denoiser && settings.time > 0.0 ? denoiser->predicted_seconds(width, height) : 0.0;
    budget.time = settings.time - denoise_seconds;
    if (settings.time > 0.0 && budget.time < 0.1 * settings.time) {
        throw Error("--time " + std::to_string(settings.time) +
                        " s: the denoise alone is predicted "
                        "to take " +
                        std::to_string(denoise_seconds) + " s a frame",
                    kExitUsage);
    }
    const std::unique_ptr<Method> method =
        entry.create(job.method_options, method_settings(arguments, budget, job, first, last));

    start = SteadyClock::now();
    const std::vector<std::unique_ptr<Context>> contexts =
        open_render_devices(context_options(arguments), *method, entry.name);
    Context& context = *contexts[0];
    totals.phase("device") = seconds_since(start);
    std::string names;
    for (const auto& device : contexts) {
        names += (names.empty() ? "" : ", ") +
                 (contexts.size() > 1 ? device->device().spec() + " " : "") + device->device().name;
    }
    log_note(std::string(contexts.size() > 1 ? "devices " : "device ") + names + "; " +
             std::to_string(scene.mesh.triangle_count()) + " triangles, " +
             std::to_string(scene.lights.lights.size()) + " lights");
    if (arguments.has("--dry-run")) {
        const int status = dry_run(job, first, context, scene, *method, entry.name);
        outputs.commit();
        return status;
    }
    Bvh bvh;
    for (long long frame = first; frame <= last; ++frame) {
        render_frame(job, static_cast<int>(frame), contexts, scene, bvh, *method, denoiser.get(),
                     identity, totals);
    }
    if (!job.stats.empty()) {
        nlohmann::json stats =
            totals.json(settings, scene, context, bvh, seconds_since(total_start));
        if (denoiser) {
            stats["denoise"] = {{"library", denoiser->library_path()},
                                {"quality", job.denoise.quality}};
            if (settings.time > 0.0) {  // predicted only where it is taken out of --time
                stats["denoise"]["predicted_seconds_per_frame"] = denoise_seconds;
            }
        }
        write_file_atomically(job.stats, stats.dump(2) + "\n");
    }
    outputs.commit();
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.1f", seconds_since(total_start));
    log_note("done in " + std::string(seconds) + " s (scene, device, kernels and frames)");
    return 0;
}

}  // namespace

CommandSpec render_command() {
    return {.name = "render",
            .synopsis = "render SCENE",
            .summary = "render a scene to an image",
            .description =
                "Renders SCENE (a scene.json file, or a glTF 2.0 .gltf/.glb file) to an image.",
            .options = render_option_specs(),
            .run = render};
}

}  // namespace rc
