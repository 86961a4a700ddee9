// The OpenCL device the tests run on: $RADCACHE_TEST_DEVICE, what --device takes ("P:D" or part
// of a device's name: "llvmpipe" for Mesa's rusticl with RUSTICL_ENABLE=llvmpipe), else radcache's
// own rule ($RADCACHE_DEVICE, the first GPU, the first CPU). The test contexts
// (default_context_options) and the renders through the command line (run_radcache) take it, and
// render there even where it ends loops early ($RADCACHE_ALLOW_LOOP_CAP=1: the tests' bounds
// judge the results).
// Where it names no device here, every test of the program is skipped with a message naming the
// spec and the devices there are: an implementation that is not installed fails nothing.
#pragma once

#include <string>

namespace rc::test {

// $RADCACHE_TEST_DEVICE, or empty where it is unset or empty.
std::string test_device_spec();

}  // namespace rc::test
