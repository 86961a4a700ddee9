// The device copy of a record store's splat into the screen tiles of a camera's image
// (splat_tiles.h): the tile grid and its record lists, made once on the host (several devices
// upload the same).
#pragma once

#include <vector>

#include "device/buffer.h"
#include "device/context.h"
#include "methods/caching/record_store.h"
#include "methods/caching/splat_tiles.h"
#include "shared/types.h"

namespace rc {

// The tiles of `camera`'s image each record of `store` is splatted into (influence: accuracy x
// radius), skipping tiles whose `tile_depths` (may be null) its sphere does not reach.
SplatTiles store_splat_tiles(const RecordStore& store, const shared::CameraParams& camera,
                             const std::vector<shared::TileDepths>* tile_depths);

struct DeviceSplat {
    DeviceSplat(Context& context, const SplatTiles& splat);
    DeviceSplat(Context& context, const RecordStore& store, const shared::CameraParams& camera,
                const std::vector<shared::TileDepths>* tile_depths)
        : DeviceSplat(context, store_splat_tiles(store, camera, tile_depths)) {}

    shared::SplatTileGrid tiles{};
    Buffer<int> tile_start;
    Buffer<int> tile_records;
};

}  // namespace rc
