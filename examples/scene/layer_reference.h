// A prim's reference to another layer (a baked asset, a baked light): exactly one, to a
// layer file (not a prim of the scene itself), which exists. Errors at the prim or the
// reference, with file:line:column.
#pragma once

#include "examples/scene/prim_reader.h"

#include <filesystem>
#include <string_view>

namespace opal::scene {

struct LayerReference {
    const usda::Reference* reference = nullptr;  // as authored (prepended, explicit or appended)
    std::filesystem::path file;                  // resolved against the referencing layer
};

// `rule` completes the count error ("has 2 references; " + rule), e.g. "a translucent mesh
// references exactly one baked asset". Throws UsdaError.
LayerReference referencedLayer(const PrimReader& reader, const std::filesystem::path& layerFile, std::string_view rule);

}  // namespace opal::scene
