#include "methods/irradiance_cache/record_level_source.h"

#include "methods/records/record_grid.h"

namespace rc {

DeviceRecords::DeviceRecords(Context& context, const RecordStore& store, bool with_grid) {
    const RecordGridData data = build_record_grid(
        with_grid ? store.records() : std::vector<shared::Record>{}, store.accuracy());
    grid = data.grid;
    records = Buffer<shared::Record>(context, store.records(), "ic_records");
    payloads = Buffer<shared::IrradiancePayload>(context, device_payloads(store), "ic_payloads");
    cell_start = Buffer<int>(context, data.cell_start, "ic_cell_start");
    cell_records = Buffer<int>(context, data.cell_records, "ic_cell_records");
}

RecordLevelSource::RecordLevelSource(Context& context, const RecordStore& store, float max_weight)
    : records_(context, store), accuracy_(store.accuracy()), max_weight_(max_weight) {}

unsigned RecordLevelSource::set_kernel_args(Kernel& kernel, unsigned first) const {
    kernel.set_arg(first, sizeof records_.grid, &records_.grid);
    const DeviceBuffer* buffers[4] = {&records_.cell_start, &records_.cell_records,
                                      &records_.records, &records_.payloads};
    for (unsigned b = 0; b < 4; ++b) {
        _cl_mem* handle = buffers[b]->handle();
        kernel.set_arg(first + 1 + b, sizeof handle, &handle);
    }
    kernel.set_arg(first + 5, sizeof accuracy_, &accuracy_);
    kernel.set_arg(first + 6, sizeof max_weight_, &max_weight_);
    return 7;
}

}  // namespace rc
