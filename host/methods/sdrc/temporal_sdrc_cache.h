// Temporal caching of SDRC's records (`--method sdrc --temporal`; Gautron, Bouatouch and
// Pattanaik 2006, §3: the temporal weights and gradients serve any cached payload;
// docs/temporal-caching.md): SDRC records keep their place across frames, each serving the frames
// its lifespan allows (§4.2), its change to the next frame estimated by reprojection
// (TcSdrcReprojection, §4.3); an expired record is computed again in its place while it serves
// the image, else dropped (§5). The payload is the radiance of the record's L-tree samples, as
// the record kernel drew them; at every frame each serving record's L-tree is built from its
// payload at that frame (the temporal gradients, §4.4), and the interpolation's misses go into
// that frame's trees only. Driven by temporal irradiance caching's two passes
// (TemporalIrradianceCache), as radiance caching's records are.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "methods/caching/glossy_cache.h"
#include "methods/frame_scene.h"
#include "methods/sdrc/sdrc_cache.h"
#include "methods/temporal/tc_motion.h"
#include "methods/temporal/temporal_glossy.h"
#include "methods/temporal/temporal_glossy_set.h"
#include "methods/temporal/temporal_options.h"

namespace rc {

class TemporalSdrcCache final : public TemporalGlossySetRecords {
   public:
    TemporalSdrcCache(SdrcOptions options, TemporalOptions temporal, int first_frame,
                      int last_frame);

    // TemporalGlossyRecords (temporal_glossy.h); shading builds each serving record's L-tree from
    // its payload at the frame.
    void place_frame(const FrameScene& frame, const TcMotion& motion,
                     const shared::IcParams& params, const shared::CameraParams& camera,
                     const RadianceSource& diffuse) override;
    std::unique_ptr<GlossyCache> shading(const FrameScene& frame) const override;

   private:
    // A store of the records `ids` (their shared parts and host data as given), their sites and,
    // when `frame` >= 0, their L-trees at that frame (else empty trees: placement reads none).
    struct Records {
        RecordStore store;
        std::vector<shared::RcQuery> sites;
        std::vector<LTree> trees;
    };
    Records records_of(const std::vector<size_t>& ids, std::vector<shared::Record> parts,
                       std::vector<RecordHostData> host, int frame) const;
    // Record `id`'s L-tree at `frame`: its samples' nodes with their radiance at that frame.
    LTree tree_at(size_t id, int frame) const;

    SdrcOptions options_;
    std::vector<std::vector<shared::LTreeNode>> nodes_;  // per record: its samples' nodes
};

}  // namespace rc
