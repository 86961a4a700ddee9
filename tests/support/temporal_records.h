// Irradiance records computed at given sites and, given the scene at the next frame, their
// reprojected estimates there: what the temporal tests compare with records computed fresh.
#pragma once

#include <memory>
#include <vector>

#include "methods/caching/cache_pipeline.h"
#include "methods/temporal/tc_reprojection.h"

namespace rc {

// The payloads of records computed at `sites` of `frame`, in order; with `next`, their estimates
// reprojected to it in *carried.
inline std::vector<shared::IrradiancePayload> records_at_sites(
    const FrameScene& frame, const std::vector<RecordSite>& sites, PipelineSettings options,
    const Scene* next = nullptr, std::vector<CarriedRecord>* carried = nullptr) {
    std::unique_ptr<TemporalReprojection> reprojection;
    if (next != nullptr) {
        reprojection = std::make_unique<TemporalReprojection>(frame, *next, 4);
    }
    CachePipeline cache(frame, {.observer = reprojection.get()});
    cache.begin(options);
    cache.add_records(sites);
    if (carried != nullptr) {
        *carried = reprojection->take(0);
    }
    std::vector<shared::IrradiancePayload> payloads;
    for (size_t i = 0; i < sites.size(); ++i) {
        payloads.push_back(cache.store(0).payload<shared::IrradiancePayload>(i));
    }
    return payloads;
}

}  // namespace rc
