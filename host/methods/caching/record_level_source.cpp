#include "methods/caching/record_level_source.h"

namespace rc {

HostRecords::HostRecords(const RecordStore& store, bool with_grid)
    : accuracy(store.accuracy()),
      records(store.records()),
      payloads(device_payloads(store)),
      grid(build_record_grid(with_grid ? store.records() : std::vector<shared::Record>{},
                             store.accuracy())) {}

DeviceRecords::DeviceRecords(Context& context, const RecordStore& store, bool with_grid)
    : DeviceRecords(context, HostRecords(store, with_grid)) {}

DeviceRecords::DeviceRecords(Context& context, const HostRecords& host)
    : grid(host.grid.grid),
      records(context, host.records, "ic_records"),
      payloads(context, host.payloads, "ic_payloads"),
      cell_start(context, host.grid.cell_start, "ic_cell_start"),
      cell_records(context, host.grid.cell_records, "ic_cell_records") {}

RecordLevelSource::RecordLevelSource(Context& context, const RecordStore& store, float max_weight)
    : RecordLevelSource(context, HostRecords(store), max_weight) {}

RecordLevelSource::RecordLevelSource(Context& context, const HostRecords& records, float max_weight)
    : records_(context, records), accuracy_(records.accuracy), max_weight_(max_weight) {}

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
