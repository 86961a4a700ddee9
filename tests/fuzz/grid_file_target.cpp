// Fuzz target: an irradiance vector grid file (--grid-in). Its checksum is appended here, and the
// scene it must have been made for is the one its own header names.
#include <OpenImageIO/hash.h>

#include <cstring>

#include "fuzz_targets.h"
#include "methods/grid/irradiance_vector_grid_file.h"
#include "util/error.h"

namespace rc::fuzz {

int grid_file(const uint8_t* data, size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    const uint64_t sum = OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size());
    bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
    uint64_t scene = 0;  // the header's scene fingerprint, at 16 (irradiance_vector_grid_file.h)
    if (bytes.size() >= 24) {
        std::memcpy(&scene, bytes.data() + 16, sizeof scene);
    }
    try {
        parse_grid_file(bytes, "fuzz.rcg", scene, "the fuzzed scene");
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
