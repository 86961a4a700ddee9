// Which glossy cache serves each material's specular lobe in a render by irradiance caching
// (`--method ic --glossy SPEC`, docs/irradiance-caching.md "Glossy lobes"): path tracing (`path`,
// irradiance caching's own), or a cache of the glossy-cache registry
// (methods/caching/glossy_caches.h: `rc`, radiance caching, DESIGN.md §6.4; `sdrc`, §6.5). SPEC is
// a comma-separated list of NAME=CACHE (the scene's material NAME) and at most one *=CACHE for the
// materials not named; a bare CACHE is *=CACHE. The materials no item names are path traced.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/material.h"

namespace rc {

// The name --glossy gives path tracing: the render pass traces the lobe (no cache).
inline constexpr const char* kGlossyPath = "path";

// A parsed --glossy SPEC.
struct GlossySpec {
    std::vector<std::pair<std::string, std::string>> named;  // (material, cache), in SPEC order
    std::string rest = kGlossyPath;                          // *=: the materials not named

    // Whether every material goes to `rest` (no material is named).
    bool uniform() const { return named.empty(); }
    // The caches (not path) SPEC names, in the glossy-cache registry's order.
    std::vector<std::string> caches() const;
};

// SPEC read (Error, exit status 2, naming the value: an item without a cache, an unknown cache, a
// material or * listed twice).
GlossySpec parse_glossy_spec(const std::string& text);
// SPEC written back, as parse_glossy_spec reads it: the named items in order, then "*=CACHE"
// (only "CACHE" when no material is named).
std::string glossy_spec_text(const GlossySpec& spec);
// Per material of `materials` (by index): the name of what serves its specular lobe ("path" or a
// cache). Error (exit status 2) naming a material SPEC names that the scene does not have.
std::vector<std::string> resolve_glossy_spec(const GlossySpec& spec,
                                             const std::vector<Material>& materials);

// What serves a material's specular lobe in a plan (the automatic method choice's).
enum class GlossyServer { kPath, kRc, kSdrc };

// "path", "rc", "sdrc".
const char* glossy_server_name(GlossyServer server);

// The --glossy SPEC of `--method ic` that serves material i of `materials` by servers[i]: the
// most frequent server as *=, the other materials by name (a uniform plan: that server's bare
// name). Error (exit status 1) when the sizes differ, or when a material whose server differs from
// the rest cannot be named (an empty name, one with ',' or '=', or one two materials share with
// different servers).
std::string glossy_spec_of(const std::vector<GlossyServer>& servers,
                           const std::vector<Material>& materials);

}  // namespace rc
