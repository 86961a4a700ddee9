// The libFuzzer entry of one target, chosen at build time (RC_FUZZ_TARGET,
// tests/fuzz/CMakeLists.txt).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return rc::fuzz::RC_FUZZ_TARGET(data, size);
}
