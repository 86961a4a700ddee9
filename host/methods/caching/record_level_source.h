// A cache level's records on the device, and a deeper level read as a radiance source
// (kernels/caching/record_level_source.h; --ic-bounces): the hemisphere rays of the level
// above interpolate its records at their hits.
#pragma once

#include "device/buffer.h"
#include "device/context.h"
#include "methods/caching/irradiance_records.h"
#include "methods/caching/record_grid.h"
#include "methods/radiance_source.h"
#include "shared/types.h"

namespace rc {

// What the device copy of a record store holds, made once on the host (several devices upload
// the same): records, their payloads (gradients scaled for the clamped radius) and the
// world-space grid over them. With `with_grid` false the grid is empty (one cell, no records):
// for splatting alone.
struct HostRecords {
    HostRecords(const RecordStore& store, bool with_grid = true);

    float accuracy = 0.0f;
    std::vector<shared::Record> records;
    std::vector<shared::IrradiancePayload> payloads;
    RecordGridData grid;
};

// The device copy of a record store (HostRecords).
struct DeviceRecords {
    DeviceRecords(Context& context, const RecordStore& store, bool with_grid = true);
    DeviceRecords(Context& context, const HostRecords& host);
    size_t bytes() const {
        return records.bytes() + payloads.bytes() + cell_start.bytes() + cell_records.bytes();
    }

    shared::RecordGrid grid{};
    Buffer<shared::Record> records;
    Buffer<shared::IrradiancePayload> payloads;
    Buffer<int> cell_start;
    Buffer<int> cell_records;
};

class RecordLevelSource final : public RadianceSource {
   public:
    // The store's records, weighted with its accuracy and at most `max_weight`.
    RecordLevelSource(Context& context, const RecordStore& store, float max_weight);
    RecordLevelSource(Context& context, const HostRecords& records, float max_weight);

    std::string build_options() const override {
        return radiance_source_define(RC_RADIANCE_RECORDS);
    }
    std::string source_name() const override { return "irradiance records"; }
    // (RecordGrid, cell start, cell records, records, payloads, accuracy, largest weight), in
    // that order.
    unsigned set_kernel_args(Kernel& kernel, unsigned first) const override;

   private:
    DeviceRecords records_;
    float accuracy_;
    float max_weight_;
};

}  // namespace rc
