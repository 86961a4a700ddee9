// What `radcache render` was asked to do, read from its command line before any work: the
// options every method shares, the output names of frames, the layers, the stats file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/denoise_options.h"
#include "app/recorded_files.h"
#include "app/render_parts.h"
#include "image/image_io.h"
#include "methods/method.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene_loader.h"
#include "util/cli.h"
#include "util/output_identity.h"  // frame_path

namespace rc {

// The render command's options: those every method shares, every method's (methods/registry),
// and the device options.
std::vector<OptionSpec> render_option_specs();

struct FrameRange {
    int first = 0;
    int last = 0;
    bool given = false;  // --frames A:B; otherwise the scene's first frame alone
};

// --frames A:B: Error (exit status 2) naming --frames for another form or when B < A.
FrameRange parse_frames(const std::string& text);

struct RenderJob {
    std::filesystem::path scene;
    std::string output_pattern;  // #### becomes the frame number
    FrameRange frames;
    int write_from = 0;           // frames before it are rendered, not written (--write-from)
    int clip_end = 0;             // the clip's last frame (--clip-end; default: --frames' last)
    std::filesystem::path stats;  // empty: no stats file
    std::vector<std::string> layers;
    ImageWriteOptions write_options;
    // A part of a larger render (docs/farm.md): --crop (empty: the whole image), --sample-range
    // (given: samples.end > 0), --write-sums.
    PixelWindow crop;
    SampleRange samples;
    bool write_sums = false;
    DenoiseRequest denoise;  // --denoise: each frame's beauty denoised before it is written
    // The method's options, read once: by read_render_job when --method names the method,
    // otherwise once the scene's render defaults name it (read_method_options).
    std::string method;
    MethodOptions method_options;
};

// Error (exit status 2) naming the option when --sample-range or --write-sums is given to a
// method other than pt (the only method whose image is a mean of independent samples per pixel),
// --sample-range is given to a render by time however the time is given (`time`: --time, -D
// time= or the scene's render.time), or --crop reaches outside a width x height image.
void check_part_options(const RenderJob& job, const MethodEntry& entry, int width, int height,
                        double time);

// Reads the options of the method `entry` into job->method_options unless they are read already;
// Error (exit status 2) naming an option another method declares or a combination that cannot
// work.
void read_method_options(const MethodEntry& entry, const ParsedArguments& arguments,
                         RenderJob* job);

// Checks everything that can be checked before loading the scene (output and stats paths,
// --frames, --aovs, -D keys, the ranges of the numeric options, --method and the options it
// takes); Error (exit status 2) naming the option otherwise.
RenderJob read_render_job(const ParsedArguments& arguments);

// Error (exit status 2) unless every output of the run (the frames first..last of -o, --stats,
// the method's --*-out files) is a file of its own: not the scene or a file its loader read
// (`scene_files`), not the method's --*-in files, not another output (util/output_identity.h).
// Checked after the scene is loaded and before any work.
void check_run_files(const RenderJob& job, const MethodEntry& method,
                     const ParsedArguments& arguments, const RecordedFiles& scene_files, int first,
                     int last);

// The scene's render defaults overridden by -D and then by --method, --spp, --seed, --exposure.
RenderSettings render_settings(const ParsedArguments& arguments, RenderSettings scene_defaults);

// The scene camera's pixel filter overridden by --filter (with its default radius) and then
// --filter-radius; Error (exit status 2) naming the option for an unknown name or a radius
// outside [kMinFilterRadius, kMaxFilterRadius].
PixelFilter pixel_filter(const ParsedArguments& arguments, PixelFilter scene_filter);

// The scene camera's pixel sampler (RC_SAMPLER_*) overridden by --sampler; Error (exit status 2)
// naming the option for an unknown name.
int pixel_sampler(const ParsedArguments& arguments, int scene_sampler);

// --environment: a radiance (R,G,B or one value) or an existing lat-long image file, or none
// without it; Error (exit status 2) naming the option for anything else.
std::optional<EnvironmentOverride> environment_override(const ParsedArguments& arguments);

// What every method reads, for frames first..last.
MethodSettings method_settings(const ParsedArguments& arguments, const RenderSettings& settings,
                               const RenderJob& job, int first, int last);

// name.ext -> name.sppN.ext
std::filesystem::path intermediate_path(const std::filesystem::path& output, int spp);

}  // namespace rc
