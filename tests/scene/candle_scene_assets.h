// The shipped candlelight scene (examples/scenes/candlelight.usda) copied into a test's
// directory with the assets it references baked beside it, small: the built-in candle and
// wick (level 1, 512 and 256 samples, an 8 x 8 environment cube map) and the flame of
// scripts/run-main (2 shells of 6 x 2 x 2 points, cube maps of 6 x 4 x 4 texels); and the
// room's environment image (examples/room), 64 x 32 pixels.
#pragma once

#include "bake/asset_stem.h"
#include "bake/bake_pipeline.h"
#include "bake/light/field_bake.h"
#include "bake/light/light_bake.h"
#include "bake/light/light_spec.h"
#include "bake/stem_lock.h"
#include "examples/room/room_image_file.h"
#include "tests/scene/scene_test_files.h"

#include <filesystem>
#include <string>

namespace opal::test {

inline void bakeSmallBuiltin(const SceneDir& dir, const std::string& name, std::uint64_t samples) {
    BakeOptions options;
    options.input = "builtin:" + name;
    options.level = 1;
    options.samples = samples;
    options.visibility.cubeFaceSize = 8;
    options.visibility.terms = 32;
    writeBakedAsset(dir / name, bakeAsset(options, nullptr, CancelToken{}, nullptr), nullptr);
}

inline void bakeSmallFlame(const SceneDir& dir) {
    const Emitter emitter = parseLightSpec("flame:height=24,radius=4");
    FieldSettings settings;
    settings.shells = 2;
    settings.directionFaceSize = 2;
    settings.mapFaceSize = 4;
    settings.raysPerTexelSide = 1;
    const StemLock lock{AssetStem(dir / "flame")};
    LightBakeReport report;
    ShadowField field = bakeShadowField(emitter, settings, nullptr, CancelToken{});
    field.bakeId = lightBakeIdentifier(emitter, settings);
    writeLightAsset(lock, field, report);
}

// Returns the scene's path in `dir`.
inline std::filesystem::path writeCandleScene(const SceneDir& dir) {
    bakeSmallBuiltin(dir, "candle", 512);
    bakeSmallBuiltin(dir, "wick", 256);
    bakeSmallFlame(dir);
    writeRoomImage(dir / "room.exr", RoomLook{}, 32);
    const std::filesystem::path scene = dir / "candlelight.usda";
    std::filesystem::copy_file(std::filesystem::path(OPAL_SOURCE_DIR) / "examples/scenes/candlelight.usda", scene);
    return scene;
}

}  // namespace opal::test
