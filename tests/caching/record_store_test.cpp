// The shared record store (host/methods/caching/record_store.cpp) with a payload that is not
// irradiance caching's: the radius limits, neighbor clamping against brute force over every pair,
// the [R_min, R_max] clamp and its gradient scale, payloads kept byte for byte, and restoring.
#include "methods/caching/record_store.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>

namespace rc {
namespace {

// A payload of another method's size (37 floats: neither IC's nor a multiple of 4).
struct DummyPayload {
    float values[37];
};

DummyPayload dummy_payload(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    DummyPayload p;
    for (float& v : p.values) {
        v = unit(rng);
    }
    return p;
}

bool same_payload(const DummyPayload& a, const DummyPayload& b) {
    return std::equal(std::begin(a.values), std::end(a.values), std::begin(b.values));
}

// A record at a random place in a 10-unit box; its harmonic mean distance spans four decades,
// so neighbor clamping has work to do.
void random_record(std::mt19937& rng, shared::Record& record, RecordHostData& host) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    record = make_record(10.0f * glm::vec3(unit(rng), unit(rng), unit(rng)),
                         glm::vec3(0.0f, 0.0f, 1.0f));
    host = RecordHostData{};
    host.harmonic_distance = std::pow(10.0f, -2.0f + 4.0f * unit(rng));
    host.min_distance = 0.5f * host.harmonic_distance;
    host.r_min = 0.0f;
    host.r_max = 1e30f;
}

// After every insertion every pair of overlapping records satisfies R_j <= R_k + |p_j - p_k| on
// the unclamped radii (checked over all pairs), no insertion raises a radius, each radius is at
// most its harmonic distance and its method's limit, the shared part's radius is the clamped one,
// and every payload is the one inserted.
TEST(RecordStore, NeighborClampingKeepsTheTriangleInequalityAfterEveryInsertion) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    RecordStore store(0.3f, sizeof(DummyPayload));
    std::vector<float> before;
    std::vector<DummyPayload> inserted;
    size_t clamped = 0;
    for (int i = 0; i < 300; ++i) {
        shared::Record record;
        RecordHostData host;
        random_record(rng, record, host);
        if (i % 3 == 0) {
            host.r_max = 0.5f;  // some records capped from above
        }
        if (i % 5 == 0) {
            host.r_min = 0.3f;  // and some raised from below
        }
        const float limit = i % 4 == 0 ? 0.2f + unit(rng) : INFINITY;
        inserted.push_back(dummy_payload(rng));
        const size_t j = store.insert(record, host, inserted.back(), limit);
        const std::vector<RecordHostData>& h = store.host_data();
        const std::vector<shared::Record>& records = store.records();
        ASSERT_EQ(j, records.size() - 1);
        EXPECT_LE(h[j].radius, host.harmonic_distance);
        EXPECT_LE(h[j].radius, limit);
        clamped += h[j].radius < std::min(host.harmonic_distance, limit) ? 1 : 0;
        for (size_t k = 0; k < before.size(); ++k) {
            ASSERT_LE(h[k].radius, before[k]) << "insertion " << i << " raised record " << k;
        }
        for (size_t a = 0; a < records.size(); ++a) {
            ASSERT_EQ(records[a].radius, std::clamp(h[a].radius, h[a].r_min, h[a].r_max));
            for (size_t b = 0; b < records.size(); ++b) {
                const float d =
                    glm::length(record_position(records[a]) - record_position(records[b]));
                if (a != b && d < h[a].radius + h[b].radius) {
                    ASSERT_LE(h[a].radius, h[b].radius + d * (1.0f + 1e-6f))
                        << "after insertion " << i << ": records " << a << " and " << b;
                }
            }
        }
        before.clear();
        for (const RecordHostData& r : h) {
            before.push_back(r.radius);
        }
    }
    EXPECT_GT(clamped, 30u);  // the test exercised clamping
    for (size_t i = 0; i < inserted.size(); ++i) {
        ASSERT_TRUE(same_payload(store.payload<DummyPayload>(i), inserted[i])) << i;
    }
}

// An infinite harmonic distance (no hit) gives an infinite R, R_max on the device (and a neighbor
// clamps it later); R_min raises the shared part's radius and hands back R / R' as the gradient
// scale; a payload of the wrong size is refused.
TEST(RecordStore, ClampsToTheBoundsAndReportsTheGradientScale) {
    std::mt19937 rng(3);
    RecordStore store(0.5f, sizeof(DummyPayload));
    RecordHostData host;
    host.harmonic_distance = INFINITY;
    host.r_min = 1.0f;
    host.r_max = 6.0f;
    store.insert(make_record(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f)), host,
                 dummy_payload(rng), INFINITY);
    EXPECT_EQ(store.host_data()[0].radius, INFINITY);
    EXPECT_EQ(store.records()[0].radius, 6.0f);
    EXPECT_EQ(store.gradient_scale(0), 1.0f);
    host.harmonic_distance = 0.25f;
    store.insert(make_record(glm::vec3(100.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)), host,
                 dummy_payload(rng), INFINITY);
    EXPECT_EQ(store.host_data()[1].radius, 0.25f);
    EXPECT_EQ(store.records()[1].radius, 1.0f);
    EXPECT_EQ(store.gradient_scale(1), 0.25f);
    EXPECT_EQ(store.host_data()[0].radius, 100.25f);  // clamped by its new neighbor
    EXPECT_EQ(store.records()[0].radius, 6.0f);
    EXPECT_THROW(store.insert(store.records()[0], host, 1.0f, INFINITY), Error);
    const std::vector<float> floats(36, 0.0f);
    EXPECT_THROW(store.insert_bytes(store.records()[0], host, floats.data(),
                                    floats.size() * sizeof(float), INFINITY),
                 Error);
}

// Neighbor clamping uses the unclamped R (course, "Summary of Implementation Details": R is
// limited by the gradient, clamped to [R_min, R_max] into R', and "for [neighbor clamping's]
// correct functionality, it is essential to use the original, unclamped value of R (not R')").
// A record made close to the camera (small R_max) beside one made far away (large R_max) must not
// pass its small R_max on: the far record keeps min(its R, the near record's unclamped R + d).
TEST(RecordStore, NeighborClampingUsesTheUnclampedRadius) {
    std::mt19937 rng(5);
    RecordStore store(0.35f, sizeof(DummyPayload));
    RecordHostData near;
    near.harmonic_distance = 30.0f;
    near.r_min = 0.1f;
    near.r_max = 1.0f;
    RecordHostData far = near;
    far.harmonic_distance = 20.0f;
    far.r_max = 50.0f;
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    store.insert(make_record(glm::vec3(0.0f), n), near, dummy_payload(rng), INFINITY);
    store.insert(make_record(glm::vec3(0.5f, 0.0f, 0.0f), n), far, dummy_payload(rng), INFINITY);
    // Course: R_far = min(20, 30 + 0.5) = 20, R_near = min(30, 20 + 0.5) = 20.5; then the clamp.
    EXPECT_EQ(store.host_data()[1].radius, 20.0f);
    EXPECT_EQ(store.records()[1].radius, 20.0f);
    EXPECT_EQ(store.host_data()[0].radius, 20.5f);
    EXPECT_EQ(store.records()[0].radius, 1.0f);
    EXPECT_EQ(store.gradient_scale(0), 1.0f);
}

// The greatest fixed point of R_b = min(R_b, R_a + |p_a - p_b|) over every ordered pair of the
// first `count` records, from their initial radii: relaxed in sweeps until nothing changes.
std::vector<float> brute_force_radii(const std::vector<glm::vec3>& positions,
                                     std::vector<float> radii, size_t count) {
    radii.resize(count);
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t a = 0; a < count; ++a) {
            for (size_t b = 0; b < count; ++b) {
                const float bound = radii[a] + glm::length(positions[a] - positions[b]);
                if (b != a && bound < radii[b]) {
                    radii[b] = bound;
                    changed = true;
                }
            }
        }
    }
    return radii;
}

// Record i of the fixed-point tests: in clusters of very different sizes, radii over five
// decades, some with no hit and some limited by their method.
struct ClusteredRecord {
    shared::Record record;
    RecordHostData host;
    float limit;
};

ClusteredRecord clustered_record(std::mt19937& rng, int i) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float scale = std::pow(10.0f, -2.0f + 3.0f * static_cast<float>(i % 4) / 3.0f);
    const glm::vec3 centre = 20.0f * glm::vec3(i % 3, (i / 3) % 2, 0.5f);
    ClusteredRecord r;
    r.record = make_record(centre + scale * glm::vec3(unit(rng), unit(rng), unit(rng)),
                           glm::vec3(0, 0, 1));
    r.host.harmonic_distance =
        i % 97 == 0 ? INFINITY : scale * std::pow(10.0f, -1.0f + 2.0f * unit(rng));
    r.host.r_min = 0.0f;
    r.host.r_max = 1e30f;
    r.limit = i % 7 == 0 ? 0.5f * scale : INFINITY;
    return r;
}

// The store's radii after several numbers of insertions, bit for bit, against brute force: the
// greatest fixed point of R_b = min(R_b, R_a + |p_a - p_b|) over every ordered pair, relaxed in
// sweeps until nothing changes, from each record's initial R = min(harmonic distance, limit). (A
// pair that violates the inequality always overlaps, so the store's overlap-limited search must
// reach the same fixed point; float addition is monotone, so any relaxation order does.) Records in
// clusters of very different sizes, radii over five decades: every radius class, grid level and
// the search's whole-class fallback are exercised.
TEST(RecordStore, InsertionReachesTheBruteForceFixedPointBitForBit) {
    std::mt19937 rng(41);
    RecordStore store(0.35f, sizeof(DummyPayload));
    std::vector<glm::vec3> positions;
    std::vector<float> radii;
    size_t lowered = 0;
    for (int i = 0; i < 2500; ++i) {
        const ClusteredRecord r = clustered_record(rng, i);
        store.insert(r.record, r.host, dummy_payload(rng), r.limit);
        positions.push_back(record_position(r.record));
        radii.push_back(std::min(r.host.harmonic_distance, r.limit));
        const size_t count = positions.size();
        if (count % 50 == 0 && (count <= 400 || count % 500 == 0)) {
            const std::vector<float> expected = brute_force_radii(positions, radii, count);
            lowered = 0;
            for (size_t k = 0; k < count; ++k) {
                ASSERT_EQ(store.host_data()[k].radius, expected[k])
                    << "record " << k << " after " << count << " insertions";
                lowered += expected[k] < radii[k] ? 1 : 0;
            }
        }
    }
    EXPECT_GT(lowered, 500u);  // clamping did most of the work
}

// Batches of records (as a placement pass inserts them), their neighbor searches on 1, 2, 3 and
// 8 threads: after every batch the radii are brute force's fixed point bit for bit (and so equal
// whatever the thread count and batch size), the records and payloads are stored in order.
// Batches of up to 1500 records give every thread several hundred searches.
TEST(RecordStore, BatchInsertionOnAnyThreadCountReachesTheBruteForceFixedPoint) {
    const std::vector<size_t> batches = {1, 40, 259, 600, 1500, 100};
    std::vector<ClusteredRecord> all;
    std::vector<DummyPayload> payloads;
    std::mt19937 rng(43);
    size_t total = 0;
    for (size_t size : batches) {
        total += size;
    }
    std::vector<glm::vec3> positions;
    std::vector<float> radii;
    for (size_t i = 0; i < total; ++i) {
        all.push_back(clustered_record(rng, static_cast<int>(i)));
        payloads.push_back(dummy_payload(rng));
        positions.push_back(record_position(all.back().record));
        radii.push_back(std::min(all.back().host.harmonic_distance, all.back().limit));
    }
    std::vector<std::vector<float>> expected_after;  // brute force after each batch
    size_t end = 0;
    for (size_t size : batches) {
        end += size;
        expected_after.push_back(brute_force_radii(positions, radii, end));
    }
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        RecordStore store(0.35f, sizeof(DummyPayload));
        store.set_threads(threads);
        size_t count = 0;
        for (size_t n = 0; n < batches.size(); ++n) {
            const size_t size = batches[n];
            std::vector<NewRecord> batch;
            for (size_t i = count; i < count + size; ++i) {
                batch.push_back({all[i].record, all[i].host, &payloads[i], all[i].limit});
            }
            ASSERT_EQ(store.insert_batch(batch), count);
            count += size;
            ASSERT_EQ(store.size(), count);
            const std::vector<float>& expected = expected_after[n];
            size_t lowered = 0;
            for (size_t k = 0; k < count; ++k) {
                ASSERT_EQ(store.host_data()[k].radius, expected[k])
                    << "record " << k << " after " << count << " on " << threads << " threads";
                lowered += expected[k] < radii[k] ? 1 : 0;
            }
            if (count == total) {
                EXPECT_GT(lowered, count / 5);  // clamping had work to do
            }
        }
        for (size_t k = 0; k < total; ++k) {
            ASSERT_EQ(record_position(store.records()[k]), positions[k]) << k;
            ASSERT_TRUE(same_payload(store.payload<DummyPayload>(k), payloads[k])) << k;
        }
    }
}

// Restoring a store's records gives the same shared parts, host data, payloads and neighbor
// search: a record inserted next is clamped as in the original.
TEST(RecordStore, RestoredStoreClampsTheNextRecordAsTheOriginal) {
    std::mt19937 rng(29);
    RecordStore store(0.4f, sizeof(DummyPayload));
    for (int i = 0; i < 200; ++i) {
        shared::Record record;
        RecordHostData host;
        random_record(rng, record, host);
        store.insert(record, host, dummy_payload(rng), INFINITY);
    }
    RecordStore copy(0.4f, sizeof(DummyPayload));
    copy.restore(store.records(), store.host_data(), store.payloads());
    EXPECT_EQ(copy.payloads(), store.payloads());
    for (int i = 0; i < 50; ++i) {
        shared::Record record;
        RecordHostData host;
        random_record(rng, record, host);
        const DummyPayload p = dummy_payload(rng);
        store.insert(record, host, p, INFINITY);
        copy.insert_bytes(record, host, p.values, sizeof p.values, INFINITY);  // the untyped form
    }
    ASSERT_EQ(copy.size(), store.size());
    for (size_t i = 0; i < store.size(); ++i) {
        ASSERT_EQ(copy.host_data()[i].radius, store.host_data()[i].radius) << i;
        ASSERT_EQ(copy.records()[i].radius, store.records()[i].radius) << i;
    }
}

}  // namespace
}  // namespace rc
