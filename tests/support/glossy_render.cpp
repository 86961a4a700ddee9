#include "glossy_render.h"

#include <utility>

#include "glossy_scenes.h"
#include "image_options.h"
#include "methods/path_tracer/path_tracer.h"

namespace rc::test {
namespace {

template <class Cache, class Options>
GlossyRender<Cache> render_glossy(DeviceFrame& device, PipelineSettings ic, Options options) {
    options.seed = ic.seed;
    Cache glossy(device.frame(), options);
    CachePipeline cache(device.frame(), {.lobes = &glossy});
    GlossyRender<Cache> r;
    r.image = cache.render(ic);
    r.stats = glossy.stats();
    return r;
}

}  // namespace

PipelineSettings glossy_ic_options(int size, int spp, uint64_t seed, int rays) {
    auto ic = image_options<PipelineSettings>(size, size, spp, seed);
    ic.rays = rays;
    ic.bounces = 1;
    ic.records_overlay = false;
    return ic;
}

RcRender render_rc(DeviceFrame& device, PipelineSettings ic, RadianceCacheOptions options) {
    return render_glossy<RadianceCache>(device, std::move(ic), std::move(options));
}

SdrcRender render_sdrc(DeviceFrame& device, PipelineSettings ic, SdrcOptions options) {
    return render_glossy<SdrcCache>(device, std::move(ic), std::move(options));
}

Image path_traced_indirect(DeviceFrame& device, int size) {
    PathTracerOptions pt;
    pt.width = size;
    pt.height = size;
    pt.spp = 1024;
    pt.seed = 11;
    return select_layers(PathTracer(device.frame()).render(pt), {"indirect"});
}

SphereErrors sphere_errors(DeviceFrame& device, const PipelineSettings& ic,
                           const Image& glossy_image, const Image& reference) {
    const Image mc = CachePipeline(device.frame()).render(ic);
    const Image mask = sphere_mask(select_layers(glossy_image, {"albedo"}));
    SphereErrors errors;
    errors.glossy =
        masked_relmse(select_layers(glossy_image, {"indirect"}), reference, mask, &errors.pixels);
    errors.monte_carlo =
        masked_relmse(select_layers(mc, {"indirect"}), reference, mask, &errors.pixels);
    return errors;
}

}  // namespace rc::test
