#include "app/compare_frames.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/compare_images.h"
#include "app/render_job.h"
#include "image/image_io.h"
#include "image/temporal_error.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/output_identity.h"

namespace rc {

namespace {

// What the command was asked: the range, the names (#### the frame number) and the layer.
struct SequenceJob {
    FrameRange frames;
    std::string test_pattern;
    std::string reference_pattern;
    std::string mask_pattern;  // empty: no mask; without #: one mask for every frame
    std::string layer;
    std::filesystem::path json_path;
};

// One frame as the comparison holds it: the test's layer, the reference's (with its noise where
// known) and the frame's mask.
struct LoadedFrame {
    std::string test_path;
    std::string reference_path;
    Image test;
    ReferenceLayer reference;
    ReferenceNoiseSource source;
    int reference_factor = 1;  // the reference box-filtered factor x factor to the test's size
    Image mask;                // 0 x 0: none
    NonfinitePixels nonfinite;
};

// The figures of one frame: its error, and the temporal error of the pair it closes.
struct FrameRow {
    int frame = 0;
    std::string test_path;
    std::string reference_path;
    ImageError error;
    ReferenceNoiseSource source;
    int reference_factor = 1;
    NonfinitePixels nonfinite;
    std::optional<TemporalError> temporal;  // absent for the first frame
};

std::string path_of(const std::string& pattern, long long frame) {
    return frame_path(pattern, frame).string();
}

// Step 1: the command line, checked before any file is read.
SequenceJob read_sequence_job(const ParsedArguments& arguments) {
    SequenceJob job;
    job.frames = parse_frames(arguments.value("--frames"));
    if (job.frames.last == job.frames.first) {
        throw Error("--frames " + arguments.value("--frames") +
                        ": a sequence needs at least two frames (compare TEST REF for one)",
                    kExitUsage);
    }
    job.test_pattern = arguments.positionals()[0];
    job.reference_pattern = arguments.positionals()[1];
    for (const std::string& pattern : {job.test_pattern, job.reference_pattern}) {
        if (pattern.find('#') == std::string::npos) {
            throw Error("--frames: " + pattern + " has no #### for the frame number", kExitUsage);
        }
    }
    if (arguments.has("--error-image")) {
        throw Error("--error-image compares one image; not with --frames", kExitUsage);
    }
    job.mask_pattern = arguments.value("--mask");
    job.layer = arguments.value("--aov", "beauty");
    job.json_path = arguments.value("--json");
    if (!job.json_path.empty()) {
        check_writable_parent(job.json_path, "--json");
    }
    return job;
}

// Step 2: every frame's files exist, so that a missing one is named before any work, and --json
// is none of them.
void check_frames_exist(const SequenceJob& job) {
    RunFiles run;
    for (long long frame = job.frames.first; frame <= job.frames.last; ++frame) {
        std::vector<std::pair<std::string, std::string>> paths = {
            {"TEST image", path_of(job.test_pattern, frame)},
            {"REF image", path_of(job.reference_pattern, frame)}};
        if (!job.mask_pattern.empty()) {
            paths.emplace_back("--mask file", path_of(job.mask_pattern, frame));
        }
        for (const auto& [what, path] : paths) {
            if (!std::filesystem::is_regular_file(path)) {
                throw Error("frame " + std::to_string(frame) + ": no file " + path);
            }
            run.input(what, path);
        }
    }
    if (!job.json_path.empty()) {
        run.output("--json", job.json_path);
    }
    run.check();
}

LoadedFrame load_frame(const SequenceJob& job, const ParsedArguments& arguments, int frame,
                       const Image& shared_mask) {
    LoadedFrame loaded;
    loaded.test_path = path_of(job.test_pattern, frame);
    loaded.reference_path = path_of(job.reference_pattern, frame);
    loaded.test = select_layers(read_image(loaded.test_path), {job.layer});
    loaded.source = find_reference_spp(arguments, loaded.reference_path);
    loaded.reference = matched_to(reference_layer(read_image(loaded.reference_path), job.layer,
                                                  loaded.reference_path, loaded.source),
                                  loaded.test, &loaded.reference_factor);
    if (job.mask_pattern.find('#') != std::string::npos) {
        loaded.mask = read_mask(path_of(job.mask_pattern, frame), arguments);
    } else {
        loaded.mask = shared_mask;
    }
    return loaded;
}

// A frame's NaN or infinite pixels are an error without --allow-nan. With it, every
// frame's mask becomes its pixels that are finite in both images (and selected by --mask), so
// that each frame's figures and each pair's temporal error are taken over finite pixels only.
void exclude_nonfinite_frame_pixels(LoadedFrame& frame, bool allow_nan) {
    PixelMask mask{frame.mask.width > 0 ? &frame.mask : nullptr};
    Image finite;
    frame.nonfinite =
        exclude_nonfinite_pixels(frame.test, frame.reference.values, frame.test_path, mask, finite);
    if (frame.nonfinite.any() && !allow_nan) {
        refuse_nonfinite_pixels(frame.nonfinite, frame.test_path, frame.reference_path);
    }
    if (allow_nan) {
        frame.mask = finite_pixel_mask(frame.test, frame.reference.values, mask);
    }
}

// The pixels both frames' masks select (1) or not (0); the masks are the size of the frames.
Image both_masks(const Image& a, const Image& b, const std::string& name) {
    check_comparable(a, b, name + " (the mask of the previous frame)");
    Image both(a.width, a.height, 1);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            both.at(x, y, 0) = a.at(x, y, 0) > 0.0f && b.at(x, y, 0) > 0.0f ? 1.0f : 0.0f;
        }
    }
    return both;
}

// The temporal error of the pair (previous, current), net of the references' noise where both
// frames' noise is known.
TemporalError pair_error(const LoadedFrame& previous, const LoadedFrame& current) {
    const bool masked = current.mask.width > 0;
    const Image mask =
        masked ? both_masks(previous.mask, current.mask, current.test_path) : Image();
    const PixelMask pixels{masked ? &mask : nullptr};
    if (previous.reference.noise_known() && current.reference.noise_known()) {
        return temporal_error_net(
            previous.test, current.test, previous.reference.values, current.reference.values,
            {&previous.reference.stddev, previous.reference.spp},
            {&current.reference.stddev, current.reference.spp}, current.test_path, pixels);
    }
    return temporal_error(previous.test, current.test, previous.reference.values,
                          current.reference.values, current.test_path, pixels);
}

// Step 3: every frame's figures, two frames in memory at a time.
std::vector<FrameRow> compare_sequence(const SequenceJob& job, const ParsedArguments& arguments) {
    const Image shared_mask =
        !job.mask_pattern.empty() && job.mask_pattern.find('#') == std::string::npos
            ? read_mask(job.mask_pattern, arguments)
            : Image();
    std::vector<FrameRow> rows;
    std::optional<LoadedFrame> previous;
    // long long: a range ending at the largest int stops.
    for (long long frame = job.frames.first; frame <= job.frames.last; ++frame) {
        LoadedFrame current = load_frame(job, arguments, static_cast<int>(frame), shared_mask);
        exclude_nonfinite_frame_pixels(current, arguments.has("--allow-nan"));
        FrameRow row;
        row.frame = static_cast<int>(frame);
        row.test_path = current.test_path;
        row.reference_path = current.reference_path;
        row.source = current.source;
        row.reference_factor = current.reference_factor;
        row.nonfinite = current.nonfinite;
        const PixelMask mask{current.mask.width > 0 ? &current.mask : nullptr};
        row.error = compare_layer(current.test, current.reference, current.test_path, mask);
        if (previous) {
            row.temporal = pair_error(*previous, current);
        }
        rows.push_back(std::move(row));
        previous = std::move(current);
    }
    return rows;
}

// The mean of a figure over the rows (after the first with `skip_first`); absent when a row
// lacks it (the net figures of a frame whose reference noise is unknown).
template <typename Figure>
std::optional<double> mean_of(const std::vector<FrameRow>& rows, bool skip_first, Figure figure) {
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = skip_first ? 1 : 0; i < rows.size(); ++i) {
        const std::optional<double> value = figure(rows[i]);
        if (!value) {
            return std::nullopt;
        }
        sum += *value;
        ++count;
    }
    return count > 0 ? std::optional<double>(sum / static_cast<double>(count)) : std::nullopt;
}

struct SequenceMeans {
    std::optional<double> relmse, relmse_net, reference_noise;
    std::optional<double> temporal_error, temporal_error_net, temporal_reference_noise;
};

SequenceMeans sequence_means(const std::vector<FrameRow>& rows) {
    SequenceMeans m;
    m.relmse =
        mean_of(rows, false, [](const FrameRow& r) { return std::optional(r.error.relmse); });
    m.relmse_net = mean_of(rows, false, [](const FrameRow& r) { return r.error.relmse_net; });
    m.reference_noise =
        mean_of(rows, false, [](const FrameRow& r) { return r.error.reference_noise; });
    m.temporal_error = mean_of(
        rows, true, [](const FrameRow& r) { return std::optional(r.temporal->temporal_error); });
    m.temporal_error_net =
        mean_of(rows, true, [](const FrameRow& r) { return r.temporal->temporal_error_net; });
    m.temporal_reference_noise =
        mean_of(rows, true, [](const FrameRow& r) { return r.temporal->reference_noise; });
    return m;
}

std::string figure_text(const std::optional<double>& value) {
    if (!value) {
        return "-";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", *value);
    return text;
}

void print_sequence(const SequenceJob& job, const std::vector<FrameRow>& rows,
                    const SequenceMeans& means) {
    char line[256];
    std::snprintf(line, sizeof line, "%6s  %-11s %-11s %-11s %s\n", "frame", "relmse", "relmse_net",
                  "temporal", "temporal_net");
    std::cout << line;
    for (const FrameRow& row : rows) {
        std::snprintf(
            line, sizeof line, "%6d  %-11s %-11s %-11s %s\n", row.frame,
            figure_text(row.error.relmse).c_str(), figure_text(row.error.relmse_net).c_str(),
            figure_text(row.temporal ? std::optional(row.temporal->temporal_error) : std::nullopt)
                .c_str(),
            figure_text(row.temporal ? row.temporal->temporal_error_net : std::nullopt).c_str());
        std::cout << line;
    }
    std::snprintf(line, sizeof line, "%6s  %-11s %-11s %-11s %s\n", "mean",
                  figure_text(means.relmse).c_str(), figure_text(means.relmse_net).c_str(),
                  figure_text(means.temporal_error).c_str(),
                  figure_text(means.temporal_error_net).c_str());
    std::cout << line;
    std::cout << "layer " << job.layer << ", frames " << job.frames.first << ".." << job.frames.last
              << " (temporal: the " << rows.size() - 1 << " pairs of consecutive frames)";
    if (job.mask_pattern.empty()) {
        std::cout << "\n";
    } else {
        std::cout << ", over the pixels of " << job.mask_pattern << "\n";
    }
    if (rows.front().reference_factor > 1) {
        std::cout << "references box-filtered " << rows.front().reference_factor << " x "
                  << rows.front().reference_factor << " to the test's resolution\n";
    }
    if (means.reference_noise && means.temporal_reference_noise) {
        std::cout << "references' noise subtracted (means): " << figure_text(means.reference_noise)
                  << " of relmse, " << figure_text(means.temporal_reference_noise)
                  << " of the temporal error (spp " << figure_text(rows.front().source.spp)
                  << " from " << rows.front().source.from << ")\n";
    } else {
        for (const FrameRow& row : rows) {
            if (!row.error.relmse_net) {
                std::cout << "net figures: not reported for frame " << row.frame << ", "
                          << row.source.note << "\n";
                break;
            }
        }
    }
}

nlohmann::json optional_json(const std::optional<double>& value) {
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json sequence_json(const SequenceJob& job, const std::vector<FrameRow>& rows,
                             const SequenceMeans& means) {
    nlohmann::json j;
    j["test"] = job.test_pattern;
    j["reference"] = job.reference_pattern;
    j["first_frame"] = job.frames.first;
    j["last_frame"] = job.frames.last;
    j["aov"] = job.layer;
    if (!job.mask_pattern.empty()) {
        j["mask"] = job.mask_pattern;
    }
    nlohmann::json frames = nlohmann::json::array();
    for (const FrameRow& row : rows) {
        nlohmann::json f = error_json(row.error, row.source);
        f["frame"] = row.frame;
        f["test"] = row.test_path;
        f["reference"] = row.reference_path;
        f["pixels"] = row.error.pixels;
        f["reference_box_filter"] = row.reference_factor;
        f["nonfinite_pixels"] = {{"test", row.nonfinite.test},
                                 {"reference", row.nonfinite.reference}};
        // The pair (frame - 1, frame); null for the first frame.
        const std::optional<TemporalError>& t = row.temporal;
        f["temporal_error"] = t ? nlohmann::json(t->temporal_error) : nlohmann::json(nullptr);
        f["temporal_error_net"] = optional_json(t ? t->temporal_error_net : std::nullopt);
        f["temporal_reference_noise"] = optional_json(t ? t->reference_noise : std::nullopt);
        f["temporal_pixels"] = t ? nlohmann::json(t->pixels) : nlohmann::json(nullptr);
        frames.push_back(std::move(f));
    }
    j["frames"] = std::move(frames);
    j["mean"] = {{"relmse", optional_json(means.relmse)},
                 {"relmse_net", optional_json(means.relmse_net)},
                 {"reference_noise", optional_json(means.reference_noise)},
                 {"temporal_error", optional_json(means.temporal_error)},
                 {"temporal_error_net", optional_json(means.temporal_error_net)},
                 {"temporal_reference_noise", optional_json(means.temporal_reference_noise)}};
    return j;
}

}  // namespace

int compare_frames(const ParsedArguments& arguments) {
    const SequenceJob job = read_sequence_job(arguments);
    check_frames_exist(job);
    const std::vector<FrameRow> rows = compare_sequence(job, arguments);
    const SequenceMeans means = sequence_means(rows);
    print_sequence(job, rows, means);
    if (!job.json_path.empty()) {
        write_file_atomically(job.json_path, sequence_json(job, rows, means).dump(2) + "\n");
    }
    return 0;
}

}  // namespace rc
