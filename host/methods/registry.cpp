#include "methods/registry.h"

#include <algorithm>
#include <set>

#include "util/error.h"
#include "util/text.h"

// One line per method: X(entry function), defined in the method's folder as
// `MethodEntry <entry>_entry();`. The order is --help's.
#define RC_METHODS(X)          \
    X(path_tracer_method)      \
    X(auto_method)             \
    X(irradiance_cache_method) \
    X(radiance_cache_method)   \
    X(sdrc_method)             \
    X(ivg_method)              \
    X(ivg_gather_method)       \
    X(decomposition_method)    \
    X(normals_method)

namespace rc {

#define RC_DECLARE_METHOD(entry) MethodEntry entry##_entry();
RC_METHODS(RC_DECLARE_METHOD)
#undef RC_DECLARE_METHOD

const std::vector<MethodEntry>& method_registry() {
#define RC_LIST_METHOD(entry) entry##_entry(),
    static const std::vector<MethodEntry> methods = {RC_METHODS(RC_LIST_METHOD)};
#undef RC_LIST_METHOD
    return methods;
}

std::string method_names() {
    std::string names;
    for (const MethodEntry& method : method_registry()) {
        names += (names.empty() ? "" : ", ") + method.name;
    }
    return names;
}

const MethodEntry& find_method(const std::string& name) {
    for (const MethodEntry& method : method_registry()) {
        if (method.name == name) {
            return method;
        }
    }
    throw Error(
        "--method: unknown method '" + excerpt(name) + "' (implemented: " + method_names() + ")",
        kExitUsage);
}

namespace {

// "ic, rc or sdrc": the methods that declare `option`.
std::string owners(const std::string& option, const std::string& last_joint) {
    std::vector<std::string> names;
    for (const MethodEntry& method : method_registry()) {
        for (const OptionSpec& spec : method.options) {
            if (spec.name == option) {
                names.push_back(method.name);
            }
        }
    }
    std::string list;
    for (size_t i = 0; i < names.size(); ++i) {
        list += (i == 0 ? "" : i + 1 == names.size() ? last_joint : ", ") + names[i];
    }
    return list;
}

}  // namespace

std::vector<OptionSpec> method_option_specs() {
    std::vector<OptionSpec> specs;
    std::set<std::string> seen;
    for (const MethodEntry& method : method_registry()) {
        for (const OptionSpec& spec : method.options) {
            if (seen.insert(spec.name).second) {
                specs.push_back(spec);
                specs.back().help = owners(spec.name, ", ") + ": " + spec.help;
            }
        }
    }
    return specs;
}

namespace {

bool declares(const MethodEntry& method, const std::string& option) {
    return std::any_of(method.options.begin(), method.options.end(),
                       [&](const OptionSpec& spec) { return spec.name == option; });
}

}  // namespace

void refuse_foreign_options(const MethodEntry& method, const ParsedArguments& arguments) {
    for (const OptionSpec& spec : method_option_specs()) {
        if (!arguments.has(spec.name) || declares(method, spec.name)) {
            continue;
        }
        throw Error(spec.name + " applies to --method " + owners(spec.name, " or ") + " only",
                    kExitUsage);
    }
}

void check_layers(const MethodEntry& method, const std::vector<std::string>& layers) {
    for (const std::string& layer : layers) {
        if (std::find(method.aovs.begin(), method.aovs.end(), layer) == method.aovs.end()) {
            throw Error("--aovs: method " + method.name + " has no layer '" + layer + "'",
                        kExitUsage);
        }
    }
}

}  // namespace rc
