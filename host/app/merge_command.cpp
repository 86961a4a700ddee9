// `radcache merge OUT PART...`: the parts of one render (app/merge_parts.h) as one image.
#include "app/commands.h"
#include "app/denoise_options.h"
#include "app/merge_parts.h"
#include "app/render_job.h"
#include "image/image_io.h"
#include "util/error.h"
#include "util/log.h"
#include "util/output_identity.h"

namespace rc {
namespace {

// The frames of --frames A:B, or the one frame (first == last, `given` false).
FrameRange merge_frames(const ParsedArguments& arguments) {
    return arguments.has("--frames") ? parse_frames(arguments.value("--frames")) : FrameRange{};
}

int merge(const ParsedArguments& arguments) {
    const std::vector<std::string>& words = arguments.positionals();
    if (words.size() < 2) {
        throw Error(
            "radcache merge needs an output and at least one part (see radcache merge "
            "--help)",
            kExitUsage);
    }
    const FrameRange frames = merge_frames(arguments);
    if (frames.given) {
        for (const std::string& word : words) {
            if (word.find('#') == std::string::npos) {
                throw Error("merge --frames: " + word + " needs a #### pattern in the name",
                            kExitUsage);
            }
        }
    }
    const auto name = [&](const std::string& word, int frame) {
        return frames.given ? frame_path(word, frame) : std::filesystem::path(word);
    };
    // Work in proportion to the parts that exist, not to the range: each frame's parts must be
    // there before the next frame is looked at, and an output folder is probed once.
    RunFiles run;
    std::filesystem::path probed;
    for (int frame = frames.first; frame <= frames.last; ++frame) {
        for (size_t i = 1; i < words.size(); ++i) {
            const std::filesystem::path part = name(words[i], frame);
            if (!std::filesystem::is_regular_file(part)) {
                throw Error(part.string() + ": no such part" +
                            (frames.given ? " (frame " + std::to_string(frame) + ")" : ""));
            }
            run.input("part", part);
        }
        const std::filesystem::path out = name(words[0], frame);
        if (frame == frames.first || out.parent_path() != probed) {
            check_output_path(out);
            probed = out.parent_path();
        }
    }
    run.output_frames("OUT", words[0], frames.first, frames.last);
    run.check();
    set_quiet(arguments.has("--quiet"));
    const std::unique_ptr<Denoiser> denoiser = open_denoiser(read_denoise_request(arguments));
    // Every frame merged before any is written: a refused part leaves no output.
    std::vector<Image> merged;
    for (int frame = frames.first; frame <= frames.last; ++frame) {
        std::vector<std::filesystem::path> parts;
        for (size_t i = 1; i < words.size(); ++i) {
            parts.push_back(name(words[i], frame));
        }
        merged.push_back(merge_parts(parts));
        if (denoiser) {
            merged.back() = denoiser->denoise(merged.back());
        }
    }
    ImageWriteOptions options;
    options.half = arguments.has("--half");
    for (int frame = frames.first; frame <= frames.last; ++frame) {
        const Image& image = merged[static_cast<size_t>(frame - frames.first)];
        write_image(name(words[0], frame), image, options);
        log_note("merged " + std::to_string(words.size() - 1) + " parts into " +
                 name(words[0], frame).string() + " (" + std::to_string(image.width) + "x" +
                 std::to_string(image.height) + ", samples " +
                 image.metadata.at("radcache:samples") + ")");
    }
    return 0;
}

std::vector<OptionSpec> merge_option_specs() {
    std::vector<OptionSpec> specs = {
        {"--frames", "", "A:B",
         "merge frames A to B: #### in OUT and each PART becomes the frame number"},
        {"--half", "", "", ".exr: store half floats"},
        {"--quiet", "-q", "", "print nothing but errors"}};
    for (OptionSpec& spec : denoise_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

}  // namespace

CommandSpec merge_command() {
    return {.name = "merge",
            .synopsis = "merge OUT PART...",
            .summary = "assemble the parts of a render split by --crop and --sample-range",
            .usage = "radcache merge OUT PART... [options]",
            .description =
                "Writes OUT from the parts of one render (.exr files of radcache render with "
                "--crop, --sample-range and --write-sums): windows side by side, and the sums of "
                "a window's sample ranges added and resolved as one render of all the samples "
                "would resolve them. Parts of another scene, method, options, image size or "
                "frame, overlapping windows or sample ranges, and gaps are refused naming the "
                "part; nothing is written then (docs/farm.md).",
            .options = merge_option_specs(),
            .run = merge};
}

}  // namespace rc
