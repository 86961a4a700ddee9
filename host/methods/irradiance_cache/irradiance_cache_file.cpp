#include "methods/irradiance_cache/irradiance_cache_file.h"

#include <OpenImageIO/hash.h>

#include <algorithm>
#include <cstring>

#include "scene/scene_fingerprint.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

constexpr char kMagic[8] = {'R', 'C', 'I', 'R', 'C', 'A', 'C', 'H'};
constexpr uint32_t kVersion = 1;
constexpr size_t kFloatsPerRecord = 35;

struct Header {
    char magic[8];
    uint32_t version;
    uint32_t record_bytes;
    uint64_t scene;
    float accuracy;
    uint32_t levels;
    uint64_t count;
};
static_assert(sizeof(Header) == 40);

constexpr uint32_t kMaxLevels = 64;

uint64_t checksum(const std::string& bytes) {
    return OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size());
}

void put_vec3(float*& out, glm::vec3 v) {
    *out++ = v.x;
    *out++ = v.y;
    *out++ = v.z;
}

glm::vec3 get_vec3(const float*& in) {
    glm::vec3 v(in[0], in[1], in[2]);
    in += 3;
    return v;
}

}  // namespace

void write_irradiance_cache(const std::filesystem::path& path, const Scene& scene,
                            const std::vector<RecordStore>& levels) {
    Header header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kVersion;
    header.record_bytes = static_cast<uint32_t>(kFloatsPerRecord * sizeof(float));
    header.scene = scene_fingerprint(scene);
    header.accuracy = levels.empty() ? 0.0f : levels[0].accuracy();
    header.levels = static_cast<uint32_t>(levels.size());
    std::vector<uint64_t> counts;
    std::vector<float> floats;
    for (const RecordStore& store : levels) {
        counts.push_back(store.size());
        header.count += store.size();
        for (const CacheRecord& r : store.records()) {
            const size_t at = floats.size();
            floats.resize(at + kFloatsPerRecord);
            float* out = floats.data() + at;
            put_vec3(out, r.position);
            put_vec3(out, r.normal);
            put_vec3(out, r.irradiance);
            for (const glm::vec3& g : r.rotation) {
                put_vec3(out, g);
            }
            for (const glm::vec3& g : r.translation) {
                put_vec3(out, g);
            }
            *out++ = r.harmonic_distance;
            *out++ = r.min_distance;
            *out++ = r.r_min;
            *out++ = r.r_max;
            *out++ = r.radius;
            put_vec3(out, r.occluder);
        }
    }
    std::string bytes;
    bytes.append(reinterpret_cast<const char*>(&header), sizeof header);
    bytes.append(reinterpret_cast<const char*>(counts.data()), counts.size() * sizeof(uint64_t));
    bytes.append(reinterpret_cast<const char*>(floats.data()), floats.size() * sizeof(float));
    const uint64_t sum = checksum(bytes);
    bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
    write_file_atomically(path, bytes);
}

std::vector<std::vector<CacheRecord>> read_irradiance_cache(const std::filesystem::path& path,
                                                            const Scene& scene, float accuracy) {
    const std::string name = path.string();
    if (!std::filesystem::is_regular_file(path)) {
        throw Error(name + ": irradiance cache file not found");
    }
    const std::string bytes = read_file(path);
    Header header;
    if (bytes.size() < sizeof header + sizeof(uint64_t) ||
        std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
        throw Error(name + ": not a radcache irradiance cache file");
    }
    std::memcpy(&header, bytes.data(), sizeof header);
    if (header.version != kVersion) {
        throw Error(name + ": irradiance cache version " + std::to_string(header.version) +
                    "; this radcache reads version " + std::to_string(kVersion));
    }
    constexpr size_t kRecordBytes = kFloatsPerRecord * sizeof(float);
    const size_t fixed = sizeof header + sizeof(uint64_t);
    const bool sizes_fit =
        header.levels <= kMaxLevels && header.count <= (bytes.size() - fixed) / kRecordBytes &&
        bytes.size() == fixed + header.levels * sizeof(uint64_t) + header.count * kRecordBytes;
    if (header.record_bytes != kRecordBytes || !sizes_fit) {
        throw Error(name + ": corrupt irradiance cache (" + std::to_string(bytes.size()) +
                    " bytes do not match its header)");
    }
    uint64_t stored_sum;
    std::memcpy(&stored_sum, bytes.data() + bytes.size() - sizeof stored_sum, sizeof stored_sum);
    if (checksum(bytes.substr(0, bytes.size() - sizeof stored_sum)) != stored_sum) {
        throw Error(name + ": corrupt irradiance cache (checksum mismatch)");
    }
    std::vector<uint64_t> counts(header.levels);
    std::memcpy(counts.data(), bytes.data() + sizeof header, counts.size() * sizeof(uint64_t));
    uint64_t total = 0;
    for (uint64_t c : counts) {
        total += std::min<uint64_t>(c, header.count + 1);
    }
    if (total != header.count) {
        throw Error(name + ": corrupt irradiance cache (level counts do not add up)");
    }
    if (header.scene != scene_fingerprint(scene)) {
        throw Error(name +
                    ": irradiance cache was made for another scene (or another frame of "
                    "it) than " +
                    scene.path.string());
    }
    if (header.accuracy != accuracy) {
        throw Error(name + ": irradiance cache was made with accuracy " +
                    std::to_string(header.accuracy) + ", not " + std::to_string(accuracy));
    }
    std::vector<float> floats(header.count * kFloatsPerRecord);
    std::memcpy(floats.data(), bytes.data() + sizeof header + counts.size() * sizeof(uint64_t),
                floats.size() * sizeof(float));
    std::vector<std::vector<CacheRecord>> levels(header.levels);
    const float* in = floats.data();
    for (size_t level = 0; level < levels.size(); ++level) {
        levels[level].resize(counts[level]);
        for (CacheRecord& r : levels[level]) {
            r.position = get_vec3(in);
            r.normal = get_vec3(in);
            r.irradiance = get_vec3(in);
            for (glm::vec3& g : r.rotation) {
                g = get_vec3(in);
            }
            for (glm::vec3& g : r.translation) {
                g = get_vec3(in);
            }
            r.harmonic_distance = *in++;
            r.min_distance = *in++;
            r.r_min = *in++;
            r.r_max = *in++;
            r.radius = *in++;
            r.occluder = get_vec3(in);
        }
    }
    return levels;
}

}  // namespace rc
