#include "methods/caching/cache_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/scene.h"
#include "util/error.h"
#include "util/file_checksum.h"
#include "util/file_io.h"

namespace rc {
namespace {

constexpr char kMagic[8] = {'R', 'C', 'I', 'R', 'C', 'A', 'C', 'H'};
constexpr uint32_t kVersion = 2;
constexpr size_t kRecordBytes = sizeof(shared::Record) + sizeof(RecordHostData);
constexpr uint32_t kMaxLevels = 64;

struct Header {
    char magic[8];
    uint32_t version;
    uint32_t record_bytes;
    char method[16];
    uint32_t payload_bytes;
    uint32_t levels;
    uint64_t scene;
    float accuracy;
    uint32_t reserved;
    uint64_t count;
};
static_assert(sizeof(Header) == 64);

template <class T>
void append(std::string& bytes, const T* values, size_t count) {
    bytes.append(reinterpret_cast<const char*>(values), count * sizeof(T));
}

std::string method_of(const Header& header) {
    return std::string(header.method, strnlen(header.method, sizeof header.method));
}

// The header after checks that need nothing but the file: magic, version, sizes, checksum.
Header checked_header(const std::string& name, const std::string& bytes, const CacheFileKey& key) {
    const std::string what = key.method + " cache";
    Header header;
    if (bytes.size() < sizeof header + sizeof(uint64_t) ||
        std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
        throw Error(name + ": not a radcache " + what + " file");
    }
    std::memcpy(&header, bytes.data(), sizeof header);
    if (header.version != kVersion) {
        throw Error(name + ": " + what + " version " + std::to_string(header.version) +
                    "; this radcache reads version " + std::to_string(kVersion));
    }
    const size_t fixed = sizeof header + sizeof(uint64_t);
    const size_t per_record = kRecordBytes + header.payload_bytes;
    // The accuracy a is in (0, 1] (--accuracy): influence radii a R stay within the world.
    const bool sizes_fit =
        header.record_bytes == kRecordBytes && header.levels <= kMaxLevels &&
        header.accuracy > 0.0f && header.accuracy <= 1.0f &&
        header.count <= (bytes.size() - fixed) / per_record &&
        bytes.size() == fixed + header.levels * sizeof(uint64_t) + header.count * per_record;
    if (!sizes_fit) {
        throw Error(name + ": corrupt " + what + " (" + std::to_string(bytes.size()) +
                    " bytes do not match its header)");
    }
    if (!has_valid_checksum(bytes)) {
        throw Error(name + ": corrupt " + what + " (checksum mismatch)");
    }
    return header;
}

// Refuses a sound file made for something else than `key`.
void check_key(const std::string& name, const Header& header, const CacheFileKey& key) {
    const std::string what = key.method + " cache";
    if (method_of(header) != key.method) {
        throw Error(name + ": holds " + method_of(header) + " records, not " + key.method +
                    " records");
    }
    if (header.payload_bytes != key.payload_bytes) {
        throw Error(name + ": " + what + " with " + std::to_string(header.payload_bytes) +
                    "-byte record payloads; this radcache's have " +
                    std::to_string(key.payload_bytes) + " bytes");
    }
    if (header.scene != key.scene) {
        throw Error(name + ": " + what +
                    " was made for another scene (or another frame of it) than " + key.scene_name);
    }
    if (header.accuracy != key.accuracy) {
        throw Error(name + ": " + what + " was made with accuracy " +
                    std::to_string(header.accuracy) + ", not " + std::to_string(key.accuracy));
    }
}

bool finite_in(float value, float min, float max) {
    return std::isfinite(value) && value >= min && value <= max;
}

// A record's values where they must lie (a file is untrusted input; its checksum
// guards against accidents only). Record positions lie in the scene's world range, normals are
// unit, radii positive; distances may be infinite (no hit); payloads are floats, all finite.
void check_record(const std::string& name, const CacheFileKey& key, uint64_t index,
                  const shared::Record& record, const RecordHostData& host,
                  const std::byte* payload) {
    const glm::vec3 p = record_position(record);
    const glm::vec3 n = record_normal(record);
    const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const bool distances = host.harmonic_distance >= 0.0f && host.min_distance >= 0.0f &&
                           host.radius > 0.0f;  // NaN fails each comparison
    bool sound = finite_in(p.x, -kMaxWorldCoordinate, kMaxWorldCoordinate) &&
                 finite_in(p.y, -kMaxWorldCoordinate, kMaxWorldCoordinate) &&
                 finite_in(p.z, -kMaxWorldCoordinate, kMaxWorldCoordinate) &&
                 finite_in(length, 0.99f, 1.01f) &&
                 finite_in(record.radius, 1e-30f, kMaxWorldCoordinate) &&
                 finite_in(host.r_min, 0.0f, kMaxWorldCoordinate) &&
                 finite_in(host.r_max, host.r_min, kMaxWorldCoordinate) && distances;
    for (size_t offset = 0; sound && offset + sizeof(float) <= key.payload_bytes;
         offset += sizeof(float)) {
        float value;
        std::memcpy(&value, payload + offset, sizeof value);
        sound = std::isfinite(value);
    }
    if (!sound) {
        throw Error(name + ": corrupt " + key.method + " cache (record " + std::to_string(index) +
                    " holds values out of range)");
    }
}

}  // namespace

void write_cache_file(const std::filesystem::path& path, const CacheFileKey& key,
                      const std::vector<RecordStore>& levels) {
    Header header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kVersion;
    header.record_bytes = static_cast<uint32_t>(kRecordBytes);
    if (key.method.size() >= sizeof header.method) {
        throw Error("cache file: method tag '" + key.method + "' is too long");
    }
    std::memcpy(header.method, key.method.data(), key.method.size());
    header.payload_bytes = static_cast<uint32_t>(key.payload_bytes);
    header.levels = static_cast<uint32_t>(levels.size());
    header.scene = key.scene;
    header.accuracy = key.accuracy;
    std::vector<uint64_t> counts;
    for (const RecordStore& store : levels) {
        if (store.payload_bytes() != key.payload_bytes) {
            throw Error("cache file: a store of " + std::to_string(store.payload_bytes()) +
                        "-byte payloads written as " + std::to_string(key.payload_bytes));
        }
        counts.push_back(store.size());
        header.count += store.size();
    }
    std::string bytes;
    append(bytes, &header, 1);
    append(bytes, counts.data(), counts.size());
    for (const RecordStore& store : levels) {
        for (size_t i = 0; i < store.size(); ++i) {
            append(bytes, &store.records()[i], 1);
            append(bytes, &store.host_data()[i], 1);
            append(bytes, store.payload_data(i), key.payload_bytes);
        }
    }
    append_checksum(bytes);
    write_file_atomically(path, bytes);
}

std::vector<RecordStore> read_cache_file(const std::filesystem::path& path,
                                         const CacheFileKey& key) {
    const std::string name = path.string();
    if (!std::filesystem::is_regular_file(path)) {
        throw Error(name + ": " + key.method + " cache file " +
                    (std::filesystem::exists(path) ? "is not a regular file (a folder, a device "
                                                     "or a FIFO)"
                                                   : "not found"));
    }
    return parse_cache_file(read_file(path, kDefaultMaxFileBytes, key.method + " cache"), name,
                            key);
}

std::vector<RecordStore> parse_cache_file(const std::string& bytes, const std::string& name,
                                          const CacheFileKey& key) {
    const Header header = checked_header(name, bytes, key);
    std::vector<uint64_t> counts(header.levels);
    if (!counts.empty()) {  // (memcpy to an empty vector's null data is undefined)
        std::memcpy(counts.data(), bytes.data() + sizeof header, counts.size() * sizeof(uint64_t));
    }
    uint64_t total = 0;
    for (uint64_t c : counts) {
        total += std::min<uint64_t>(c, header.count + 1);
    }
    if (total != header.count) {
        throw Error(name + ": corrupt " + key.method + " cache (level counts do not add up)");
    }
    check_key(name, header, key);

    const char* in = bytes.data() + sizeof header + counts.size() * sizeof(uint64_t);
    std::vector<RecordStore> levels;
    uint64_t index = 0;
    for (uint64_t count : counts) {
        std::vector<shared::Record> records(count);
        std::vector<RecordHostData> host(count);
        std::vector<std::byte> payloads(count * key.payload_bytes);
        for (size_t i = 0; i < count; ++i, ++index) {
            std::memcpy(&records[i], in, sizeof(shared::Record));
            in += sizeof(shared::Record);
            std::memcpy(&host[i], in, sizeof(RecordHostData));
            in += sizeof(RecordHostData);
            if (key.payload_bytes > 0) {
                std::memcpy(payloads.data() + i * key.payload_bytes, in, key.payload_bytes);
            }
            in += key.payload_bytes;
            check_record(name, key, index, records[i], host[i],
                         payloads.data() + i * key.payload_bytes);
        }
        levels.emplace_back(key.accuracy, key.payload_bytes);
        levels.back().restore(std::move(records), std::move(host), std::move(payloads));
    }
    return levels;
}

}  // namespace rc
