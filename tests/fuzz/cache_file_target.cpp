// Fuzz target: a record cache file (--cache-in, --rc-cache-in). Its checksum is appended here so
// that the fuzzer reaches what lies behind it, and the key it must match is taken from its own
// header (method tag, payload size, scene, accuracy); the records read are then put in a record
// grid, as a render would.
#include <OpenImageIO/hash.h>

#include <cstring>

#include "fuzz_targets.h"
#include "methods/caching/cache_file.h"
#include "methods/caching/record_grid.h"
#include "util/error.h"

namespace rc::fuzz {
namespace {

template <class T>
T field(const std::string& bytes, size_t offset) {
    T value{};
    if (offset + sizeof value <= bytes.size()) {
        std::memcpy(&value, bytes.data() + offset, sizeof value);
    }
    return value;
}

}  // namespace

int cache_file(const uint8_t* data, size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    const uint64_t sum = OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size());
    bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
    // The header's fields (cache_file.h): method tag at 16, payload bytes at 32, scene at 40,
    // accuracy at 48.
    CacheFileKey key;
    key.method = std::string(bytes.data() + std::min<size_t>(16, bytes.size()),
                             bytes.size() >= 32 ? strnlen(bytes.data() + 16, 15) : 0);
    key.payload_bytes = field<uint32_t>(bytes, 32) % 4096;
    key.scene = field<uint64_t>(bytes, 40);
    key.scene_name = "the fuzzed scene";
    key.accuracy = field<float>(bytes, 48);
    try {
        for (const RecordStore& level : parse_cache_file(bytes, "fuzz.rcc", key)) {
            build_record_grid(level.records(), key.accuracy, 1 << 16);
        }
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
