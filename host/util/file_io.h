// Whole-file reads with size limits, and all-or-nothing writes: one file at a time, or every
// output of a run together (OutputBatch).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <system_error>

namespace rc {

// The largest file read_file accepts unless told otherwise.
inline constexpr uint64_t kDefaultMaxFileBytes = uint64_t{4} << 30;

// The file's bytes. Only a regular file of at most `max_bytes` bytes is read (so /dev/zero, a
// FIFO or a directory is refused before any allocation); throws Error naming the file (and
// `what` it is, when given: "mesh file") otherwise or when it cannot be read.
std::string read_file(const std::filesystem::path& path, uint64_t max_bytes = kDefaultMaxFileBytes,
                      const std::string& what = "");

// When a write reaches its path: with the open OutputBatch (if any), or at once (caches).
enum class WriteTiming { kWithBatch, kNow };

// Writes `bytes` to a temporary file beside `path` and renames it over `path`, so readers never
// see a partial file. Throws Error naming the file on failure. While an OutputBatch is open the
// rename waits for its commit (unless `timing` is kNow).
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           WriteTiming timing = WriteTiming::kWithBatch);

// Runs `write(temporary)` and renames the temporary file over `path`; removes it on failure.
// While an OutputBatch is open the rename waits for its commit (unless `timing` is kNow).
void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write,
                             WriteTiming timing = WriteTiming::kWithBatch);

// The outputs of one run, committed together: while a batch is open, every file
// written with WriteTiming::kWithBatch goes to a temporary beside its path, and commit() renames
// them all over their paths, in the order written. A batch destroyed without commit() removes its
// temporaries, so a run that fails anywhere leaves no new file and every old one intact. One batch
// is open at a time in a process; a second path written twice keeps the last content.
class OutputBatch {
   public:
    OutputBatch();
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;

    // Renames every staged file over its path; Error naming the first that cannot be renamed
    // (the later ones are removed).
    void commit();
};

// A folder the run made for its outputs (util/new_folders.h): removed, when empty, by a signal
// that ends the run (util/interrupt_cleanup.h), after the staged files; forgotten when the run
// keeps it or removes it itself.
void note_new_folder(const std::filesystem::path& folder);
// Makes `folder` (and its parents) for outputs; what create_directories reports in `error`.
void create_output_folder(const std::filesystem::path& folder, std::error_code& error);
void forget_new_folder(const std::filesystem::path& folder);

// Error (exit status 2) "<option> <file>: ..." unless `file` could be written: its directory
// exists and is writable, and the path is not a directory or another non-regular file. Checked
// before any work is done.
void check_writable_parent(const std::filesystem::path& file, const std::string& option);

// A temporary path in the same directory as `path` (same file system, so rename is atomic),
// with the same extension.
std::filesystem::path temporary_sibling(const std::filesystem::path& path);

}  // namespace rc
