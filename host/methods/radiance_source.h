// Where a caching method's hemisphere rays read "the radiance beyond the first bounce" (DESIGN.md
// §2; kernels/caching/radiance_source.h): chosen when the method sets up the rays' kernel, whose
// program is built with the source's definitions and whose source parameters the source binds
// (KernelArgumentGroup::set_kernel_args). Implemented by path-traced continuation (here), the
// irradiance vector grid and a deeper irradiance-cache level, each in its method's folder.
#pragma once

#include <map>
#include <string>

#include "device/context.h"
#include "device/kernel.h"
#include "shared/radiance_sources.h"

namespace rc {

class RadianceSource : public KernelArgumentGroup {
   public:
    // The program build options that select the source's device code (-DRC_RADIANCE_SOURCE=...).
    virtual std::string build_options() const = 0;
    // The source's name, for statistics and messages.
    virtual std::string source_name() const = 0;
};

// The -D definition selecting source `kind` (RC_RADIANCE_PATH, _RECORDS, _GRID).
inline std::string radiance_source_define(int kind) {
    return "-DRC_RADIANCE_SOURCE=" + std::to_string(kind);
}

// The kernel `name` of program `entry` (relative to kernels/) built with `source`'s definitions:
// built at its first use with each kind of source and kept in *kernels (by name and options).
Kernel& source_kernel(Context& context, std::map<std::string, Kernel>* kernels,
                      const std::string& entry, const std::string& name,
                      const RadianceSource& source);

// Path-traced continuation: nothing to bind.
class PathContinuation final : public RadianceSource {
   public:
    std::string build_options() const override { return radiance_source_define(RC_RADIANCE_PATH); }
    std::string source_name() const override { return "path tracing"; }
    unsigned set_kernel_args(Kernel&, unsigned) const override { return 0; }
};

}  // namespace rc
