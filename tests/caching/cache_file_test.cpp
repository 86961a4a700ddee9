// Record cache files (host/methods/caching/cache_file.cpp) with a payload that is not irradiance
// caching's: an exact round trip of several levels, and the refusal of a file made for another
// method, payload size, scene or accuracy, or damaged, each with an error naming the file.
#include "methods/caching/cache_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

struct DummyPayload {
    float values[37];
};

CacheFileKey dummy_key() {
    CacheFileKey key;
    key.method = "dummy";
    key.payload_bytes = sizeof(DummyPayload);
    key.scene = 0x1234567890abcdefull;
    key.scene_name = "dummy scene";
    key.accuracy = 0.25f;
    return key;
}

RecordStore random_store(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    RecordStore store(dummy_key().accuracy, sizeof(DummyPayload));
    for (int i = 0; i < count; ++i) {
        RecordHostData host;
        host.harmonic_distance = 0.05f + unit(rng);
        host.min_distance = 0.5f * host.harmonic_distance;
        host.r_min = 0.1f;
        host.r_max = 0.8f;
        DummyPayload p;
        for (float& v : p.values) {
            v = unit(rng) - 0.5f;
        }
        store.insert(
            make_record(glm::vec3(unit(rng), unit(rng), unit(rng)), glm::vec3(0.0f, 0.0f, 1.0f)),
            host, p, 0.3f + unit(rng));
    }
    return store;
}

// (memcmp of empty stores would pass it null pointers: undefined behaviour, UBSan says.)
bool same_records(const RecordStore& a, const RecordStore& b) {
    if (a.size() == 0 || b.size() == 0) {
        return a.size() == b.size() && a.payload_bytes() == b.payload_bytes() &&
               a.accuracy() == b.accuracy();
    }
    return a.size() == b.size() && a.payload_bytes() == b.payload_bytes() &&
           a.accuracy() == b.accuracy() && a.payloads() == b.payloads() &&
           std::memcmp(a.records().data(), b.records().data(), a.size() * sizeof(shared::Record)) ==
               0 &&
           std::memcmp(a.host_data().data(), b.host_data().data(),
                       a.size() * sizeof(RecordHostData)) == 0;
}

void expect_refused(const std::filesystem::path& file, const CacheFileKey& key,
                    const std::string& message) {
    try {
        read_cache_file(file, key);
        ADD_FAILURE() << file << " was accepted";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    }
}

// Three levels (one empty) of 37-float payloads come back bit for bit.
TEST(CacheFile, RoundTripsAnyPayloadSizeExactly) {
    std::mt19937 rng(11);
    std::vector<RecordStore> levels;
    levels.push_back(random_store(rng, 120));
    levels.push_back(RecordStore(dummy_key().accuracy, sizeof(DummyPayload)));
    levels.push_back(random_store(rng, 40));
    const auto file = test::scratch_dir("cache_file_round_trip") / "dummy.rcc";
    write_cache_file(file, dummy_key(), levels);
    const std::vector<RecordStore> read = read_cache_file(file, dummy_key());
    ASSERT_EQ(read.size(), levels.size());
    for (size_t level = 0; level < levels.size(); ++level) {
        EXPECT_TRUE(same_records(read[level], levels[level])) << "level " << level;
    }
}

// A sound file read for another method, payload size, scene or accuracy is refused, and so are
// damaged ones.
TEST(CacheFile, RefusesAnotherMethodPayloadSizeSceneOrAccuracy) {
    std::mt19937 rng(13);
    const auto dir = test::scratch_dir("cache_file_refused");
    const auto good = dir / "good.rcc";
    write_cache_file(good, dummy_key(), {random_store(rng, 30)});
    EXPECT_NO_THROW(read_cache_file(good, dummy_key()));

    CacheFileKey key = dummy_key();
    key.method = "irradiance";
    expect_refused(good, key, "holds dummy records, not irradiance records");
    key = dummy_key();
    key.payload_bytes = 36 * sizeof(float);
    expect_refused(good, key, "148-byte record payloads");
    key = dummy_key();
    key.scene ^= 1;
    expect_refused(good, key, "another scene (or another frame of it) than dummy scene");
    key = dummy_key();
    key.accuracy = 0.5f;
    expect_refused(good, key, "accuracy");

    const std::string bytes = read_file(good);
    std::string flipped = bytes;
    flipped[bytes.size() / 2] ^= 0x10;
    write_file_atomically(dir / "flipped.rcc", flipped);
    expect_refused(dir / "flipped.rcc", dummy_key(), "checksum");
    write_file_atomically(dir / "truncated.rcc", bytes.substr(0, bytes.size() - 7));
    expect_refused(dir / "truncated.rcc", dummy_key(), "corrupt");
    std::string version = bytes;
    version[8] = 1;
    write_file_atomically(dir / "version.rcc", version);
    expect_refused(dir / "version.rcc", dummy_key(), "dummy cache version 1");
    expect_refused(dir / "missing.rcc", dummy_key(), "dummy cache file not found");
}

}  // namespace
}  // namespace rc
