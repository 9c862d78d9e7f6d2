// Shadow-field light sidecars (schema/asset/shadow_field_file.h) loaded once per file: moving,
// scaling or recolouring a light, or a second light prim using the same baked light, reads
// nothing. Cached by the file's absolute normal path; a failed load is not cached.
#pragma once

#include "delegate/relight/shadow_field_light.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace opal {

class ShadowFieldCache {
public:
    // Throws opal::Error naming the file (and chunk) when it does not read.
    std::shared_ptr<const LoadedShadowField> get(const std::string& file);
    std::size_t size() const { return fields_.size(); }

private:
    std::map<std::filesystem::path, std::shared_ptr<const LoadedShadowField>> fields_;
};

}  // namespace opal
