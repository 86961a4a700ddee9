// `--method auto` (docs/auto.md): the image with the lowest expected error in the time given,
// without knowing the methods. On the first frame a short pilot on this device measures the
// scene (the path tracer's noise, a caching method's work); the model (auto_model.json) turns the
// figures into a plan (which method serves each material, the knobs and the samples); the plan's
// method then renders every frame.
#include <algorithm>
#include <memory>
#include <optional>
#include <set>

#include "methods/auto/auto_materials.h"
#include "methods/auto/auto_motion.h"
#include "methods/auto/auto_pilot.h"
#include "methods/auto/auto_plan.h"
#include "methods/auto/auto_runs.h"
#include "methods/auto/auto_throughput.h"
#include "methods/method.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {
namespace {

// The layers every method auto may choose writes, and so auto's.
const std::vector<std::string> kAutoAovs = {"beauty", "direct", "indirect", "albedo", "normal"};

struct AutoOptions {
    bool spp_fixed = false;  // --spp (or -D spp=) on the command line: the samples are the user's
};

// Whether the command line fixes the samples per pixel.
bool spp_on_command_line(const ParsedArguments& arguments) {
    if (arguments.has("--spp")) {
        return true;
    }
    const std::vector<std::string> overrides = arguments.values("-D");
    return std::any_of(overrides.begin(), overrides.end(),
                       [](const std::string& d) { return d.rfind("spp=", 0) == 0; });
}

class AutoMethod final : public Method {
   public:
    AutoMethod(const AutoOptions& options, const MethodSettings& settings)
        : options_(options), settings_(settings) {}

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        nlohmann::json plan_json;
        if (!inner_) {
            plan_json = make_plan(frame, hooks);
            MethodSettings inner = settings_;
            inner.spp = plan_.spp;
            inner.time = 0.0;
            inner_ = make_method(plan_.run, inner);
            check_plan_memory(frame);
        }
        FrameResult result = inner_->render_frame(frame, hooks);
        result.image = select_layers(result.image, kAutoAovs);
        result.stats["auto"] =
            plan_json.is_null() ? nlohmann::json{{"method", plan_.run.method}} : plan_json;
        return result;
    }

    std::optional<nlohmann::json> plan(const FrameScene& frame, const FrameHooks& hooks) override {
        return make_plan(frame, hooks);
    }

    std::vector<ProgramRequest> programs() const override {
        std::vector<ProgramRequest> programs;
        std::set<std::pair<std::string, std::string>> seen;
        for (const char* method : {"pt", "ic", "rc", "sdrc"}) {
            for (ProgramRequest& request : make_method({method, {}}, settings_)->programs()) {
                if (seen.insert({request.entry, request.options}).second) {
                    programs.push_back(std::move(request));
                }
            }
        }
        return programs;
    }

    // The path tracer's, the least of any plan's: the plan's own method is checked once made
    // (check_plan_memory), before its first buffer.
    DeviceMemoryNeed device_memory_need(const Scene& scene,
                                        const DeviceInfo& device) const override {
        DeviceMemoryNeed need =
            make_method({"pt", {}}, settings_)->device_memory_need(scene, device);
        need.excludes += std::string(need.excludes.empty() ? "" : ", ") +
                         "the buffers of the method the plan chooses (checked once it is chosen)";
        return need;
    }

   private:
    // The plan's method, beside what the device holds now (the scene and its BVH), fits.
    void check_plan_memory(const FrameScene& frame) const {
        DeviceMemoryNeed need;
        need.add("held", frame.context.device_memory().in_use);
        need.add_all(inner_->device_memory_need(frame.scene, frame.context.device()),
                     plan_.run.method + " ");
        check_device_memory_need(frame.context, need);
    }

    // Pilot, model and plan (once); the plan's line on stderr; its statistics returned.
    nlohmann::json make_plan(const FrameScene& frame, const FrameHooks& hooks) {
        const auto start = SteadyClock::now();
        const AutoModel& model = auto_model();
        const DeviceThroughput throughput = device_throughput(frame.context, hooks);
        PlanInputs in;
        in.model = &model;
        in.throughput = &throughput;
        in.budget = settings_.time;
        in.spp = settings_.spp;
        in.spp_fixed = options_.spp_fixed;
        in.pixels =
            static_cast<double>(render_width(settings_, frame)) * render_height(settings_, frame);
        in.frames = settings_.frame_count;
        in.motion = clip_motion(frame.scene, settings_.first_frame,
                                settings_.first_frame + std::max(settings_.frame_count, 1) - 1);
        in.noise = noise_pilot(frame, settings_, model, hooks);
        in.pilot_seconds = static_cast<double>(in.noise.rays) * throughput.pt_seconds_per_ray;
        choose_materials(frame, hooks, model, throughput, &in);
        plan_ = choose_plan(in);
        log_note(plan_.line());
        nlohmann::json json = plan_.json(in);
        json["pilot"]["measured_seconds"] = seconds_since(start);
        json["throughput"] = {{"file", throughput.file.string()},
                              {"measured_now", throughput.measured_now}};
        return json;
    }

    // The materials' servers (radiance caching's tables asked when a lobe is glossy) and the
    // cache pilot of the caching method that serves them.
    void choose_materials(const FrameScene& frame, const FrameHooks& hooks, const AutoModel& model,
                          const DeviceThroughput& throughput, PlanInputs* in) {
        const auto& materials = frame.scene.materials;
        const bool glossy = std::any_of(materials.begin(), materials.end(), has_glossy_lobe);
        nlohmann::json tables;
        if (glossy) {
            const TablePilot pilot = brdf_table_pilot(frame, settings_, hooks);
            tables = pilot.materials;
            in->pilot_seconds +=
                static_cast<double>(pilot.rays) * throughput.cache_of("rc", kTableRays);
            in->tables_seconds =
                static_cast<double>(pilot.glossy_materials) * throughput.table_seconds_per_material;
        }
        in->materials = choose_lobe_servers(materials, model, glossy ? &tables : nullptr);
        in->cache_run = caching_run(in->materials, materials);
        in->cache = cache_pilot(frame, settings_, model, in->cache_run, hooks);
        add_pilot_seconds(*in->cache, model_key(in->materials), throughput, in);
    }

    static void add_pilot_seconds(const CachePilot& pilot, const std::string& key,
                                  const DeviceThroughput& throughput, PlanInputs* in) {
        in->pilot_seconds +=
            static_cast<double>(pilot.cache_rays) * throughput.cache_of(key, pilot.ic_rays) +
            static_cast<double>(pilot.rays - pilot.cache_rays) * throughput.camera_of(key);
    }

    AutoOptions options_;
    MethodSettings settings_;
    AutoPlan plan_;
    std::unique_ptr<Method> inner_;
};

}  // namespace

MethodEntry auto_method_entry() {
    MethodDefinition<AutoOptions> definition;
    definition.name = "auto";
    definition.summary =
        "the method, knobs and samples with the lowest predicted error in --time, chosen per "
        "material from a short pilot on this device (docs/auto.md)";
    definition.aovs = kAutoAovs;
    definition.finish = [](AutoOptions& options, const ParsedArguments& arguments) {
        options.spp_fixed = spp_on_command_line(arguments);
    };
    definition.create = [](const AutoOptions& options, const MethodSettings& settings) {
        return std::make_unique<AutoMethod>(options, settings);
    };
    return method_entry(std::move(definition));
}

}  // namespace rc
