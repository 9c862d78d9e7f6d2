#include "examples/scene/layer_reference.h"

#include "examples/scene/asset_path.h"

#include <string>

namespace opal::scene {

LayerReference referencedLayer(const PrimReader& reader, const std::filesystem::path& layerFile, std::string_view rule) {
    const std::vector<usda::Reference> references = reader.prim().references.composed();
    if (references.size() != 1)
        reader.fail(reader.prim().location,
                    "has " + std::to_string(references.size()) + " references; " + std::string(rule));
    const usda::ListOp<usda::Reference>& op = reader.prim().references;
    const usda::Reference& reference = !op.prepended.empty()       ? op.prepended.front()
                                       : !op.explicitItems.empty() ? op.explicitItems.front()
                                                                   : op.appended.front();
    if (reference.assetPath.empty())
        reader.fail(reference.location, "references <" + reference.primPath +
                                            "> inside the scene; only references to baked asset layers are supported");
    LayerReference result{&reference, resolveAssetPath(layerFile, reference.assetPath)};
    std::error_code error;
    if (!std::filesystem::is_regular_file(result.file, error))
        reader.fail(reference.location, "references @" + reference.assetPath + "@, which does not exist (resolved to " +
                                            result.file.string() + ")");
    return result;
}

}  // namespace opal::scene
