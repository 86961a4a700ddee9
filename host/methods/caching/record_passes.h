// A frame of irradiance caching as the methods built on its records render it (ic, rc, sdrc): in
// one pass of --spp camera samples, or by time (--time; methods/sample_passes.h) in passes of
// camera samples over the records the first pass placed.
#pragma once

#include <functional>

#include "methods/caching/cache_pipeline.h"
#include "methods/method.h"

namespace rc {

// What a method adds to each pass's result (a glossy cache's rays, statistics and the seconds
// its records took, in FrameResult::cache_seconds beside the irradiance records'), with
// irradiance caching's statistics of the pass.
using RecordPassFinish = std::function<void(FrameResult& result, const PipelineStats&)>;

// The frame rendered by `cache`: with `time` > 0 by time, each pass at most options.spp samples
// per pixel (a later pass adds records only where its samples are not covered), else one pass of
// options.spp. The result holds the image, samples, rays, non-finite samples and irradiance
// caching's statistics (pipeline_stats.h) of the first pass, `finish` having added its own; *last:
// the statistics of the last pass.
FrameResult render_record_passes(CachePipeline& cache, const PipelineSettings& options, double time,
                                 const FrameHooks& hooks, const RecordPassFinish& finish,
                                 PipelineStats* last);

}  // namespace rc
