#include "app/merge_parts.h"

#include <algorithm>
#include <map>

#include "app/render_parts.h"
#include "image/image_io.h"
#include "image/sample_sums.h"
#include "util/error.h"

namespace rc {
namespace {

struct Part {
    std::string name;
    Image image;
    PixelWindow crop;
    SampleRange samples;
};

// The attribute `key` of `part`'s image; Error naming the part when it has none.
std::string attribute(const Part& part, const std::string& key) {
    const auto found = part.image.metadata.find(key);
    if (found == part.image.metadata.end()) {
        throw Error(part.name + ": not a part of a radcache render (no " + key +
                    " attribute: render parts as .exr)");
    }
    return found->second;
}

Part read_part(const std::filesystem::path& path) {
    Part part{path.string(), read_image(path), {}, {}};
    try {
        part.crop = parse_crop(attribute(part, "radcache:crop"));
        part.samples = parse_sample_range(attribute(part, "radcache:samples"));
    } catch (const Error& error) {
        throw Error(part.name + ": unreadable part attributes (" + error.what() + ")");
    }
    // The attributes the merge places the part by, against the EXR's own windows: its data
    // window (origin and size) and its display window (the whole image's size).
    const Image& image = part.image;
    const bool whole = image.full_width == 0;
    const PixelWindow data{image.origin_x, image.origin_x + image.width, image.origin_y,
                           image.origin_y + image.height};
    if (part.crop.x0 != data.x0 || part.crop.x1 != data.x1 || part.crop.y0 != data.y0 ||
        part.crop.y1 != data.y1) {
        throw Error(part.name + ": its radcache:crop " + window_text(part.crop) +
                    " is not its data window " + window_text(data));
    }
    const std::string size = std::to_string(whole ? image.width : image.full_width) + "x" +
                             std::to_string(whole ? image.height : image.full_height);
    if (attribute(part, "radcache:size") != size) {
        throw Error(part.name + ": its radcache:size " + attribute(part, "radcache:size") +
                    " is not its display window's size " + size);
    }
    return part;
}

// Error unless `part` belongs to the render of `first`.
void check_same_render(const Part& part, const Part& first) {
    for (const auto& [key, what] :
         {std::pair{"radcache:scene", "scene (its file or a file it reads)"},
          {"radcache:method", "method"},
          {"radcache:options", "options"},
          {"radcache:size", "image size"},
          {"radcache:frame", "frame"}}) {
        const std::string mine = attribute(part, key);
        const std::string theirs = attribute(first, key);
        if (mine != theirs) {
            throw Error(part.name + ": another " + what + " than " + first.name + " ('" + mine +
                        "' against '" + theirs + "')");
        }
    }
    if (part.image.channel_names != first.image.channel_names) {
        throw Error(part.name + ": other layers than " + first.name);
    }
}

bool overlap(const PixelWindow& a, const PixelWindow& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// The parts of one window, sorted by their first sample: Error unless their ranges follow each
// other without overlap or gap, or where several have no sums. Returns their range.
SampleRange check_ranges(std::vector<const Part*>& parts) {
    std::sort(parts.begin(), parts.end(),
              [](const Part* a, const Part* b) { return a->samples.first < b->samples.first; });
    for (size_t i = 1; i < parts.size(); ++i) {
        const Part& before = *parts[i - 1];
        const Part& part = *parts[i];
        if (part.samples.first < before.samples.end) {
            throw Error(part.name + ": samples " + range_text(part.samples) + " overlap " +
                        before.name + "'s " + range_text(before.samples));
        }
        if (part.samples.first > before.samples.end) {
            throw Error(part.name + ": samples " +
                        range_text({before.samples.end, part.samples.first}) +
                        " are missing between " + before.name + " and it");
        }
    }
    if (parts.size() > 1) {
        for (const Part* part : parts) {
            if (!has_sums(part->image)) {
                throw Error(part->name +
                            ": no sums layers to add its samples (render the parts "
                            "with --write-sums)");
            }
        }
    }
    return {parts.front()->samples.first, parts.back()->samples.end};
}

// The image of one window's parts: the one part's, or their sums added (in double, in sample
// order) and resolved, every channel of the parts taken from the sums or their resolution.
Image add_ranges(const std::vector<const Part*>& parts) {
    if (parts.size() == 1) {
        return parts[0]->image;
    }
    Image total = sums_of(parts[0]->image);
    std::vector<double> sums(total.pixels.size(), 0.0);
    for (const Part* part : parts) {
        const Image own = sums_of(part->image);
        for (size_t i = 0; i < sums.size(); ++i) {
            sums[i] += own.pixels[i];
        }
    }
    std::transform(sums.begin(), sums.end(), total.pixels.begin(),
                   [](double v) { return static_cast<float>(v); });
    const Image resolved = resolve_sums(total);
    const Image& first = parts[0]->image;
    Image image(first.width, first.height, first.channels);
    image.channel_names = first.channel_names;
    const auto index_in = [](const Image& image, const std::string& name) {
        const auto found = std::find(image.channel_names.begin(), image.channel_names.end(), name);
        return found == image.channel_names.end()
                   ? -1
                   : static_cast<int>(found - image.channel_names.begin());
    };
    for (int c = 0; c < first.channels; ++c) {
        const std::string& name = first.channel_names[c];
        const Image* source = &total;
        int from = index_in(total, name);
        if (from < 0) {
            source = &resolved;
            from = index_in(resolved, name);
        }
        if (from < 0) {
            throw Error(parts[0]->name + ": channel " + name + " cannot be added from sums");
        }
        for (size_t p = 0; p < static_cast<size_t>(image.width) * image.height; ++p) {
            image.pixels[p * image.channels + c] = source->pixels[p * source->channels + from];
        }
    }
    return image;
}

}  // namespace

Image merge_parts(const std::vector<std::filesystem::path>& paths) {
    std::vector<Part> parts;
    for (const auto& path : paths) {
        parts.push_back(read_part(path));
        check_same_render(parts.back(), parts.front());
    }
    std::map<std::string, std::vector<const Part*>> windows;  // by window_text
    PixelWindow box = parts[0].crop;
    for (const Part& part : parts) {
        for (const auto& [text, others] : windows) {
            if (text != window_text(part.crop) && overlap(part.crop, others[0]->crop)) {
                throw Error(part.name + ": its window " + window_text(part.crop) + " overlaps " +
                            others[0]->name + "'s " + text);
            }
        }
        windows[window_text(part.crop)].push_back(&part);
        box = {std::min(box.x0, part.crop.x0), std::max(box.x1, part.crop.x1),
               std::min(box.y0, part.crop.y0), std::max(box.y1, part.crop.y1)};
    }
    long long area = 0;
    for (const auto& [text, group] : windows) {
        area += static_cast<long long>(group[0]->crop.width()) * group[0]->crop.height();
    }
    if (area != static_cast<long long>(box.width()) * box.height()) {
        throw Error("the parts' windows leave pixels of " + window_text(box) + " uncovered");
    }
    Image merged(box.width(), box.height(), parts[0].image.channels);
    merged.channel_names = parts[0].image.channel_names;
    const Part* reference = nullptr;
    SampleRange samples;
    for (auto& [text, group] : windows) {
        const SampleRange range = check_ranges(group);
        if (reference != nullptr && (range.first != samples.first || range.end != samples.end)) {
            throw Error(group[0]->name + ": its window has samples " + range_text(range) + ", " +
                        reference->name + "'s " + range_text(samples));
        }
        reference = group[0];
        samples = range;
        const Image image = add_ranges(group);
        const PixelWindow& c = group[0]->crop;
        for (int y = 0; y < c.height(); ++y) {
            std::copy_n(&image.pixels[static_cast<size_t>(y) * c.width() * image.channels],
                        static_cast<size_t>(c.width()) * image.channels,
                        &merged.pixels[(static_cast<size_t>(y + c.y0 - box.y0) * box.width() +
                                        (c.x0 - box.x0)) *
                                       merged.channels]);
        }
    }
    merged.metadata = parts[0].image.metadata;
    merged.metadata["radcache:crop"] = window_text(box);
    merged.metadata["radcache:samples"] = range_text(samples);
    merged.origin_x = box.x0;
    merged.origin_y = box.y0;
    merged.full_width = parts[0].image.full_width;
    merged.full_height = parts[0].image.full_height;
    return merged;
}

}  // namespace rc
