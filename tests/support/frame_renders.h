// Rendering frames through the command line and comparing them, as the temporal tests do.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "image/image.h"

namespace rc::test {

// Whether two images hold the same pixels, bit for bit.
bool same_pixels(const Image& a, const Image& b);

// dir/name####.exr for `frame`.
std::filesystem::path frame_file(const std::filesystem::path& dir, const std::string& name,
                                 int frame);

// `radcache render SCENE args -o dir/name####.exr --stats dir/name.json --quiet`, which must
// succeed (a failed expectation otherwise); its stats.
nlohmann::json render_frames(const std::filesystem::path& scene, const std::filesystem::path& dir,
                             const std::string& name, const std::vector<std::string>& args);

// The glossy records' statistics (frames[f].temporal.radiance) of a `--temporal` render of a scene
// that does not move, frames 0..last: frame 0 creates every record (at least one) and traces their
// rays; the later frames reuse them all, creating, recomputing and dropping none, tracing no
// record rays.
void expect_static_glossy_records(const nlohmann::json& stats, int last);

}  // namespace rc::test
