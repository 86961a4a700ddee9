#include "methods/irradiance_cache/record_level_source.h"

namespace rc {

DeviceRecords::DeviceRecords(Context& context, const RecordStore& store) {
    const RecordGridData data = store.build_grid();
    grid = data.grid;
    records = Buffer<shared::IrradianceRecord>(context, store.device_records(), "ic_records");
    cell_start = Buffer<int>(context, data.cell_start, "ic_cell_start");
    cell_records = Buffer<int>(context, data.cell_records, "ic_cell_records");
}

RecordLevelSource::RecordLevelSource(Context& context, const RecordStore& store, float max_weight)
    : records_(context, store), accuracy_(store.accuracy()), max_weight_(max_weight) {}

unsigned RecordLevelSource::set_kernel_args(Kernel& kernel, unsigned first) const {
    kernel.set_arg(first, sizeof records_.grid, &records_.grid);
    const DeviceBuffer* buffers[3] = {&records_.cell_start, &records_.cell_records,
                                      &records_.records};
    for (unsigned b = 0; b < 3; ++b) {
        _cl_mem* handle = buffers[b]->handle();
        kernel.set_arg(first + 1 + b, sizeof handle, &handle);
    }
    kernel.set_arg(first + 4, sizeof accuracy_, &accuracy_);
    kernel.set_arg(first + 5, sizeof max_weight_, &max_weight_);
    return 6;
}

}  // namespace rc
