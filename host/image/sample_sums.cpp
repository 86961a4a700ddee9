#include "image/sample_sums.h"

#include <algorithm>
#include <cmath>

#include "shared/film.h"
#include "util/error.h"

namespace rc {

const char* const kSumsLayers[7] = {"beauty_sum", "beauty_sumsq", "direct_sum", "indirect_sum",
                                    "albedo_sum", "normal_sum",   "count"};

namespace {

// The film slot of each three-channel sums layer, in kSumsLayers' order.
constexpr int kSumsSlots[6] = {RC_PT_FILM_BEAUTY,   RC_PT_FILM_BEAUTY_SQUARED, RC_PT_FILM_DIRECT,
                               RC_PT_FILM_INDIRECT, RC_PT_FILM_ALBEDO,         RC_PT_FILM_NORMAL};
constexpr int kSumsChannels = 6 * 3 + 1;

std::vector<std::string> sums_channel_names() {
    std::vector<std::string> names;
    for (int layer = 0; layer < 6; ++layer) {
        for (const char* c : {"R", "G", "B"}) {
            names.push_back(std::string(kSumsLayers[layer]) + "." + c);
        }
    }
    names.push_back(std::string(kSumsLayers[6]) + ".Y");
    return names;
}

}  // namespace

Image film_sums(const std::vector<shared::float4>& film, int width, int height) {
    Image image(width, height, kSumsChannels);
    image.channel_names = sums_channel_names();
    const size_t pixels = static_cast<size_t>(width) * height;
    for (size_t p = 0; p < pixels; ++p) {
        const shared::float4* s = &film[RC_PT_FILM_SLOTS * p];
        float* out = &image.pixels[p * kSumsChannels];
        for (const int slot : kSumsSlots) {
            *out++ = s[slot].x;
            *out++ = s[slot].y;
            *out++ = s[slot].z;
        }
        *out = s[RC_PT_FILM_BEAUTY].w;
    }
    return image;
}

bool has_sums(const Image& image) {
    const std::vector<std::string> names = sums_channel_names();
    return std::all_of(names.begin(), names.end(), [&](const std::string& name) {
        return std::find(image.channel_names.begin(), image.channel_names.end(), name) !=
               image.channel_names.end();
    });
}

Image sums_of(const Image& image) {
    return select_layers(image, {std::begin(kSumsLayers), std::end(kSumsLayers)});
}

Image resolve_sums(const Image& sums) {
    if (sums.channels != kSumsChannels) {
        throw Error("internal: a sums image has " + std::to_string(sums.channels) + " channels");
    }
    // Layers beauty, stddev (from the squares), direct, indirect, albedo, normal as the path
    // tracer orders them: beauty, direct, indirect, albedo, normal, stddev.
    Image image(sums.width, sums.height, 18);
    image.channel_names = {"R", "G", "B"};
    for (const char* layer : {"direct", "indirect", "albedo", "normal", "stddev"}) {
        for (const char* c : {"R", "G", "B"}) {
            image.channel_names.push_back(std::string(layer) + "." + c);
        }
    }
    constexpr int kOrder[6] = {0, 5, 1, 2, 3, 4};  // sums layer -> image layer
    const size_t pixels = static_cast<size_t>(sums.width) * sums.height;
    for (size_t p = 0; p < pixels; ++p) {
        const float* s = &sums.pixels[p * kSumsChannels];
        float* out = &image.pixels[p * 18];
        const float n = s[18];
        const float inv = n > 0.0f ? 1.0f / n : 0.0f;
        for (int layer = 0; layer < 6; ++layer) {
            for (int c = 0; c < 3; ++c) {
                out[3 * kOrder[layer] + c] = s[3 * layer + c] * inv;
            }
        }
        for (int c = 0; c < 3; ++c) {
            const float mean = out[c];
            const float square = out[15 + c];
            out[15 + c] =
                n > 1.0f ? std::sqrt(std::max(0.0f, square - mean * mean) * n / (n - 1.0f)) : 0.0f;
        }
    }
    return image;
}

}  // namespace rc
