// `radcache convert IN OUT.json`: reads a glTF 2.0 or pbrt-v4 scene and writes it in
// radcache's scene format (scene/scene_writer.h), so that the user can edit it; rendering OUT.json
// gives the image of rendering IN.
#include <algorithm>
#include <system_error>

#include "app/commands.h"
#include "app/recorded_files.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"
#include "util/new_folders.h"

namespace rc {
namespace {

// Error (exit status 2) before any work when a mesh or texture folder's path is taken by what is
// not a folder.
void check_folders(const std::vector<std::filesystem::path>& folders) {
    for (const std::filesystem::path& folder : folders) {
        std::error_code error;
        const std::filesystem::file_status status = std::filesystem::status(folder, error);
        if (std::filesystem::exists(status) && !std::filesystem::is_directory(status)) {
            throw Error("convert: OUT's folder " + folder.string() + " exists and is not a folder",
                        kExitUsage);
        }
    }
}

// Error (exit status 2) before any work when IN read a file inside a folder convert writes
// (a glTF buffer or a pbrt include stored as OUT_meshes/0.obj would be overwritten).
void refuse_inputs_in(const std::vector<std::filesystem::path>& inputs,
                      const std::vector<std::filesystem::path>& folders) {
    for (const std::filesystem::path& folder : folders) {
        std::error_code error;
        const std::filesystem::path base = std::filesystem::weakly_canonical(folder, error);
        for (const std::filesystem::path& input : inputs) {
            const std::filesystem::path file = std::filesystem::weakly_canonical(input, error);
            const auto [end, _] = std::mismatch(base.begin(), base.end(), file.begin(), file.end());
            if (!error && end == base.end()) {
                throw Error("convert: IN reads " + input.string() + ", inside " + folder.string() +
                                ", which convert writes: choose another OUT",
                            kExitUsage);
            }
        }
    }
}

int convert(const ParsedArguments& arguments) {
    if (arguments.positionals().size() != 2) {
        throw Error("radcache convert needs IN and OUT.json (see radcache convert --help)",
                    kExitUsage);
    }
    set_quiet(arguments.has("--quiet"));
    const std::filesystem::path in = arguments.positionals()[0];
    if (!is_imported_scene_path(in)) {
        throw Error("convert: IN " + in.string() + ": expected a .gltf, .glb or .pbrt file",
                    kExitUsage);
    }
    const std::filesystem::path out = arguments.positionals()[1];
    if (out.extension() != ".json") {
        throw Error("convert: OUT " + out.string() + ": expected a .json file name", kExitUsage);
    }
    check_writable_parent(out, "OUT");
    const std::vector<std::filesystem::path> folders = {
        out.parent_path() / (out.stem().string() + "_meshes"),
        out.parent_path() / (out.stem().string() + "_textures")};
    check_folders(folders);
    const RecordedFiles read;  // OUT may be none of the files IN read
    const Scene scene = load_scene(in, read, arguments.value("--camera"));
    refuse_inputs_in(read.paths(), folders);
    RunFiles run;
    run.input("IN scene", in);
    read.add_inputs_to(run);
    run.output("OUT", out);
    run.check();
    // All or nothing: every file staged and renamed at the commit; on failure (a full disk, a
    // limit of the format) the staged files go, and so do the folders this run made.
    NewFolders new_folders(folders);
    OutputBatch batch;
    write_scene(scene, out);
    batch.commit();
    new_folders.keep();
    log_note("wrote " + out.string() + " (" + std::to_string(scene.shapes.size()) + " shapes, " +
             std::to_string(scene.materials.size()) + " materials)");
    return 0;
}

}  // namespace

CommandSpec convert_command() {
    return {.name = "convert",
            .synopsis = "convert IN OUT.json",
            .summary = "a glTF or pbrt-v4 scene in radcache's scene format",
            .description =
                "Writes the glTF 2.0 scene IN (.gltf or .glb) or the pbrt-v4 scene "
                "IN (.pbrt) in radcache's scene format: OUT.json, its meshes as "
                "OBJ files in OUT_meshes/ and embedded textures in OUT_textures/.",
            .options = {{"--camera", "", "NAME",
                         "glTF scenes: the camera of that name (default: the first)"},
                        {"--quiet", "-q", "", "print nothing but errors"}},
            .run = convert};
}

}  // namespace rc
