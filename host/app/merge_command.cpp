// `radcache merge OUT PART...`: the parts of one render (app/merge_parts.h) as one image.
#include "app/commands.h"
#include "app/merge_parts.h"
#include "image/image_io.h"
#include "util/error.h"
#include "util/log.h"
#include "util/output_identity.h"

namespace rc {
namespace {

int merge(const ParsedArguments& arguments) {
    const std::vector<std::string>& words = arguments.positionals();
    if (words.size() < 2) {
        throw Error(
            "radcache merge needs an output and at least one part (see radcache merge "
            "--help)",
            kExitUsage);
    }
    const std::filesystem::path output = words[0];
    check_output_path(output);
    RunFiles run;
    std::vector<std::filesystem::path> parts;
    for (size_t i = 1; i < words.size(); ++i) {
        parts.emplace_back(words[i]);
        run.input("part", parts.back());
    }
    run.output("OUT", output);
    run.check();
    set_quiet(arguments.has("--quiet"));
    const Image merged = merge_parts(parts);
    ImageWriteOptions options;
    options.half = arguments.has("--half");
    write_image(output, merged, options);
    log_note("merged " + std::to_string(parts.size()) + " parts into " + output.string() + " (" +
             std::to_string(merged.width) + "x" + std::to_string(merged.height) + ", samples " +
             merged.metadata.at("radcache:samples") + ")");
    return 0;
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
            .options = {{"--half", "", "", ".exr: store half floats"},
                        {"--quiet", "-q", "", "print nothing but errors"}},
            .run = merge};
}

}  // namespace rc
