// The files one run reads and writes, checked before any work: no output may be one of the run's
// inputs (the scene, a mesh, a cache it reads) or another of its outputs. Two paths are one file
// when they name the same file (same device and inode: hard links, symlinks, "./a/../a") or,
// where either does not exist, when their lexically normal absolute paths (symlinked folders
// resolved) are equal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rc {

// The output name of a frame: the first run of '#' replaced by the zero-padded frame number.
std::filesystem::path frame_path(const std::string& pattern, int frame);

class RunFiles {
   public:
    // A file the run reads: `what` says what it is ("scene file", "mesh file", "--cache-in").
    void input(const std::string& what, const std::filesystem::path& path);
    // A file the run writes, given by `option` ("--stats", "-o").
    void output(const std::string& option, const std::filesystem::path& path);
    // The frames first..last the run writes by `option`'s `pattern`: its first run of '#' is the
    // zero-padded frame number (frame_path).
    void output_frames(const std::string& option, const std::string& pattern, int first, int last);

    // Error (exit status 2) for the first output that is an input or an earlier output, one line
    // naming both: "--stats scenes/x/scene.json: is the run's scene file; refusing to overwrite
    // an input".
    void check() const;

   private:
    struct File {
        std::string role;  // what an input is; the option of an output
        std::filesystem::path path;
    };
    struct Frames {
        std::string option;
        std::string pattern;
        int first = 0;
        int last = 0;
    };
    std::vector<File> inputs_;
    std::vector<File> outputs_;
    std::vector<Frames> frames_;
};

}  // namespace rc
