#include "methods/sample_passes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "util/error.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {

void add_weighted(Image* mean, double mean_weight, const Image& image, double weight) {
    if (mean->pixels.empty()) {
        *mean = image;
        return;
    }
    if (mean->width != image.width || mean->height != image.height ||
        mean->channels != image.channels) {
        throw Error("internal: passes of one frame gave images of different shapes");
    }
    const double total = mean_weight + weight;
    for (size_t i = 0; i < mean->pixels.size(); ++i) {
        mean->pixels[i] =
            static_cast<float>((mean_weight * mean->pixels[i] + weight * image.pixels[i]) / total);
    }
}

namespace {

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    return text;
}

// The largest total samples per pixel a render may reach (--spp's own bound).
constexpr int kMaxSamples = 1 << 24;

// The samples of the pass after one that took `per_sample` seconds a sample per pixel, with
// `left` seconds left and `samples` taken so far; 0 when not one more fits.
int next_pass_spp(double left, double per_sample, int samples, int max_spp) {
    if (!(left > 0.0) || samples >= kMaxSamples) {
        return 0;
    }
    const double fits = per_sample > 0.0 ? std::floor(left / per_sample) : double(kMaxSamples);
    if (!(fits >= 1.0)) {
        return 0;
    }
    const double most = std::min(
        {fits, double(samples), double(std::max(max_spp, 1)), double(kMaxSamples - samples)});
    return static_cast<int>(most);
}

// A pass's own figures in the stats: its samples, its wall time (pass_seconds), the method's
// stats of it (their "seconds" the method's phases).
nlohmann::json pass_stats(const SamplePass& pass, double seconds, const nlohmann::json& stats) {
    nlohmann::json entry = stats.is_object() ? stats : nlohmann::json::object();
    entry["first_sample"] = pass.first;
    entry["spp"] = pass.spp;
    entry["pass_seconds"] = seconds;
    return entry;
}

}  // namespace

FrameResult render_sample_passes(const SamplePassBudget& budget, const FrameHooks& hooks,
                                 const std::function<FrameResult(const SamplePass&)>& pass) {
    const auto start = SteadyClock::now();
    const std::function<double()> clock =
        budget.clock ? budget.clock
                     : std::function<double()>([start] { return seconds_since(start); });
    FrameResult result;
    nlohmann::json later = nlohmann::json::array();
    double first_seconds = 0.0;
    SamplePass next{0, 1};
    while (next.spp > 0) {
        const double before = clock();
        FrameResult part = pass(next);
        const double seconds = clock() - before;
        if (next.first == 0) {
            result.stats = part.stats;
            result.cache_seconds = part.cache_seconds;
            first_seconds = seconds;
        } else {
            later.push_back(pass_stats(next, seconds, part.stats));
        }
        add_weighted(&result.image, next.first, part.image, next.spp);
        result.rays += part.rays;
        result.nonfinite_samples += part.nonfinite_samples;
        if (result.first_nonfinite_pixel < 0) {
            result.first_nonfinite_pixel = part.first_nonfinite_pixel;
        }
        result.spp = next.first + next.spp;
        if (hooks.progress) {
            hooks.progress(std::min(1.0, clock() / budget.seconds),
                           std::to_string(result.spp) + " spp");
        }
        // The cost of a sample: the pass's time, less what built the cache for the first (when
        // it says; a later pass's new records count as the cost of its samples).
        const double cache = next.first == 0 ? std::clamp(part.cache_seconds, 0.0, seconds) : 0.0;
        const double sampling = seconds - cache;
        next = {result.spp, next_pass_spp(budget.seconds - clock(), sampling / next.spp, result.spp,
                                          budget.max_spp)};
    }
    const double total = clock();
    if (first_seconds > budget.seconds) {
        log_note("by time: the cache and one sample per pixel took " + seconds_text(first_seconds) +
                 ", beyond --time " + seconds_text(budget.seconds) +
                 ": the image has 1 spp (a cheaper cache or --method pt suits this budget)");
    }
    log_note("by time: " + seconds_text(first_seconds) + " for the cache and 1 spp, " +
             std::to_string(result.spp - 1) + " more spp in " +
             seconds_text(total - first_seconds) + " (" + std::to_string(later.size()) +
             " more passes)");
    result.stats["spp"] = result.spp;
    result.stats["passes"] = later;
    result.stats["time"] = {{"budget", budget.seconds},
                            {"passes", later.size() + 1},
                            {"spp", result.spp},
                            {"first_pass_seconds", first_seconds},
                            {"later_passes_seconds", total - first_seconds}};
    return result;
}

}  // namespace rc
