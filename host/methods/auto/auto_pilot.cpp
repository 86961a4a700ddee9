#include "methods/auto/auto_pilot.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace rc {
namespace {

// A pilot seed: the render's, moved so the pilot's samples are not the render's own.
uint64_t pilot_seed(uint64_t seed, uint64_t which) {
    return seed ^ (0x9e3779b97f4a7c15ull * (which + 1));
}

MethodSettings pilot_settings(const MethodSettings& settings, const PilotSize& size, int spp,
                              uint64_t seed) {
    MethodSettings pilot = settings;
    pilot.width = size.width;
    pilot.height = size.height;
    pilot.spp = spp;
    pilot.time = 0.0;
    pilot.seed = seed;
    pilot.frame_count = 1;
    pilot.layers = {"beauty"};
    return pilot;
}

// Two path-traced images of `spp` samples (seeds apart) at `depth`: their rays, and the per-sample
// relMSE and the summed light of their mean.
struct NoisePair {
    double v = 0.0;
    double light = 0.0;
    uint64_t rays = 0;
};

// The mean of the two images' mean over the pixels around (x, y) (up to 8, the pixel itself left
// out): the relMSE's denominator, as independent of the pixel's own noise as the pilot allows.
// The pixel's own mean would share its outliers with the difference it divides (a sample of 50
// times the pixel's light enters both), and so bounded the estimate: it read the path tracer's
// noise 1.6 (Cornell box) to 5.5 (two-rooms) times low; the neighbours' mean reads it within
// 1.1 (docs/lab/auto.md).
double neighbours_mean(const Image& a, const Image& b, int x, int y, int c) {
    double sum = 0.0;
    int count = 0;
    for (int v = std::max(0, y - 1); v <= std::min(a.height - 1, y + 1); ++v) {
        for (int u = std::max(0, x - 1); u <= std::min(a.width - 1, x + 1); ++u) {
            if (u != x || v != y) {
                sum += 0.5 * (static_cast<double>(a.at(u, v, c)) + b.at(u, v, c));
                ++count;
            }
        }
    }
    return count > 0 ? sum / count : 0.5 * (static_cast<double>(a.at(x, y, c)) + b.at(x, y, c));
}

NoisePair noise_pair(const FrameScene& frame, const MethodSettings& settings, const PilotSize& size,
                     int spp, int depth, const FrameHooks& hooks) {
    FrameResult images[2];
    for (int i = 0; i < 2; ++i) {
        MethodSettings pilot = pilot_settings(settings, size, spp, pilot_seed(settings.seed, i));
        pilot.max_depth = depth;
        const std::unique_ptr<Method> pt = make_method({"pt", {}}, pilot);
        images[i] = render_quietly(*pt, frame, hooks);
    }
    const Image& a = images[0].image;
    const Image& b = images[1].image;
    NoisePair pair;
    pair.rays = images[0].rays + images[1].rays;
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double d = static_cast<double>(a.at(x, y, c)) - b.at(x, y, c);
                const double mean = neighbours_mean(a, b, x, y, c);
                // Var of one sample: spp (a - b)^2 / 2 (each image the mean of spp samples).
                sum += spp * 0.5 * d * d / (mean * mean + 0.01);
                pair.light += 0.5 * (static_cast<double>(a.at(x, y, c)) + b.at(x, y, c));
            }
        }
    }
    pair.v = sum / (3.0 * a.width * a.height);
    return pair;
}

}  // namespace

int render_width(const MethodSettings& settings, const FrameScene& frame) {
    return settings.width > 0 ? settings.width : frame.scene.camera.width;
}

int render_height(const MethodSettings& settings, const FrameScene& frame) {
    return settings.height > 0 ? settings.height : frame.scene.camera.height;
}

PilotSize pilot_size(const AutoModel& model, int width, int height) {
    const int shorter = std::min(width, height);
    const int side =
        std::min(shorter, std::max(model.pilot_min_side, shorter / model.pilot_divisor));
    const double scale = static_cast<double>(side) / shorter;
    PilotSize size;
    size.width = std::max(1, static_cast<int>(std::lround(width * scale)));
    size.height = std::max(1, static_cast<int>(std::lround(height * scale)));
    return size;
}

NoisePilot noise_pilot(const FrameScene& frame, const MethodSettings& settings,
                       const AutoModel& model, const FrameHooks& hooks) {
    NoisePilot pilot;
    pilot.size = pilot_size(model, render_width(settings, frame), render_height(settings, frame));
    const int spp = model.pilot_pt_spp;
    const NoisePair all = noise_pair(frame, settings, pilot.size, spp, settings.max_depth, hooks);
    const NoisePair direct = noise_pair(frame, settings, pilot.size, spp, 1, hooks);
    pilot.v_pt = all.v;
    pilot.v_direct = std::min(direct.v, all.v);
    pilot.indirect_fraction = all.light > 0.0 ? std::max(0.0, 1.0 - direct.light / all.light) : 0.0;
    pilot.rays_per_sample = static_cast<double>(all.rays) / (2.0 * spp * pilot.size.pixels());
    pilot.rays = all.rays + direct.rays;
    return pilot;
}

size_t glossy_table_count(const nlohmann::json& materials) {
    size_t count = 0;
    for (const nlohmann::json& material : materials) {
        count += material.value("kind", std::string()) != "diffuse";
    }
    return count;
}

TablePilot brdf_table_pilot(const FrameScene& frame, const MethodSettings& settings,
                            const FrameHooks& hooks) {
    const PilotSize size{std::min(8, render_width(settings, frame)),
                         std::min(8, render_height(settings, frame))};
    const std::unique_ptr<Method> rc =
        make_method({"rc", {{"--ic-rays", std::to_string(kTableRays)}}},
                    pilot_settings(settings, size, 1, pilot_seed(settings.seed, 3)));
    const FrameResult result = render_quietly(*rc, frame, hooks);
    TablePilot pilot;
    pilot.rays = result.rays;
    if (result.stats.contains("radiance_cache")) {
        pilot.materials = result.stats.at("radiance_cache").value("materials", pilot.materials);
    }
    pilot.glossy_materials = glossy_table_count(pilot.materials);
    return pilot;
}

uint64_t cache_rays_of(const nlohmann::json& stats) {
    uint64_t rays = stats.value("record_rays", uint64_t{0});
    for (const char* cache : {"radiance_cache", "sdrc"}) {
        if (stats.contains(cache)) {
            rays += stats.at(cache).value("record_rays", uint64_t{0});
        }
    }
    return rays;
}

CachePilot cache_pilot(const FrameScene& frame, const MethodSettings& settings,
                       const AutoModel& model, MethodRun run, const FrameHooks& hooks) {
    CachePilot pilot;
    pilot.size = pilot_size(model, render_width(settings, frame), render_height(settings, frame));
    const int default_rays = static_cast<int>(declared_default(run.method, "--ic-rays"));
    pilot.ic_rays = std::max(4, default_rays / model.pilot_rays_divisor);
    pilot.accuracy = declared_default(run.method, "--accuracy");
    run.options.push_back({"--ic-rays", std::to_string(pilot.ic_rays)});
    pilot.run = run;
    const MethodSettings pilot_run =
        pilot_settings(settings, pilot.size, 1, pilot_seed(settings.seed, 2));
    const std::unique_ptr<Method> method = make_method(run, pilot_run);
    const FrameResult result = render_quietly(*method, frame, hooks);
    pilot.stats = result.stats;
    pilot.rays = result.rays;
    pilot.cache_rays = std::min(cache_rays_of(result.stats), result.rays);
    pilot.camera_rays_per_sample =
        static_cast<double>(result.rays - pilot.cache_rays) / pilot.size.pixels();
    return pilot;
}

}  // namespace rc
