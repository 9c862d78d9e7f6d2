#include "bench/dome_map.h"

#include "delegate/dome_texture.h"
#include "schema/error.h"

namespace opal::bench {

std::shared_ptr<const LatLongMap> readDomeMap(const std::filesystem::path& env) {
    if (std::error_code ec; !std::filesystem::is_regular_file(env, ec))
        throw Error("environment map '" + env.string() + "' not found (pass --env, or set OPAL_SHARED_ASSETS)");
    DomeTextureCache textures;
    const hd::LightDesc defaults;
    return textures.get(env.string(), defaults.textureColorSpace);
}

}  // namespace opal::bench
