#include "methods/caching/device_splat.h"

#include "methods/caching/record_store.h"

namespace rc {

SplatTiles store_splat_tiles(const RecordStore& store, const shared::CameraParams& camera,
                             const std::vector<shared::TileDepths>* tile_depths) {
    std::vector<glm::vec3> centres;
    std::vector<float> influence;
    for (const shared::Record& record : store.records()) {
        centres.push_back(record_position(record));
        influence.push_back(store.accuracy() * record.radius);
    }
    return splat_tiles(camera, centres, influence, RC_SPLAT_TILE_SIZE, tile_depths);
}

DeviceSplat::DeviceSplat(Context& context, const SplatTiles& splat)
    : tiles{splat.tile_size, splat.tiles_x, splat.tiles_y, 0},
      tile_start(context, splat.tile_start, "ic_tile_start"),
      tile_records(context, splat.tile_records, "ic_tile_records") {}

}  // namespace rc
