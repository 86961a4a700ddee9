#include "methods/caching/glossy_spec.h"

#include <algorithm>
#include <map>

#include "methods/caching/glossy_caches.h"
#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

[[noreturn]] void refuse(const std::string& what) { throw Error("--glossy: " + what, kExitUsage); }

// `name` when it is path or a registered glossy cache; else Error naming it.
std::string checked_cache(const std::string& name, const std::string& item) {
    if (name == kGlossyPath || find_glossy_cache(name) != nullptr) {
        return name;
    }
    refuse("unknown cache '" + excerpt(name) + "' in '" + excerpt(item) + "' (expected " +
           kGlossyPath + ", " + glossy_cache_names() + ")");
}

std::vector<std::string> split_items(const std::string& text) {
    std::vector<std::string> items;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        items.push_back(text.substr(start, comma - start));
        if (comma == std::string::npos) {
            return items;
        }
        start = comma + 1;
    }
}

}  // namespace

std::vector<std::string> GlossySpec::caches() const {
    std::vector<std::string> used;
    for (const GlossyCacheEntry& entry : glossy_cache_registry()) {
        const bool listed = std::any_of(named.begin(), named.end(), [&](const auto& item) {
            return item.second == entry.name;
        });
        if (rest == entry.name || listed) {
            used.push_back(entry.name);
        }
    }
    return used;
}

GlossySpec parse_glossy_spec(const std::string& text) {
    GlossySpec spec;
    bool rest_given = false;
    for (const std::string& item : split_items(text)) {
        const size_t equals = item.find('=');
        const std::string name = equals == std::string::npos ? "*" : item.substr(0, equals);
        const std::string cache = item.substr(equals == std::string::npos ? 0 : equals + 1);
        if (name.empty() || cache.empty()) {
            refuse("expected CACHE, NAME=CACHE or *=CACHE, got '" + excerpt(item) + "' in '" +
                   excerpt(text) + "'");
        }
        if (name == "*") {
            if (rest_given) {
                refuse("the rest (*) is given twice in '" + excerpt(text) + "'");
            }
            spec.rest = checked_cache(cache, item);
            rest_given = true;
            continue;
        }
        for (const auto& earlier : spec.named) {
            if (earlier.first == name) {
                refuse("material '" + excerpt(name) + "' is listed twice in '" + excerpt(text) +
                       "'");
            }
        }
        spec.named.emplace_back(name, checked_cache(cache, item));
    }
    return spec;
}

std::string glossy_spec_text(const GlossySpec& spec) {
    if (spec.uniform()) {
        return spec.rest;
    }
    std::string text;
    for (const auto& [name, cache] : spec.named) {
        text += name + "=" + cache + ",";
    }
    return text + "*=" + spec.rest;
}

std::vector<std::string> resolve_glossy_spec(const GlossySpec& spec,
                                             const std::vector<Material>& materials) {
    std::vector<std::string> servers(materials.size(), spec.rest);
    for (const auto& [name, cache] : spec.named) {
        bool found = false;
        for (size_t m = 0; m < materials.size(); ++m) {
            if (materials[m].name == name) {
                servers[m] = cache;
                found = true;
            }
        }
        if (!found) {
            std::string known;
            for (const Material& material : materials) {
                known += (known.empty() ? "" : ", ") + material.name;
            }
            refuse("the scene has no material '" + excerpt(name) + "' (it has " + excerpt(known) +
                   ")");
        }
    }
    return servers;
}

const char* glossy_server_name(GlossyServer server) {
    switch (server) {
        case GlossyServer::kRc:
            return "rc";
        case GlossyServer::kSdrc:
            return "sdrc";
        default:
            return kGlossyPath;
    }
}

std::string glossy_spec_of(const std::vector<GlossyServer>& servers,
                           const std::vector<Material>& materials) {
    if (servers.size() != materials.size()) {
        throw Error("glossy_spec_of: " + std::to_string(servers.size()) + " servers for " +
                    std::to_string(materials.size()) + " materials");
    }
    // The most frequent server is the rest (ties: the first in enum order).
    std::map<GlossyServer, size_t> counts;
    for (GlossyServer server : servers) {
        ++counts[server];
    }
    GlossySpec spec;
    GlossyServer rest = GlossyServer::kPath;
    size_t most = 0;
    for (const auto& [server, count] : counts) {
        if (count > most) {
            rest = server;
            most = count;
        }
    }
    spec.rest = glossy_server_name(rest);
    std::map<std::string, GlossyServer> named;
    for (size_t m = 0; m < servers.size(); ++m) {
        const std::string& name = materials[m].name;
        const bool nameable =
            !name.empty() && name != "*" && name.find_first_of(",=") == std::string::npos;
        const auto same = [&](size_t k) { return materials[k].name == name; };
        bool shared_differently = false;
        for (size_t k = 0; k < servers.size(); ++k) {
            shared_differently = shared_differently || (same(k) && servers[k] != servers[m]);
        }
        if (servers[m] == rest && !shared_differently) {
            continue;
        }
        if (!nameable || shared_differently) {
            throw Error("glossy_spec_of: material " + std::to_string(m) + " '" + excerpt(name) +
                        "' cannot be named in --glossy");
        }
        if (named.emplace(name, servers[m]).second) {
            spec.named.emplace_back(name, glossy_server_name(servers[m]));
        }
    }
    return glossy_spec_text(spec);
}

}  // namespace rc
