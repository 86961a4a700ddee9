// The second reliability probe's output defects, one regression test each: an output naming one
// of the run's inputs (the scene, a mesh, the glTF file, --cache-in, compare's TEST or REF), by
// name or through a hard link or symlink, or two outputs naming one file, destroyed the input with
// exit status 0; now refused with one line and exit status 2 before any work, the input intact
// and no output written; the intermediate images of --save-every-pow2 are outputs too, and
// convert refuses inputs inside the folders it writes. An
// interrupted --frames run left its finished frames as temporaries; now it leaves none.
#include "util/output_identity.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/error.h"

extern char** environ;

namespace rc {
namespace {

std::string bytes_of(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// The Cornell box (its scene file and meshes) copied into a fresh scratch folder.
std::filesystem::path cornell_copy(const std::string& name) {
    const auto dir = test::scratch_dir(name);
    const auto source = test::source_dir() / "scenes/cornell-box";
    std::filesystem::copy_file(source / "scene.json", dir / "scene.json");
    std::filesystem::copy(source / "meshes", dir / "meshes");
    return dir;
}

// `radcache render SCENE` with quick options and `extra`.
test::CommandResult quick_render(const std::filesystem::path& scene,
                                 const std::vector<std::string>& extra,
                                 const std::string& method = "normals") {
    std::vector<std::string> args = {"render", scene.string(), "--method", method,  "--width",
                                     "4",      "--height",     "4",        "--spp", "1",
                                     "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::run_radcache(args);
}

// Refused with exit status 2 and one line naming `option` and `file` and `why`; `input` byte-
// identical afterwards; none of `absent` created.
void expect_refused(const test::CommandResult& result, const std::string& option,
                    const std::string& file, const std::string& why,
                    const std::filesystem::path& input, const std::string& input_bytes,
                    const std::vector<std::filesystem::path>& absent = {}) {
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_NE(result.output.find(option + " " + file + ": "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(why), std::string::npos) << result.output;
    EXPECT_EQ(bytes_of(input), input_bytes) << input;
    for (const auto& path : absent) {
        EXPECT_FALSE(std::filesystem::exists(path)) << path;
    }
}

constexpr const char* kInput = "refusing to overwrite an input";
constexpr const char* kTwice = "refusing to write one file twice";

TEST(OutputIdentity, StatsNamingTheSceneOrAMeshIsRefused) {
    const auto dir = cornell_copy("identity_stats_scene");
    const auto scene = dir / "scene.json";
    const std::string scene_bytes = bytes_of(scene);
    const auto out = dir / "out.png";
    expect_refused(quick_render(scene, {"-o", out.string(), "--stats", scene.string()}), "--stats",
                   scene.string(), "is the run's scene file", scene, scene_bytes, {out});
    // The same file through "./meshes/.." is the same file.
    const std::string dotted = (dir / "meshes" / ".." / "scene.json").string();
    expect_refused(quick_render(scene, {"-o", out.string(), "--stats", dotted}), "--stats", dotted,
                   kInput, scene, scene_bytes, {out});
    const auto mesh = dir / "meshes/floor.obj";
    const std::string mesh_bytes = bytes_of(mesh);
    expect_refused(quick_render(scene, {"-o", out.string(), "--stats", mesh.string()}), "--stats",
                   mesh.string(), "is the run's mesh file", mesh, mesh_bytes, {out});
}

// The intermediate images of --save-every-pow2 (name.sppN.ext) are outputs like the others: one
// named by --stats, or a link to a mesh with an intermediate's name, is refused before any work.
TEST(OutputIdentity, IntermediateImagesAreCheckedLikeEveryOutput) {
    const auto dir = cornell_copy("identity_intermediates");
    const auto scene = dir / "scene.json";
    const auto out = dir / "p.exr";
    const auto stats = dir / "p.spp1.exr";
    expect_refused(
        quick_render(scene, {"-o", out.string(), "--save-every-pow2", "--stats", stats.string()},
                     "pt"),
        "--save-every-pow2", stats.string(), kTwice, scene, bytes_of(scene), {out, stats});
    const auto mesh = dir / "meshes/floor.obj";
    const std::string mesh_bytes = bytes_of(mesh);
    const auto alias = dir / "p.spp2.exr";
    std::filesystem::create_symlink(mesh, alias);
    expect_refused(quick_render(scene, {"-o", out.string(), "--save-every-pow2"}, "pt"),
                   "--save-every-pow2", alias.string(), kInput, mesh, mesh_bytes, {out});
}

TEST(OutputIdentity, HardLinkAndSymlinkAliasesOfTheSceneAreRefused) {
    const auto dir = cornell_copy("identity_alias");
    const auto scene = dir / "scene.json";
    const std::string scene_bytes = bytes_of(scene);
    // A hard link with an image's name, as -o.
    const auto hard = dir / "alias.png";
    std::filesystem::create_hard_link(scene, hard);
    expect_refused(quick_render(scene, {"-o", hard.string()}), "-o", hard.string(),
                   "is the run's scene file", scene, scene_bytes);
    // A symlink, as --stats.
    const auto soft = dir / "link.json";
    std::filesystem::create_symlink(scene, soft);
    const auto out = dir / "out.png";
    expect_refused(quick_render(scene, {"-o", out.string(), "--stats", soft.string()}), "--stats",
                   soft.string(), kInput, scene, scene_bytes, {out});
    EXPECT_TRUE(std::filesystem::is_symlink(soft));
    // A frame of a sequence that is a hard link to the scene.
    const auto frame = dir / "f0002.png";
    std::filesystem::create_hard_link(scene, frame);
    expect_refused(quick_render(scene, {"-o", (dir / "f####.png").string(), "--frames", "0:3"}),
                   "-o", frame.string(), "is the run's scene file", scene, scene_bytes,
                   {dir / "f0000.png", dir / "f0001.png", dir / "f0003.png"});
}

TEST(OutputIdentity, TheGltfFileIsRefusedAsAnOutput) {
    const auto dir = test::scratch_dir("identity_gltf");
    const auto gltf = dir / "scene.gltf";
    std::filesystem::copy_file(test::source_dir() / "tests/data/gltf/cornell-box.gltf", gltf);
    const std::string gltf_bytes = bytes_of(gltf);
    const auto out = dir / "out.png";
    expect_refused(quick_render(gltf, {"-o", out.string(), "--stats", gltf.string()}), "--stats",
                   gltf.string(), "is the run's scene file", gltf, gltf_bytes, {out});
    // convert IN OUT: OUT a symlink to IN.
    const auto link = dir / "out.json";
    std::filesystem::create_symlink(gltf, link);
    expect_refused(test::run_radcache({"convert", gltf.string(), link.string(), "-q"}), "OUT",
                   link.string(), kInput, gltf, gltf_bytes);
}

// convert writes OUT_meshes/N.obj: a file IN reads from inside that folder (here a pbrt include
// stored as out_meshes/0.obj) is refused before any work, untouched.
TEST(OutputIdentity, ConvertRefusesInputsInsideTheFoldersItWrites) {
    const auto dir = test::scratch_dir("identity_convert_folders");
    std::filesystem::create_directories(dir / "out_meshes");
    const auto include = dir / "out_meshes" / "0.obj";
    std::ofstream(include) << "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0]\n";
    const std::string include_bytes = bytes_of(include);
    const auto scene = dir / "scene.pbrt";
    std::ofstream(scene) << "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                            "LightSource \"point\" \"point3 from\" [0 0 -4]\n"
                            "Include \"out_meshes/0.obj\"\n";
    const test::CommandResult result =
        test::run_radcache({"convert", scene.string(), (dir / "out.json").string(), "-q"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_NE(result.output.find("out_meshes/0.obj, inside"), std::string::npos) << result.output;
    EXPECT_EQ(bytes_of(include), include_bytes);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

TEST(OutputIdentity, CacheAndGridOutputsNamingInputsAreRefused) {
    const auto dir = cornell_copy("identity_cache");
    const auto scene = dir / "scene.json";
    const std::string scene_bytes = bytes_of(scene);
    const auto out = dir / "out.png";
    const auto cache = dir / "records.bin";
    std::ofstream(cache, std::ios::binary) << "not a cache";
    const std::string cache_bytes = bytes_of(cache);
    expect_refused(
        quick_render(
            scene,
            {"-o", out.string(), "--cache-in", cache.string(), "--cache-out", cache.string()},
            "ic"),
        "--cache-out", cache.string(), "is the run's --cache-in file", cache, cache_bytes, {out});
    expect_refused(quick_render(scene, {"-o", out.string(), "--cache-out", scene.string()}, "ic"),
                   "--cache-out", scene.string(), kInput, scene, scene_bytes, {out});
    expect_refused(quick_render(scene, {"-o", out.string(), "--grid-out", scene.string()}, "ivg"),
                   "--grid-out", scene.string(), kInput, scene, scene_bytes, {out});
}

TEST(OutputIdentity, TwoOutputsOfOneRunNamingOneFileAreRefused) {
    const auto dir = cornell_copy("identity_twice");
    const auto scene = dir / "scene.json";
    const std::string scene_bytes = bytes_of(scene);
    const auto exr = dir / "x.exr";
    expect_refused(quick_render(scene, {"-o", exr.string(), "--stats", exr.string()}), "--stats",
                   exr.string(), "is also the output of -o", scene, scene_bytes, {exr});
    const auto stats = dir / "s.json";
    const auto out = dir / "out.png";
    expect_refused(
        quick_render(scene,
                     {"-o", out.string(), "--stats", stats.string(), "--cache-out", stats.string()},
                     "ic"),
        "--cache-out", stats.string(), "is also the output of --stats", scene, scene_bytes,
        {stats, out});
    // --stats naming a frame of -o's sequence.
    const auto frame = dir / "f0002.png";
    expect_refused(quick_render(scene, {"-o", (dir / "f####.png").string(), "--frames", "0:3",
                                        "--stats", frame.string()}),
                   "--stats", frame.string(), kTwice, scene, scene_bytes, {frame});
}

TEST(OutputIdentity, CompareOutputsNamingItsImagesAreRefused) {
    const auto dir = test::scratch_dir("identity_compare");
    const Image image(2, 2, 3);
    const auto a = dir / "a.exr";
    const auto b = dir / "b.exr";
    write_image(a, image);
    write_image(b, image);
    const std::string a_bytes = bytes_of(a);
    const std::string b_bytes = bytes_of(b);
    expect_refused(test::run_radcache({"compare", a.string(), b.string(), "--json", a.string()}),
                   "--json", a.string(), "is the run's TEST image", a, a_bytes);
    expect_refused(
        test::run_radcache({"compare", a.string(), b.string(), "--error-image", b.string()}),
        "--error-image", b.string(), "is the run's REF image", b, b_bytes);
    const auto both = dir / "both.exr";
    expect_refused(test::run_radcache({"compare", a.string(), b.string(), "--json", both.string(),
                                       "--error-image", both.string()}),
                   "--error-image", both.string(), kTwice, a, a_bytes, {both});
}

TEST(OutputIdentity, FrameFunctionsAgreeWithRunFiles) {
    RunFiles run;
    run.input("scene file", "scene.json");
    run.output_frames("-o", "f####.png", 0, 1 << 30);  // not expanded: a billion frames
    run.output("--stats", "f0000007.png");             // not a frame of the pattern (width 4)
    EXPECT_NO_THROW(run.check());
    run.output("--json", "f0007.png");
    EXPECT_THROW(run.check(), Error);
}

// Runs radcache with `args`, signals it with `signal` once a staged temporary (*.tmp-*) shows in
// `watched`, and returns its exit status as a shell reports it (128 + the signal's number).
int interrupted_run(const std::vector<std::string>& radcache_args,
                    const std::filesystem::path& watched, int signal) {
    std::vector<std::string> args = {test::radcache_executable().string()};
    args.insert(args.end(), radcache_args.begin(), radcache_args.end());
    std::vector<char*> argv;
    for (const std::string& arg : args) {
        argv.push_back(const_cast<char*>(arg.c_str()));
    }
    argv.push_back(nullptr);
    // The child starts with default signal actions whatever this process inherited.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (const int each : {SIGINT, SIGTERM, SIGHUP, SIGALRM}) {
        sigaddset(&defaults, each);
    }
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    // Its warnings (the scene has no animation) are no part of the test.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (spawned != 0) {
        return -1;
    }
    // Poll for the first staged file; give up if the run ends first.
    int status = 0;
    for (bool staged = false; !staged;) {
        if (::waitpid(pid, &status, WNOHANG) == pid) {
            ADD_FAILURE() << "the run ended before it was signalled";
            return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        }
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(watched, error)) {
            staged = staged || entry.path().filename().string().find(".tmp-") != std::string::npos;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ::kill(pid, signal);
    ::waitpid(pid, &status, 0);
    return WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                               : (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

// `radcache render` over many frames into `dir`, signalled once its first frame is staged.
int interrupted_render(const std::filesystem::path& dir, int signal) {
    return interrupted_run(
        {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "--frames",
         "0:99999", "-o", (dir / "f####.exr").string(), "--method", "normals", "--width", "4",
         "--height", "4", "-q"},
        dir, signal);
}

// Every file of `dir`, by name.
std::vector<std::string> files_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    return names;
}

TEST(OutputIdentity, InterruptedSequencesLeaveNoTemporaries) {
    // SIGALRM (`timeout -s ALRM`) left a finished frame's temporary file.
    for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGALRM}) {
        const auto dir = test::scratch_dir("identity_signal_" + std::to_string(signal));
        EXPECT_EQ(interrupted_render(dir, signal), 128 + signal);
        // The staged frames are removed: no temporary, and (all or nothing) no frame.
        EXPECT_EQ(files_in(dir), std::vector<std::string>{}) << "signal " << signal;
    }
}

// SIGTERM during convert left an empty OUT_meshes/ folder: the staged meshes were removed, the
// folder the run had made was not. A pbrt scene of 20 000 distinct triangles, so that convert
// is still writing their OBJ files when signalled.
TEST(OutputIdentity, AnInterruptedConvertLeavesNoFolder) {
    const auto dir = test::scratch_dir("identity_convert_signal");
    std::ofstream scene(dir / "big.pbrt");
    scene << "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
             "LightSource \"point\" \"point3 from\" [0 0 -4]\n";
    for (int i = 0; i < 20000; ++i) {
        scene << "Shape \"trianglemesh\" \"point3 P\" [" << i << " 0 0 " << i + 1 << " 0 0 " << i
              << " 1 0]\n";
    }
    scene.close();
    const int status =
        interrupted_run({"convert", (dir / "big.pbrt").string(), (dir / "out.json").string(), "-q"},
                        dir / "out_meshes", SIGTERM);
    EXPECT_EQ(status, 128 + SIGTERM);
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"big.pbrt"});
}

}  // namespace
}  // namespace rc
