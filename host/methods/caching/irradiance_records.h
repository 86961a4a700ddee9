// Irradiance caching's records in the shared record store (host/methods/caching/): the payload
// (shared::IrradiancePayload), the radius limit its translational gradient sets, the gradients
// scaled when the [R_min, R_max] clamp raised R, and the key of its cache files.
#pragma once

#include <vector>

#include "methods/caching/cache_file.h"
#include "methods/caching/record_store.h"
#include "scene/scene.h"
#include "shared/records.h"

namespace rc {

// The method tag of irradiance records in cache files.
inline constexpr const char* kIrradianceMethodTag = "irradiance";

// A record the record kernels computed, before insertion: its three parts.
struct ComputedRecord {
    shared::Record record{};
    RecordHostData host{};
    shared::IrradiancePayload payload{};
};

// An empty store of irradiance records.
RecordStore irradiance_store(float accuracy);

// The gradient limit on R: E / |grad_t E| (luminance), so |grad E| R <= E keeps first-order
// extrapolation within the radius non-negative (course, "Gradient Limit on Record Spacing");
// infinite where there is no gradient or no irradiance.
float irradiance_radius_limit(const shared::IrradiancePayload& payload);

// Inserts a computed record with its gradient limit; returns its index.
size_t insert_irradiance_record(RecordStore& store, const ComputedRecord& computed);
// Inserts computed records in one batch (RecordStore::insert_batch: the same radii as one by one).
void insert_irradiance_records(RecordStore& store, const std::vector<ComputedRecord>& computed);

// The kernels' form of record i's payload: both gradients scaled by store.gradient_scale(i),
// so extrapolation over a radius the clamp raised stays as bounded as over R.
shared::IrradiancePayload device_payload(const RecordStore& store, size_t i);
std::vector<shared::IrradiancePayload> device_payloads(const RecordStore& store);

// The cache-file key of irradiance records for this scene and accuracy.
CacheFileKey irradiance_cache_key(const Scene& scene, float accuracy);

}  // namespace rc
