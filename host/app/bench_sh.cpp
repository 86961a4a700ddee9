// `radcache bench sh`: the throughput of radiance caching's spherical-harmonic kernels on one
// device (coefficients projected/s, rotations/s, BRDF table build) and the adaptive order of a
// scene's materials in both bases (DESIGN.md §6.4, docs/radiance-caching.md).
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/device_options.h"
#include "device/device_features.h"
#include "methods/radiance_cache/brdf_tables.h"
#include "scene/scene_loader.h"
#include "shared/sh_rotation_zxz.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

double kernel_seconds(const Context& context, const std::string& kernel) {
    const auto found = context.kernel_times().find(kernel);
    return found == context.kernel_times().end() ? 0.0 : found->second.seconds;
}

// Device seconds of one launch of `kernel` over `items` after a warm-up launch.
template <class... Args>
double timed_launch(Context& context, Kernel& kernel, size_t items, const Args&... args) {
    context.launch(kernel, items, args...);
    const double before = kernel_seconds(context, kernel.name());
    context.launch(kernel, items, args...);
    return kernel_seconds(context, kernel.name()) - before;
}

struct ShFigures {
    double coefficients_per_second = 0.0;
    double samples_per_second = 0.0;
    double rotations_per_second = 0.0;
    double zxz_rotations_per_second = 0.0;
};

// Projection of `records` records of m x n stratified samples at order RC_SH_MAX_ORDER (the
// test radiance of rc_cells_probe, a cosine lobe) and rotation of as many r, g, b vector
// triples by random-looking rotations, exact (Ivanic-Ruedenberg) and by the zxzxz factorization.
ShFigures measure(Context& context, int records, int m, int n) {
    ShFigures figures;
    const int order = RC_SH_MAX_ORDER;
    const size_t cells_count = static_cast<size_t>(records) * m * n;
    Kernel cells_kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_cells_probe");
    Kernel projection = context.kernel("radiance_cache/rc_probe.cl", "rc_projection_probe");
    Buffer<shared::float4> cells(context, cells_count, "cells");
    const shared::float4 colour = {1.0f, 0.8f, 0.6f, 0.0f};
    context.launch(cells_kernel, cells_count, m, n, 1u, 2u, 1, RC_BASIS_SH, 0, 1.0f, colour, cells);
    Buffer<float> coefficients(context, static_cast<size_t>(records) * 3 * order * order,
                               "coefficients");
    const double projection_seconds = timed_launch(context, projection, records, m, n, 1u, 2u,
                                                   RC_BASIS_SH, order, cells, coefficients);
    figures.samples_per_second = static_cast<double>(cells_count) / projection_seconds;
    figures.coefficients_per_second = figures.samples_per_second * 3 * order * order;

    std::vector<shared::float4> rows;
    for (int i = 0; i < records; ++i) {
        const float a = 0.37f * i, b = 0.11f * i;  // R = Rz(a) Rx(b)
        const float ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
        rows.push_back({ca, -sa * cb, sa * sb, 0.0f});
        rows.push_back({sa, ca * cb, -ca * sb, 0.0f});
        rows.push_back({0.0f, sb, cb, 0.0f});
    }
    const Buffer<shared::float4> rotations(context, rows, "rotations");
    Kernel rotation = context.kernel("radiance_cache/rc_probe.cl", "rc_rotation_probe");
    const double rotation_seconds =
        timed_launch(context, rotation, records, order, 3, rotations, coefficients);
    figures.rotations_per_second = records / rotation_seconds;

    std::vector<float> table(RC_SH_X90_TABLE_SIZE);
    shared::rc_sh_x90_table(table.data());
    const Buffer<float> x90(context, table, "x90");
    Kernel zxz = context.kernel("radiance_cache/rc_probe.cl", "rc_rotation_zxz_probe");
    const double zxz_seconds =
        timed_launch(context, zxz, records, order, 3, rotations, x90, coefficients);
    figures.zxz_rotations_per_second = records / zxz_seconds;
    return figures;
}

std::vector<OptionSpec> bench_sh_options() {
    return with_device_options({
        {"--scene", "", "FILE", "scene whose materials get BRDF tables (default glossy-box)"},
        OptionSpec{"--records", "", "N",
                   "records projected and vector triples rotated (default 4096)"}
            .integers(1, 1 << 20),
        OptionSpec{"--strata", "", "M",
                   "polar strata M of a record's hemisphere; N = 4 M (default 16)"}
            .integers(1, 256),
        OptionSpec{"--max-error", "", "E", "largest BRDF representation error (default 0.1)"}
            .numbers(1e-6, 0.999),
        OptionSpec{"--resolution", "", "N", "BRDF table texels per side (default 32)"}.integers(
            2, 256),
        {"--json", "", "FILE", "also write the results as JSON"},
    });
}

int bench_sh(const ParsedArguments& arguments) {
    const std::string scene_path =
        arguments.has("--scene") ? arguments.value("--scene") : shipped_scene("glossy-box");
    check_bench_files(arguments, {scene_path});
    const int records = static_cast<int>(arguments.integer("--records", 4096));
    const int m = static_cast<int>(arguments.integer("--strata", 16));
    BrdfTableOptions table_options;
    table_options.max_error = arguments.number("--max-error", table_options.max_error);
    table_options.resolution =
        static_cast<int>(arguments.integer("--resolution", table_options.resolution));

    Context context(context_options(arguments));
    refuse_loop_capped_device(context);
    const Scene scene = load_scene(scene_path);
    const ShFigures figures = measure(context, records, m, 4 * m);
    std::printf("device %s, order %d, %d records of %d x %d samples\n",
                context.device().name.c_str(), RC_SH_MAX_ORDER, records, m, 4 * m);
    std::printf("%-40s %12.2f\n", "SH coefficients projected/s (millions)",
                figures.coefficients_per_second * 1e-6);
    std::printf("%-40s %12.3f\n", "samples projected/s (millions)",
                figures.samples_per_second * 1e-6);
    std::printf("%-40s %12.3f\n", "rgb rotations/s (millions)",
                figures.rotations_per_second * 1e-6);
    std::printf("%-40s %12.3f\n", "rgb rotations/s zxzxz (millions)",
                figures.zxz_rotations_per_second * 1e-6);

    nlohmann::json materials = nlohmann::json::array();
    for (int basis : {RC_BASIS_SH, RC_BASIS_HSH}) {
        table_options.basis = basis;
        const double before = kernel_seconds(context, "rc_brdf_table_texels");
        const BrdfTables tables(context, scene.materials, table_options);
        const double seconds = kernel_seconds(context, "rc_brdf_table_texels") - before;
        const char* name = basis == RC_BASIS_SH ? "SH" : "HSH";
        std::printf("%s BRDF tables of %s: %zu texels in %.3f s (max error %.3g)\n", name,
                    scene_path.c_str(), tables.texel_count(), seconds, table_options.max_error);
        for (const BrdfTableSummary& s : tables.summaries()) {
            std::printf(
                "  %-16s %-8s order %2d  Monte Carlo %5.1f%%  error at order %d %.3f..%.3f\n",
                s.name.c_str(), brdf_kind_name(s.kind), s.order, 100 * s.fallback_fraction,
                RC_SH_MAX_ORDER, s.min_error_at_max_order, s.max_error_at_max_order);
            materials.push_back({{"basis", name},
                                 {"material", s.name},
                                 {"kind", brdf_kind_name(s.kind)},
                                 {"order", s.order},
                                 {"fallback_fraction", s.fallback_fraction},
                                 {"min_error_at_max_order", s.min_error_at_max_order},
                                 {"max_error_at_max_order", s.max_error_at_max_order}});
        }
    }
    if (arguments.has("--json")) {
        const nlohmann::json report = {
            {"device", context.device().name},
            {"order", RC_SH_MAX_ORDER},
            {"records", records},
            {"strata", {m, 4 * m}},
            {"coefficients_projected_per_second", figures.coefficients_per_second},
            {"samples_projected_per_second", figures.samples_per_second},
            {"rotations_per_second", figures.rotations_per_second},
            {"zxz_rotations_per_second", figures.zxz_rotations_per_second},
            {"scene", scene_path},
            {"max_error", table_options.max_error},
            {"resolution", table_options.resolution},
            {"materials", materials}};
        write_file_atomically(arguments.value("--json"), report.dump(2) + "\n");
    }
    return 0;
}

}  // namespace

CommandSpec bench_sh_command() {
    return {
        .name = "bench sh",
        .summary = "radiance caching's spherical harmonics: projection, rotation, BRDF tables",
        .description =
            "Radiance caching's spherical harmonics at order 10 on one device (kernel time):\n"
            "coefficients projected/s from stratified hemisphere samples, r, g, b vector triples\n"
            "rotated/s (Ivanic-Ruedenberg and zxzxz), and the BRDF tables of the scene's "
            "materials: build\n"
            "time and each material's adaptive order in SH and in HSH.",
        .options = bench_sh_options(),
        .run = bench_sh};
}

}  // namespace rc
