// Files of a test's scratch folder: writing one as it is, listing what a command left there.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rc::test {

// Writes `bytes` to `path` (binary, replacing it); returns `path`.
std::filesystem::path write_file(const std::filesystem::path& path, const std::string& bytes);

// The names of the entries of `dir`, sorted.
std::vector<std::string> file_names(const std::filesystem::path& dir);

}  // namespace rc::test
