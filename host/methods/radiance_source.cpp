#include "methods/radiance_source.h"

namespace rc {

Kernel& source_kernel(Context& context, std::map<std::string, Kernel>* kernels,
                      const std::string& entry, const std::string& name,
                      const RadianceSource& source) {
    const std::string options = source.build_options();
    const std::string key = name + " " + options;
    auto found = kernels->find(key);
    if (found == kernels->end()) {
        found = kernels->emplace(key, context.kernel(entry, name, options)).first;
    }
    return found->second;
}

}  // namespace rc
