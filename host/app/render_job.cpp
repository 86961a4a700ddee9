#include "app/render_job.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "app/denoise_options.h"
#include "app/device_options.h"
#include "app/render_parts.h"
#include "methods/registry.h"
#include "scene/animation.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/text.h"

namespace rc {

std::vector<OptionSpec> render_option_specs() {
    std::vector<OptionSpec> specs = {
        {"--output", "-o", "FILE",
         "output image: .exr (all AOVs), .hdr, .pfm or .png (default out.png); with --frames, "
         "#### in the name becomes the frame number"},
        {"--method", "", "NAME",
         "rendering method: " + method_names() + " (default pt; each listed below)"},
        OptionSpec{"--spp", "", "N", "samples per pixel (default: the scene's render.spp, else 16)"}
            .integers(1, 1 << 24),
        OptionSpec{"--time", "", "SECONDS",
                   "render each frame for this long instead of to --spp: pt adds passes of one "
                   "sample per pixel; a caching method builds its cache with the first sample "
                   "per pixel, then adds samples over it (at most --spp a pass) while the time "
                   "left holds them (default: the scene's render.time, else --spp decides)"}
            .numbers(0.0, 1e7),
        OptionSpec{"--seed", "", "N", "random seed (default: the scene's render.seed, else 0)"}
            .integers(0, 1LL << 62),
        OptionSpec{"--width", "", "N", "image width in pixels (default: the scene camera's)"}
            .integers(1, 1 << 16),
        OptionSpec{"--height", "", "N", "image height in pixels (default: the scene camera's)"}
            .integers(1, 1 << 16),
        {"--camera", "", "NAME",
         "glTF scenes: the camera of that name (or its node's name; default: the first)"},
        {"--environment", "", "COLOUR|FILE",
         "light the scene with an environment: a constant radiance, R,G,B or one value for all "
         "three, each in [0, 1e9], or a lat-long image (EXR, HDR, PNG, ...; the top row looks up "
         "+y, as Mitsuba's envmap): added when the scene has none, replacing the one it has (as "
         "a glTF viewer lights a model)"},
        OptionSpec{"--filter", "", "NAME",
                   "pixel reconstruction filter: box, tent or gaussian (default: the scene "
                   "camera's, else box)"}
            .one_of({"box", "tent", "gaussian"}),
        OptionSpec{"--filter-radius", "", "R",
                   "the filter's radius in pixels, in (0, 16] (default: box 0.5, tent 1, "
                   "gaussian 1.5)"}
            .numbers(kMinFilterRadius, kMaxFilterRadius),
        OptionSpec{"--sampler", "", "NAME",
                   "where a pixel's camera samples fall: sobol (a randomly shifted Sobol' "
                   "sequence per pixel; edges converge at about 1/N) or independent (uniform "
                   "random; the stddev layer is then exact) (default: the scene camera's, else "
                   "sobol)"}
            .one_of({"sobol", "independent"}),
        {"--frames", "", "A:B", "render frames A to B of an animated scene, one image each"},
        {"--write-from", "", "F",
         "with --frames A:B: frames A to F-1 are rendered (a temporal cache's warm-up, a farm "
         "task's pre-roll) but not written; F in A..B"},
        {"--clip-end", "", "F",
         "with --frames A:B: the clip goes on to frame F >= B, of which these frames are a part "
         "(a farm task's): temporal caching places its records ahead and ends their lives as a "
         "render of A to F does, so frames A to B are that render's (default B)"},
        {"-D", "", "KEY=VALUE",
         "override a render default: method, spp, time, max_depth, rr_depth, seed, exposure", true},
        OptionSpec{"--exposure", "", "STOPS", "exposure applied before 8-bit encoding (default 0)"}
            .numbers(-64.0, 64.0),
        {"--half", "", "", ".exr: store half floats"},
        {"--aovs", "", "LIST", ".exr: the layers to write, comma-separated (default all)"},
        {"--stats", "", "FILE", "write timings and counts as JSON"},
        {"--dry-run", "", "",
         "decide without rendering: --method auto's pilot and plan (its line on stderr, and in "
         "--stats); no image is written"},
        {"--quiet", "-q", "", "print nothing but errors"},
        {"--list-knobs", "", "",
         "print the quality knobs of --method (default: of every method) from its option table "
         "and exit (no scene needed)"},
        {"--json", "", "", "--list-knobs: as JSON"},
        {"--strict", "", "", "treat every warning (no emitter, dropped samples, ...) as an error"},
        {"--crop", "", "X0:X1,Y0:Y1",
         "render only columns X0 to X1 - 1 and rows Y0 to Y1 - 1 of the image, each pixel as the "
         "whole render has it; the image is the window's (.exr: placed in the whole image's "
         "window), for radcache merge (docs/farm.md)"},
        {"--sample-range", "", "S0:S1",
         "pt: render samples S0 to S1 - 1 of each pixel, those a single render of S1 samples "
         "draws (instead of --spp), for radcache merge (docs/farm.md)"},
        {"--write-sums", "", "",
         "pt, .exr: also write each pixel's sums of samples, of the squares of its beauty samples "
         "and its count of samples (layers beauty_sum, beauty_sumsq, direct_sum, indirect_sum, "
         "albedo_sum, normal_sum, count), so parts add up exactly in radcache merge"},
    };
    for (const MethodEntry& method : method_registry()) {
        std::string layers;
        for (const std::string& aov : method.aovs) {
            layers += (layers.empty() ? "" : ", ") + aov;
        }
        specs[1].help +=
            "\n      " + method.name + ": " + method.summary + " (layers " + layers + ")";
    }
    for (OptionSpec& spec : method_option_specs()) {
        specs.push_back(std::move(spec));
    }
    for (OptionSpec& spec : device_option_specs()) {
        specs.push_back(std::move(spec));
    }
    for (OptionSpec& spec : denoise_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

namespace {

// A frame number of --frames, in [-kMaxFrameNumber, kMaxFrameNumber].
int frame_number(const std::string& text, const std::string& frames) {
    errno = 0;
    const long long number = std::strtoll(text.c_str(), nullptr, 10);
    if (errno != 0 || number < -kMaxFrameNumber || number > kMaxFrameNumber) {
        throw Error("--frames " + excerpt(frames) + ": frame " + excerpt(text) + " outside [" +
                        std::to_string(-kMaxFrameNumber) + ", " + std::to_string(kMaxFrameNumber) +
                        "]",
                    kExitUsage);
    }
    return static_cast<int>(number);
}

}  // namespace

FrameRange parse_frames(const std::string& text) {
    static const std::regex form(R"(^(-?\d+):(-?\d+)$)");
    std::smatch match;
    if (text.size() > 64 || !std::regex_match(text, match, form)) {
        throw Error("--frames: expected A:B, got '" + excerpt(text) + "'", kExitUsage);
    }
    FrameRange range;
    range.first = frame_number(match[1].str(), text);
    range.last = frame_number(match[2].str(), text);
    range.given = true;
    if (range.last < range.first) {
        throw Error("--frames: " + text + " ends before it starts", kExitUsage);
    }
    return range;
}

namespace {

std::vector<std::string> parse_layers(const std::string& text) {
    std::vector<std::string> layers;
    std::stringstream list(text);
    for (std::string layer; std::getline(list, layer, ',');) {
        if (!layer.empty()) {
            layers.push_back(layer);
        }
    }
    if (layers.empty()) {
        throw Error("--aovs: expected a comma-separated list of layers", kExitUsage);
    }
    return layers;
}

}  // namespace

namespace {

// --crop, --sample-range and --write-sums, and what they cannot go with.
void read_part_options(const ParsedArguments& arguments, RenderJob* job) {
    if (arguments.has("--crop")) {
        job->crop = parse_crop(arguments.value("--crop"));
    }
    if (arguments.has("--sample-range")) {
        const std::string range = arguments.value("--sample-range");
        job->samples = parse_sample_range(range);
        for (const char* other : {"--spp", "--time"}) {
            if (arguments.has(other)) {
                throw Error("--sample-range " + range + " renders S1 - S0 samples: drop " + other,
                            kExitUsage);
            }
        }
    }
    job->write_sums = arguments.has("--write-sums");
    std::string extension = std::filesystem::path(job->output_pattern).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (job->write_sums && extension != ".exr") {
        throw Error("--write-sums needs an .exr output (-o " + job->output_pattern + ")",
                    kExitUsage);
    }
    if (job->write_sums && arguments.has("--half")) {
        throw Error("--write-sums writes float32 sums (half floats would not add up): drop --half",
                    kExitUsage);
    }
}

// --denoise and what it cannot go with: a farm part is denoised after the merge.
void read_denoise_options(const ParsedArguments& arguments, RenderJob* job) {
    job->denoise = read_denoise_request(arguments);
    for (const char* part : {"--crop", "--sample-range", "--write-sums"}) {
        if (job->denoise.given && arguments.has(part)) {
            throw Error(std::string("--denoise with ") + part +
                            ": a part is denoised after the merge (radcache merge ... --denoise)",
                        kExitUsage);
        }
    }
}

// The frame number of the option `name`, which needs --frames: Error (exit status 2) naming
// the option unless it is a whole number; `fallback` without the option.
int frame_option(const ParsedArguments& arguments, const std::string& name,
                 const FrameRange& frames, int fallback) {
    if (!arguments.has(name)) {
        return fallback;
    }
    const std::string text = arguments.value(name);
    if (!frames.given) {
        throw Error(name + " " + text + " needs --frames", kExitUsage);
    }
    static const std::regex whole(R"(^-?\d{1,9}$)");
    if (!std::regex_match(text, whole)) {
        throw Error(name + ": expected a frame number, got '" + excerpt(text) + "'", kExitUsage);
    }
    return std::stoi(text);
}

std::string frames_text(const FrameRange& frames) {
    return std::to_string(frames.first) + ":" + std::to_string(frames.last);
}

// --write-from F: the first frame written (without the option, --frames' first), within --frames.
int read_write_from(const ParsedArguments& arguments, const FrameRange& frames) {
    const int first = frame_option(arguments, "--write-from", frames, frames.first);
    if (first < frames.first || first > frames.last) {
        throw Error("--write-from " + std::to_string(first) + ": not within --frames " +
                        frames_text(frames),
                    kExitUsage);
    }
    return first;
}

// --clip-end F: the clip's last frame (without the option, --frames' last), at or after
// --frames' last.
int read_clip_end(const ParsedArguments& arguments, const FrameRange& frames) {
    const int end = frame_option(arguments, "--clip-end", frames, frames.last);
    if (end < frames.last) {
        throw Error("--clip-end " + std::to_string(end) + ": before the last of --frames " +
                        frames_text(frames),
                    kExitUsage);
    }
    return end;
}

}  // namespace

void check_part_options(const RenderJob& job, const MethodEntry& entry, int width, int height,
                        double time) {
    if (job.samples.end > 0 && time > 0.0) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", time);
        throw Error("--sample-range " + range_text(job.samples) +
                        " renders S1 - S0 samples, but the render is by time (" + seconds +
                        " s, from -D time= or the scene's render.time): add -D time=0",
                    kExitUsage);
    }
    if (entry.name != "pt") {
        for (const auto& [given, name] :
             {std::pair{job.samples.end > 0, "--sample-range"}, {job.write_sums, "--write-sums"}}) {
            if (given) {
                throw Error(std::string(name) + " applies to --method pt only", kExitUsage);
            }
        }
    }
    const PixelWindow& c = job.crop;
    if (!c.empty() && (c.x1 > width || c.y1 > height)) {
        throw Error("--crop " + window_text(c) + " reaches outside the image (" +
                        std::to_string(width) + "x" + std::to_string(height) + ")",
                    kExitUsage);
    }
}

RenderJob read_render_job(const ParsedArguments& arguments) {
    if (arguments.positionals().size() != 1) {
        throw Error("radcache render needs exactly one scene file (see radcache render --help)",
                    kExitUsage);
    }
    RenderJob job;
    job.scene = arguments.positionals()[0];
    job.output_pattern = arguments.value("--output", "out.png");
    if (arguments.has("--frames")) {
        job.frames = parse_frames(arguments.value("--frames"));
    }
    if (job.frames.given && job.frames.first != job.frames.last &&
        job.output_pattern.find('#') == std::string::npos) {
        throw Error(
            "--output " + job.output_pattern + ": several frames need a #### pattern in the name",
            kExitUsage);
    }
    job.write_from = read_write_from(arguments, job.frames);
    job.clip_end = read_clip_end(arguments, job.frames);
    check_output_path(frame_path(job.output_pattern, job.frames.first));
    read_part_options(arguments, &job);
    read_denoise_options(arguments, &job);
    if (job.frames.given) {
        check_output_path(frame_path(job.output_pattern, job.frames.last));
    }
    job.stats = arguments.value("--stats");
    if (!job.stats.empty()) {
        check_writable_parent(job.stats, "--stats");
    }
    RenderSettings overrides_only;
    for (const std::string& assignment : arguments.values("-D")) {
        overrides_only.apply_override(assignment);  // validates the keys before loading
    }
    // Every value the command line gives that does not depend on the scene is range-checked
    // before it loads, so that a bad one is the only line printed.
    const RenderSettings settings = render_settings(arguments, overrides_only);
    const MethodSettings method = method_settings(arguments, settings, job, 0, 0);
    context_options(arguments);
    if (arguments.has("--method")) {
        // Its options read once here; checked against the command line's settings now, and
        // against the scene's when the method is made.
        const MethodEntry& entry = find_method(settings.method);
        read_method_options(entry, arguments, &job);
        entry.check(job.method_options, method);
    }
    pixel_filter(arguments, PixelFilter{});
    pixel_sampler(arguments, RC_SAMPLER_SOBOL);
    environment_override(arguments);
    job.write_options.half = arguments.has("--half");
    if (arguments.has("--aovs")) {
        job.layers = parse_layers(arguments.value("--aovs"));
    }
    return job;
}

void read_method_options(const MethodEntry& entry, const ParsedArguments& arguments,
                         RenderJob* job) {
    if (job->method == entry.name) {
        return;
    }
    refuse_foreign_options(entry, arguments);
    job->method_options = entry.read(arguments);
    job->method = entry.name;
}

void check_run_files(const RenderJob& job, const MethodEntry& method,
                     const ParsedArguments& arguments, const RecordedFiles& scene_files, int first,
                     int last) {
    RunFiles run;
    run.input("scene file", job.scene);
    scene_files.add_inputs_to(run);
    run.output_frames("-o", job.output_pattern, first, last);
    if (!job.stats.empty()) {
        run.output("--stats", job.stats);
    }
    // The intermediate images beside each frame's: name.sppN.ext for every power of two N up
    // to the most samples a render takes (2^24, as by --time).
    if (arguments.has("--save-every-pow2")) {
        for (int spp = 1; spp <= (1 << 24); spp *= 2) {
            run.output_frames("--save-every-pow2",
                              intermediate_path(job.output_pattern, spp).string(), first, last);
        }
    }
    // The method's file options: --cache-out, --grid-out, ... write; --cache-in, ... read.
    for (const OptionInfo& option : method.table) {
        const std::string& name = option.spec.name;
        if (option.type != "path" || !arguments.has(name)) {
            continue;
        }
        const bool writes = name.size() > 4 && name.compare(name.size() - 4, 4, "-out") == 0;
        if (writes) {
            run.output(name, arguments.value(name));
        } else {
            run.input(name + " file", arguments.value(name));
        }
    }
    run.check();
}

RenderSettings render_settings(const ParsedArguments& arguments, RenderSettings settings) {
    for (const std::string& assignment : arguments.values("-D")) {
        settings.apply_override(assignment);
    }
    settings.method = arguments.value("--method", settings.method);
    settings.spp = static_cast<int>(arguments.integer("--spp", settings.spp));
    settings.time = arguments.number("--time", settings.time);
    settings.seed =
        static_cast<uint64_t>(arguments.integer("--seed", static_cast<long long>(settings.seed)));
    settings.exposure = static_cast<float>(arguments.number("--exposure", settings.exposure));
    return settings;
}

PixelFilter pixel_filter(const ParsedArguments& arguments, PixelFilter filter) {
    if (arguments.has("--filter")) {
        const std::string name = arguments.value("--filter");
        filter.type = pixel_filter_type(name);
        if (filter.type < 0) {
            throw Error("--filter: expected box, tent or gaussian, got '" + excerpt(name) + "'",
                        kExitUsage);
        }
        filter.radius = default_filter_radius(filter.type);
    }
    filter.radius = static_cast<float>(arguments.number("--filter-radius", filter.radius));
    return filter;
}

std::optional<EnvironmentOverride> environment_override(const ParsedArguments& arguments) {
    if (!arguments.has("--environment")) {
        return std::nullopt;
    }
    const std::string text = arguments.value("--environment");
    std::vector<float> values;
    size_t start = 0;
    bool colour = !text.empty();
    while (colour && start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string word = text.substr(start, comma - start);
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        colour = !word.empty() && end == word.c_str() + word.size() && value >= 0.0 && value <= 1e9;
        values.push_back(static_cast<float>(value));
        start = comma + 1;
    }
    EnvironmentOverride environment;
    if (colour && (values.size() == 1 || values.size() == 3)) {
        environment.radiance =
            values.size() == 1 ? glm::vec3(values[0]) : glm::vec3(values[0], values[1], values[2]);
        return environment;
    }
    if (text.find(',') != std::string::npos || !std::filesystem::is_regular_file(text)) {
        throw Error(
            "--environment: expected a colour R,G,B or one value, each in [0, 1e9], or "
            "a lat-long image file, got '" +
                excerpt(text) + "'",
            kExitUsage);
    }
    environment.map = text;
    return environment;
}

int pixel_sampler(const ParsedArguments& arguments, int scene_sampler) {
    if (!arguments.has("--sampler")) {
        return scene_sampler;
    }
    const std::string name = arguments.value("--sampler");
    const int type = pixel_sampler_type(name);
    if (type < 0) {
        throw Error("--sampler: expected sobol or independent, got '" + excerpt(name) + "'",
                    kExitUsage);
    }
    return type;
}

MethodSettings method_settings(const ParsedArguments& arguments, const RenderSettings& settings,
                               const RenderJob& job, int first, int last) {
    MethodSettings method;
    method.width = static_cast<int>(arguments.integer("--width", 0));
    method.height = static_cast<int>(arguments.integer("--height", 0));
    method.spp = settings.spp;
    method.time = settings.time;
    method.seed = settings.seed;
    method.max_depth = settings.max_depth;
    method.rr_depth = settings.rr_depth;
    // The clip the frames belong to: on to --clip-end (a farm task's frames are part of one).
    const int end = job.frames.given ? std::max(last, job.clip_end) : last;
    const long long frames = static_cast<long long>(end) - first + 1;
    method.frame_count = static_cast<int>(std::min<long long>(frames, 1 << 30));
    method.first_frame = first;
    method.layers = job.layers;
    method.crop = job.crop;
    if (job.samples.end > 0) {
        method.first_sample = job.samples.first;
        method.spp = job.samples.end - job.samples.first;
    }
    method.write_sums = job.write_sums;
    return method;
}

std::filesystem::path intermediate_path(const std::filesystem::path& output, int spp) {
    std::filesystem::path path = output;
    path.replace_filename(output.stem().string() + ".spp" + std::to_string(spp) +
                          output.extension().string());
    return path;
}

}  // namespace rc
