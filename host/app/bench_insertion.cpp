// `radcache bench insertion`: the host's record insertion (neighbor clamping, DESIGN.md §6.2
// step 4) over a saved irradiance cache's records, one by one and in batches on one thread and
// on all the host's threads, side by side; every way must give the radii the render gave, bit for
// bit (docs/lab/devices.md, "The host's own work in an `ic` render").
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "methods/caching/cache_file.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/caching/irradiance_records.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/parallel_ranges.h"
#include "util/timing.h"

namespace rc {
namespace {

// One way of inserting: batch size (0: one by one) and threads.
struct InsertionWay {
    std::string name;
    size_t batch = 0;
    unsigned threads = 1;
    std::vector<double> seconds;  // one per repeat
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The level's records as the render made them: initial R from their harmonic distance and
// gradient limit (RecordStore::insert recomputes the clamped one).
std::vector<NewRecord> new_records(const RecordStore& level,
                                   std::vector<shared::IrradiancePayload>& payloads) {
    payloads.resize(level.size());
    std::vector<NewRecord> records(level.size());
    for (size_t i = 0; i < level.size(); ++i) {
        payloads[i] = level.payload<shared::IrradiancePayload>(i);
        RecordHostData host = level.host_data()[i];
        host.radius = 0.0f;
        records[i] = {level.records()[i], host, &payloads[i], irradiance_radius_limit(payloads[i])};
    }
    return records;
}

// Inserts every record the given way; throws unless each radius is the saved one, bit for bit.
double time_insertion(const RecordStore& level, const std::vector<NewRecord>& records,
                      const InsertionWay& way) {
    RecordStore store = irradiance_store(level.accuracy());
    store.set_threads(way.threads);
    const auto start = SteadyClock::now();
    const size_t batch = way.batch > 0 ? way.batch : 1;
    for (size_t begin = 0; begin < records.size(); begin += batch) {
        const size_t end = std::min(records.size(), begin + batch);
        store.insert_batch(std::vector<NewRecord>(records.begin() + begin, records.begin() + end));
    }
    const double seconds = seconds_since(start);
    for (size_t i = 0; i < records.size(); ++i) {
        if (store.host_data()[i].radius != level.host_data()[i].radius) {
            throw Error("bench insertion: " + way.name + " gave record " + std::to_string(i) +
                        " another radius than the saved cache");
        }
    }
    return seconds;
}

std::vector<OptionSpec> bench_insertion_options() {
    return {
        {"--cache-in", "", "FILE", "irradiance cache saved by `radcache render --cache-out`"},
        {"--scene", "", "FILE", "the scene it was made for (default cornell-box)"},
        OptionSpec{"--accuracy", "", "A", "the accuracy it was made with (default 0.35)"}.numbers(
            1e-6, 1.0),
        OptionSpec{"--batch", "", "N", "records per batch (default 1024)"}.integers(1, 1 << 24),
        OptionSpec{"--repeats", "", "N",
                   "rounds of every way, interleaved; the median reported (default 3)"}
            .integers(1, 1000),
        {"--json", "", "FILE", "also write the results as JSON"},
    };
}

int bench_insertion(const ParsedArguments& arguments) {
    if (!arguments.has("--cache-in")) {
        throw Error("bench insertion needs --cache-in FILE", kExitUsage);
    }
    const std::string scene_path =
        arguments.has("--scene") ? arguments.value("--scene") : shipped_scene("cornell-box");
    check_bench_files(arguments, {scene_path});
    const float accuracy =
        static_cast<float>(arguments.number("--accuracy", PipelineSettings{}.accuracy));
    const size_t batch = static_cast<size_t>(arguments.integer("--batch", 1024));
    const int repeats = static_cast<int>(arguments.integer("--repeats", 3));
    const Scene scene = load_scene(scene_path);
    const std::vector<RecordStore> levels =
        read_cache_file(arguments.value("--cache-in"), irradiance_cache_key(scene, accuracy));
    std::vector<InsertionWay> ways = {{"one by one", 0, 1},
                                      {"batches, 1 thread", batch, 1},
                                      {"batches, all threads", batch, host_threads()}};
    nlohmann::json report_levels = nlohmann::json::array();
    for (size_t l = 0; l < levels.size(); ++l) {
        std::vector<shared::IrradiancePayload> payloads;
        const std::vector<NewRecord> records = new_records(levels[l], payloads);
        nlohmann::json level = {{"level", l}, {"records", records.size()}};
        for (InsertionWay& way : ways) {
            way.seconds.clear();
        }
        for (int r = 0; r < repeats; ++r) {
            for (InsertionWay& way : ways) {
                way.seconds.push_back(time_insertion(levels[l], records, way));
            }
        }
        for (const InsertionWay& way : ways) {
            const double seconds = median(way.seconds);
            std::printf("level %zu, %zu records, %-22s %2u thread(s): %8.4f s (%.4f-%.4f)\n", l,
                        records.size(), way.name.c_str(), way.threads, seconds,
                        *std::min_element(way.seconds.begin(), way.seconds.end()),
                        *std::max_element(way.seconds.begin(), way.seconds.end()));
            level["ways"].push_back({{"way", way.name},
                                     {"batch", way.batch},
                                     {"threads", way.threads},
                                     {"seconds", seconds},
                                     {"seconds_each", way.seconds}});
        }
        report_levels.push_back(level);
    }
    std::printf("every way gave the saved radii, bit for bit\n");
    if (arguments.has("--json")) {
        const nlohmann::json report = {{"cache", arguments.value("--cache-in")},
                                       {"scene", scene_path},
                                       {"batch", batch},
                                       {"host_threads", host_threads()},
                                       {"repeats", repeats},
                                       {"levels", report_levels}};
        write_file_atomically(arguments.value("--json"), report.dump(2) + "\n");
    }
    return 0;
}

}  // namespace

CommandSpec bench_insertion_command() {
    return {.name = "bench insertion",
            .summary = "the host's record insertion and neighbor clamping over a saved cache",
            .usage = "radcache bench insertion --cache-in FILE [options]",
            .description =
                "Inserts a saved irradiance cache's records again, level by level: one by one, in\n"
                "batches on one thread and in batches on all the host's threads (host seconds of\n"
                "each, the median of --repeats interleaved rounds). Every way must give the radii\n"
                "the render gave, bit for bit (otherwise an error).",
            .options = bench_insertion_options(),
            .run = bench_insertion};
}

}  // namespace rc
