// Whole-file reads and all-or-nothing writes.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace rc {

// The file's bytes; throws Error naming the file when it cannot be read.
std::string read_file(const std::filesystem::path& path);

// Writes `bytes` to a temporary file beside `path` and renames it over `path`, so readers never
// see a partial file. Throws Error naming the file on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Runs `write(temporary)` and renames the temporary file over `path`; removes it on failure.
void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write);

// Error (exit status 2) "<option> <file>: directory '<dir>' does not exist or is not writable"
// unless `file` could be created: checked before any work is done.
void check_writable_parent(const std::filesystem::path& file, const std::string& option);

// A temporary path in the same directory as `path` (same file system, so rename is atomic),
// with the same extension.
std::filesystem::path temporary_sibling(const std::filesystem::path& path);

}  // namespace rc
