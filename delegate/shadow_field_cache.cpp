#include "delegate/shadow_field_cache.h"

#include "schema/asset/shadow_field_file.h"
#include "schema/error.h"

namespace opal {

std::shared_ptr<const LoadedShadowField> ShadowFieldCache::get(const std::string& file) {
    if (file.empty()) throw Error("shadow-field light: no opal:field (the light asset's sidecar)");
    std::error_code error;
    std::filesystem::path key = std::filesystem::absolute(file, error).lexically_normal();
    if (error) key = file;
    if (const auto it = fields_.find(key); it != fields_.end()) return it->second;
    auto loaded = std::make_shared<const LoadedShadowField>(readShadowFieldFile(key));
    fields_.emplace(key, loaded);
    return loaded;
}

}  // namespace opal
