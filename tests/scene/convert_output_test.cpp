// `radcache convert`'s outputs: all or nothing on a full disk (no partial OUT_meshes/ folder, old
// outputs intact), instancing kept as instancing (shapes of one mesh share one OBJ file), the
// scene format's limits applied to what it writes (render would refuse it), and a folder that
// cannot be made named in one line instead of the library's `filesystem error` text.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::filesystem::path hierarchy_gltf() {
    return test::source_dir() / "tests" / "data" / "gltf" / "hierarchy.gltf";
}

// Every path under `dir` with its bytes, to compare a folder before and after a run.
std::map<std::string, std::string> tree(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        const std::string name = std::filesystem::relative(entry.path(), dir).string();
        files[name] = entry.is_regular_file() ? read_file(entry.path()) : "<folder>";
    }
    return files;
}

// `output` ends with its one error line, which names `names` (hierarchy.gltf's warning that
// glTF's spot cone falloff is not supported comes before it when the scene is read).
void expect_one_error_line(const std::string& output, const std::string& names) {
    const size_t error = output.find("radcache: error: ");
    ASSERT_NE(error, std::string::npos) << output;
    EXPECT_TRUE(error == 0 || output[error - 1] == '\n') << output;
    EXPECT_EQ(output.find('\n', error), output.size() - 1) << output;
    EXPECT_EQ(output.find("radcache: error: ", error + 1), std::string::npos) << output;
    EXPECT_NE(output.find(names, error), std::string::npos) << output;
    EXPECT_EQ(output.find("filesystem error"), std::string::npos) << output;
}

// A full disk, simulated by a file-size limit (`ulimit -f`, SIGXFSZ ignored so that the write
// fails with EFBIG as on ENOSPC): the conversion fails in one line, and the folder holds what it
// held before, old outputs included, without a partial OUT_meshes/ or a temporary.
TEST(ConvertOutput, AFullDiskLeavesNoPartialOutput) {
    for (const bool old_outputs : {false, true}) {
        const auto dir = test::scratch_dir(old_outputs ? "convert_full_old" : "convert_full");
        if (old_outputs) {
            std::ofstream(dir / "x.json") << "old scene\n";
            std::filesystem::create_directory(dir / "x_meshes");
            std::ofstream(dir / "x_meshes" / "0.obj") << "old mesh\n";
        }
        const auto before = tree(dir);
        const std::filesystem::path log = dir.parent_path() / (dir.filename().string() + ".log");
        // 2 blocks (1 KiB or 2 KiB): the meshes fit, the scene file does not.
        const std::string command = "trap '' XFSZ; ulimit -f 2; exec '" +
                                    test::radcache_executable().string() + "' convert '" +
                                    hierarchy_gltf().string() + "' '" + (dir / "x.json").string() +
                                    "' -q > '" + log.string() + "' 2>&1";
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << status;
        EXPECT_EQ(WEXITSTATUS(status), 1);
        expect_one_error_line(read_file(log), (dir / "x.json").string());
        EXPECT_EQ(tree(dir), before);
    }
}

// Every node of one mesh names the same OBJ file: three more instances of mesh 0 add three
// shapes and no mesh file.
TEST(ConvertOutput, InstancesShareOneMeshFile) {
    const auto dir = test::scratch_dir("convert_instances");
    nlohmann::json model = nlohmann::json::parse(read_file(hierarchy_gltf()));
    const auto convert = [&](const std::string& name) {
        std::ofstream(dir / (name + ".gltf")) << model.dump();
        const test::CommandResult result =
            test::run_radcache({"convert", (dir / (name + ".gltf")).string(),
                                (dir / (name + ".json")).string(), "-q"});
        EXPECT_EQ(result.exit_code, 0) << result.output;
        return nlohmann::json::parse(read_file(dir / (name + ".json")));
    };
    const nlohmann::json plain = convert("plain");
    for (int copy = 0; copy < 3; ++copy) {
        model["nodes"].push_back({{"mesh", 0}, {"translation", {copy + 2.0, 0.0, 0.0}}});
        model["scenes"][0]["nodes"].push_back(model["nodes"].size() - 1);
    }
    const nlohmann::json copies = convert("copies");
    const auto files = [](const nlohmann::json& scene) {
        std::set<std::string> names;
        for (const nlohmann::json& shape : scene["shapes"]) {
            names.insert(shape["file"].get<std::string>());
        }
        return names.size();
    };
    const size_t mesh_files = static_cast<size_t>(
        std::distance(std::filesystem::directory_iterator(dir / "copies_meshes"), {}));
    EXPECT_EQ(files(copies), files(plain));
    EXPECT_EQ(mesh_files, files(plain));
    EXPECT_GT(copies["shapes"].size(), plain["shapes"].size() + 2);
}

// What render would refuse is refused when written: a name over the string limit, a scene file
// over 64 MiB (200 000 instances of one mesh); one line, exit 1, nothing written.
TEST(ConvertOutput, TheSceneLimitsApplyToWhatItWrites) {
    const auto dir = test::scratch_dir("convert_limits");
    nlohmann::json long_name = nlohmann::json::parse(read_file(hierarchy_gltf()));
    long_name["nodes"][0]["name"] = std::string(5000, 'n');
    nlohmann::json many = nlohmann::json::parse(read_file(hierarchy_gltf()));
    for (int copy = 0; copy < 200000; ++copy) {
        many["nodes"].push_back({{"mesh", 0}});
        many["scenes"][0]["nodes"].push_back(many["nodes"].size() - 1);
    }
    for (const auto& [name, model, names] :
         {std::tuple<std::string, nlohmann::json, std::string>{"long_name", long_name,
                                                               "more than the scene format's "
                                                               "limit of 4096"},
          std::tuple<std::string, nlohmann::json, std::string>{
              "many", many, "more than the 64 MiB a scene file may hold"}}) {
        std::ofstream(dir / (name + ".gltf")) << model.dump();
        const auto out = dir / "out";
        std::filesystem::create_directories(out);
        const test::CommandResult result = test::run_radcache(
            {"convert", (dir / (name + ".gltf")).string(), (out / "x.json").string(), "-q"});
        EXPECT_EQ(result.exit_code, 1) << name;
        expect_one_error_line(result.output, names);
        EXPECT_TRUE(std::filesystem::is_empty(out)) << name;
    }
}

// OUT under a file, or OUT's mesh folder taken by a file: one line naming the path, exit 2.
TEST(ConvertOutput, FoldersThatCannotBeMadeAreOneLine) {
    const auto dir = test::scratch_dir("convert_folders");
    std::ofstream(dir / "file") << "a file\n";
    std::ofstream(dir / "y_meshes") << "a file\n";
    for (const auto& [out, names] :
         {std::pair<std::string, std::string>{(dir / "file" / "x.json").string(), "file"},
          std::pair<std::string, std::string>{(dir / "y.json").string(), "y_meshes"}}) {
        const auto before = tree(dir);
        const test::CommandResult result =
            test::run_radcache({"convert", hierarchy_gltf().string(), out, "-q"});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        expect_one_error_line(result.output, names);
        EXPECT_EQ(tree(dir), before);
    }
}

}  // namespace
}  // namespace rc
