// Program builds: include expansion, the build log of a broken kernel, and the binary cache
// (hits, header changes, corrupt entries).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "device/binary_cache.h"
#include "device/build_log.h"
#include "device/compiler_workarounds.h"
#include "device/context.h"
#include "device/kernel_sources.h"
#include "methods/radiance_source.h"
#include "shared/rng.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

size_t occurrences(const std::string& text, const std::string& needle) {
    size_t count = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) {
        ++count;
    }
    return count;
}

// A copy of the source tree's kernels/ to edit.
std::filesystem::path copy_of_kernels(const std::string& name) {
    const std::filesystem::path dir = test::scratch_dir(name) / "kernels";
    std::filesystem::copy(test::source_dir() / "kernels", dir,
                          std::filesystem::copy_options::recursive);
    return dir;
}

void append(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::app);
    out << text;
}

TEST(ProgramBuild, ExpandsEveryIncludeOnceWithLineMarkers) {
    const KernelSources sources;
    const std::string text = sources.expand("normals/normals.cl");
    EXPECT_EQ(occurrences(text, "#line 1 \"shared/types.h\""), 1u);
    EXPECT_EQ(occurrences(text, "#line 1 \"common/bvh_traversal.h\""), 1u);
    EXPECT_EQ(occurrences(text, "#line 1 \"normals/normals.cl\""), 1u);
    EXPECT_EQ(occurrences(text, "#include \""), 0u);
    EXPECT_EQ(occurrences(text, "#pragma once"), 0u);
}

// Irradiance caching reads the grid only through its lookup (the radiance source): its programs
// hold none of the grid's deposition, which needs 64-bit atomics.
TEST(ProgramBuild, IrradianceCachingLeavesTheGridsDepositionOut) {
    const KernelSources sources;
    for (const char* entry :
         {"irradiance_cache/irradiance_cache.cl", "irradiance_cache/ic_record_cells.cl"}) {
        const std::string text = sources.expand(entry);
        EXPECT_EQ(occurrences(text, "#line 1 \"irradiance_vector_grid/ivg_deposit.h\""), 0u)
            << entry;
        EXPECT_EQ(occurrences(text, "rc_ivg_deposit_segment"), 0u) << entry;
        // compat.h's two definitions (the extension's and the 32-bit fallback), no call.
        EXPECT_EQ(occurrences(text, "rc_atomic_add_long("), 2u) << entry;
    }
    const std::string grid = sources.expand("irradiance_vector_grid/irradiance_vector_grid.cl");
    EXPECT_EQ(occurrences(grid, "#line 1 \"irradiance_vector_grid/ivg_deposit.h\""), 1u);
}

// The hemisphere rays' kernel builds for every radiance source (records/radiance_source.h).
TEST(ProgramBuild, RecordCellsBuildForEveryRadianceSource) {
    Context& context = test::shared_context();
    for (int source : {RC_RADIANCE_PATH, RC_RADIANCE_RECORDS, RC_RADIANCE_GRID}) {
        const Kernel kernel = context.kernel("irradiance_cache/ic_record_cells.cl",
                                             "ic_record_cells", radiance_source_define(source));
        EXPECT_EQ(kernel.name(), "ic_record_cells");
    }
}

TEST(ProgramBuild, OverrideDirectoryIsReadAndMissingIncludesAreNamed) {
    const std::filesystem::path dir = copy_of_kernels("missing_include");
    append(dir / "normals" / "normals.h", "\n#include \"common/does_not_exist.h\"\n");
    const KernelSources sources(dir);
    try {
        sources.expand("normals/normals.cl");
        FAIL() << "no error";
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("normals/normals.h:"), std::string::npos) << message;
        EXPECT_NE(message.find("common/does_not_exist.h"), std::string::npos) << message;
    }
}

// A copy of kernels/ named `name` whose normals.h does not compile.
std::filesystem::path broken_kernels(const std::string& name) {
    const std::filesystem::path dir = copy_of_kernels(name);
    append(dir / "normals" / "normals.h", "\nthis_is_not_opencl_c broken;\n");
    return dir;
}

// Context options reading the broken kernels `name`, without the binary cache.
ContextOptions broken_kernel_options(const std::string& name) {
    ContextOptions options = test::default_context_options();
    options.kernel_dir = broken_kernels(name);
    options.cache_dir.clear();
    return options;
}

TEST(ProgramBuild, BrokenKernelReportsTheBuildLogWithFileAndLine) {
    Context context(broken_kernel_options("broken_kernel"));
    try {
        context.kernel("normals/normals.cl", "render_normals");
        FAIL() << "no error";
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_NE(
            message.find("clBuildProgram(normals/normals.cl) failed: CL_BUILD_PROGRAM_FAILURE"),
            std::string::npos)
            << message;
        EXPECT_NE(message.find("build log"), std::string::npos) << message;
        EXPECT_NE(message.find("normals/normals.h:"), std::string::npos) << message;
        EXPECT_NE(message.find("this_is_not_opencl_c"), std::string::npos) << message;
    }
}

// The line (1-based) of `expanded`, normals.cl expanded, holding `needle`, and the line of
// normals/normals.h that holds it, found by searching the texts (not through the #line markers).
struct FoundLine {
    long expanded = 0;
    long original = 0;
};
FoundLine find_line(const std::string& expanded, const std::string& needle) {
    FoundLine found;
    std::istringstream lines(expanded);
    std::string line;
    for (long n = 1; std::getline(lines, line); ++n) {
        if (line.find(needle) != std::string::npos) {
            found.expanded = n;
        }
    }
    std::ifstream header(test::source_dir() / "kernels" / "normals" / "normals.h");
    for (long n = 1; std::getline(header, line); ++n) {
        if (line.find(needle) != std::string::npos) {
            found.original = n;
        }
    }
    return found;
}

TEST(ProgramBuild, VendorLogsWithoutFileNamesAreMappedToOurFileAndLine) {
    // The last line of normals.h that opens a function: unique enough to find by text.
    std::ifstream header(test::source_dir() / "kernels" / "normals" / "normals.h");
    std::string line;
    std::string needle;
    while (std::getline(header, line)) {
        if (line.rfind("RC_FUNC ", 0) == 0) {
            needle = line;
        }
    }
    ASSERT_FALSE(needle.empty());
    const std::string source = KernelSources().expand("normals/normals.cl");
    const FoundLine at = find_line(source, needle);
    ASSERT_GT(at.expanded, 0);
    ASSERT_GT(at.original, 0);
    const std::string ours = "normals/normals.h:" + std::to_string(at.original);
    // NVIDIA: <kernel>:LINE:COL; Intel: a number as the name; AMD: "FILE", line LINE.
    EXPECT_EQ(map_build_log("<kernel>:" + std::to_string(at.expanded) + ":5: error: bad", source),
              ours + ":5: error: bad");
    EXPECT_EQ(map_build_log("1:" + std::to_string(at.expanded) + ":9: warning: w", source),
              ours + ":9: warning: w");
    EXPECT_EQ(map_build_log("\"/tmp/OCL77.cl\", line " + std::to_string(at.expanded) +
                                ": error: identifier is undefined",
                            source),
              ours + ": error: identifier is undefined");
    // A log that already names our files (the compiler honoured #line) and its other lines stay.
    const std::string honoured =
        ours + ":3: error: x\n    int x = y;\n        ^\n1 error generated.";
    EXPECT_EQ(map_build_log(honoured, source), honoured);
    // A line beyond the source stays a plain number.
    EXPECT_EQ(map_build_log("<kernel>:99999999:1: error: e", source), "99999999:1: error: e");
}

TEST(ProgramBuild, ABackgroundBuildFailureIsReportedWhenTheProgramIsUsed) {
    const ContextOptions options = broken_kernel_options("broken_prebuild");
    {
        Context context(options);
        context.prebuild({{"normals/normals.cl", ""}, {"rng_probe.cl", ""}});
        EXPECT_EQ(context.program("rng_probe.cl").kernel("rng_stream_words").name(),
                  "rng_stream_words");
        try {
            context.program("normals/normals.cl");
            FAIL() << "no error";
        } catch (const Error& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("clBuildProgram(normals/normals.cl) failed"), std::string::npos)
                << message;
            EXPECT_NE(message.find("this_is_not_opencl_c"), std::string::npos) << message;
        }
    }
    // A failed background build nobody asks for ends with the context, silently.
    Context unused(options);
    unused.prebuild({{"normals/normals.cl", ""}});
}

// The error, with its build log, is all the user sees: PoCL's compiler prints its own summary
// ("1 error generated.") on stderr during clBuildProgram, which used to come before our line; it
// is now the build log's last line.
TEST(ProgramBuild, BrokenKernelThroughTheCommandLineExitsNonZeroWithTheLog) {
    const std::filesystem::path dir = broken_kernels("broken_kernel_cli");
    const auto output = dir.parent_path() / "out.png";
    const test::CommandResult result = test::run_radcache(
        {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "-o",
         output.string(), "--method", "normals", "--kernel-dir", dir.string(), "--no-kernel-cache",
         "--quiet"});
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_EQ(result.output.rfind("radcache: error: clBuildProgram(normals/normals.cl) failed", 0),
              0u)
        << result.output;
    const size_t log = result.output.find("build log:");
    EXPECT_NE(log, std::string::npos) << result.output;
    EXPECT_GT(result.output.find("this_is_not_opencl_c"), log) << result.output;
    const size_t summary = result.output.find(" generated.");
    if (summary != std::string::npos) {
        EXPECT_GT(summary, log) << result.output;
    }
    EXPECT_FALSE(std::filesystem::exists(output));
}

// The build report of rng_probe.cl in a new context of `options`.
ProgramBuildReport probe_build(const ContextOptions& options) {
    Context context(options);
    return context.program("rng_probe.cl").report();
}

TEST(ProgramBuild, BinaryCacheHitsAndSeesHeaderChanges) {
    ContextOptions options = test::default_context_options();
    options.cache_dir = test::scratch_dir("cache_hits");
    EXPECT_FALSE(probe_build(options).from_cache);
    EXPECT_TRUE(probe_build(options).from_cache);
    // A comment added to an included header changes the expanded source and so the key.
    const std::filesystem::path dir = copy_of_kernels("cache_header_change");
    append(dir / "shared/rng.h", "\n// a change\n");
    options.kernel_dir = dir;
    EXPECT_FALSE(probe_build(options).from_cache);
}

TEST(ProgramBuild, CorruptCacheEntryIsIgnoredAndRebuilt) {
    ContextOptions options = test::default_context_options();
    options.cache_dir = test::scratch_dir("cache_corrupt");
    probe_build(options);
    std::vector<std::filesystem::path> entries;
    for (const auto& entry : std::filesystem::directory_iterator(options.cache_dir)) {
        entries.push_back(entry.path());
    }
    ASSERT_EQ(entries.size(), 1u);
    // Flip bytes in the middle of the stored binary.
    std::string bytes = read_file(entries[0]);
    ASSERT_GT(bytes.size(), 100u);
    for (size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i) {
        bytes[i] = static_cast<char>(~bytes[i]);
    }
    write_file_atomically(entries[0], bytes);
    {
        Context context(options);
        const ProgramBuildReport report = context.program("rng_probe.cl").report();
        EXPECT_FALSE(report.from_cache);
        EXPECT_TRUE(report.replaced_corrupt_entry);
        // The rebuilt program works.
        Kernel kernel = context.kernel("rng_probe.cl", "rng_stream_words");
        Buffer<unsigned> out(context, 8, "words");
        context.launch(kernel, 8, 1u, 2u, 3u, 1u, out);
        EXPECT_EQ(out.download()[5], shared::rc_rng_word(1, 2, 5, 3, 0));
    }
    // A truncated entry too.
    write_file_atomically(entries[0], read_file(entries[0]).substr(0, 40));
    EXPECT_TRUE(probe_build(options).replaced_corrupt_entry);
    // An entry whose checksum is right but whose binary the driver refuses.
    {
        const DeviceInfo& device = test::shared_context().device();
        // The options every program of a default Context is built with: the language, the
        // BVH layout and the device's compiler workarounds.
        std::string built_with = "-cl-std=CL1.2 -DRC_BVH_LAYOUT=" +
                                 std::to_string(static_cast<int>(default_bvh_layout()));
        if (const std::string workarounds = compiler_workaround_options(device);
            !workarounds.empty()) {
            built_with += " " + workarounds;
        }
        const BinaryCacheKey key = BinaryCacheKey::of(
            KernelSources().expand("rng_probe.cl"), built_with, device.name, device.driver_version);
        const BinaryCache cache(options.cache_dir);
        ASSERT_EQ(cache.entry_path(key), entries[0]);
        cache.store(key, std::vector<unsigned char>(4096, 0x5a));
        EXPECT_TRUE(probe_build(options).replaced_corrupt_entry);
    }
    // The rebuilt entry is valid again.
    EXPECT_TRUE(probe_build(options).from_cache);
}

TEST(ProgramBuild, DumpKernelsWritesTheExpandedSource) {
    ContextOptions options = test::default_context_options();
    options.dump_kernels_dir = test::scratch_dir("dump");
    Context context(options);
    context.program("trace.cl");
    const std::string dumped = read_file(options.dump_kernels_dir / "trace.cl");
    EXPECT_NE(dumped.find("rc_trace_closest"), std::string::npos);
    EXPECT_NE(dumped.find("-cl-std=CL1.2"), std::string::npos);
    EXPECT_NE(dumped.find("-DRC_BVH_LAYOUT="), std::string::npos);
    // Builds of one entry with other options go to files of their own.
    context.program("irradiance_cache/ic_record_cells.cl",
                    radiance_source_define(RC_RADIANCE_GRID));
    const std::string grid = read_file(
        options.dump_kernels_dir / "irradiance_cache_ic_record_cells._DRC_RADIANCE_SOURCE_2.cl");
    EXPECT_NE(grid.find("-DRC_RADIANCE_SOURCE=2"), std::string::npos);
}

}  // namespace
}  // namespace rc
