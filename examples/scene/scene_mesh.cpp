#include "examples/scene/scene_mesh.h"

#include "examples/scene/asset_path.h"
#include "schema/error.h"

namespace opal::scene {
namespace {

const usda::Reference& theReference(const PrimReader& reader) {
    const std::vector<usda::Reference> references = reader.prim().references.composed();
    if (references.size() != 1)
        reader.fail(reader.prim().location, "has " + std::to_string(references.size()) +
                                                " references; a translucent mesh references exactly one baked asset");
    const usda::ListOp<usda::Reference>& op = reader.prim().references;
    const usda::Reference& reference = !op.prepended.empty()       ? op.prepended.front()
                                       : !op.explicitItems.empty() ? op.explicitItems.front()
                                                                   : op.appended.front();
    if (reference.assetPath.empty())
        reader.fail(reference.location, "references <" + reference.primPath +
                                            "> inside the scene; only references to baked asset layers are supported");
    return reference;
}

std::shared_ptr<const TranslucentAsset> loadAsset(const PrimReader& reader, const usda::Reference& reference,
                                                  const std::filesystem::path& file, AssetCache& assets) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
        reader.fail(reference.location, "references @" + reference.assetPath + "@, which does not exist (resolved to " +
                                            file.string() + ")");
    std::shared_ptr<const TranslucentAsset> asset;
    try {
        asset = assets.load(file);
    } catch (const Error& e) {
        reader.fail(reference.location, "cannot load the asset @" + reference.assetPath + "@: " + e.what());
    }
    if (!reference.primPath.empty() && reference.primPath != "/" + asset->name)
        reader.fail(reference.location, "references <" + reference.primPath + "> in @" + reference.assetPath +
                                            "@, but the asset's prim is </" + asset->name + ">");
    return asset;
}

void checkApiSchemas(const PrimReader& reader) {
    for (const std::string& schema : reader.prim().apiSchemas.composed())
        if (schema != "MaterialBindingAPI")
            reader.fail(reader.prim().location, "applies " + quotedName(schema) +
                                                    "; a mesh in a scene applies only MaterialBindingAPI (the asset "
                                                    "brings OpalSubsurfaceAPI)");
}

}  // namespace

bool isAssetReference(const usda::Prim& prim) { return prim.references.authored(); }

SceneMesh readMesh(PrimReader& reader, const Imath::M44d& objectToWorld, const std::filesystem::path& layerFile,
                   AssetCache& assets) {
    checkApiSchemas(reader);
    const usda::Reference& reference = theReference(reader);
    SceneMesh mesh;
    mesh.assetFile = resolveAssetPath(layerFile, reference.assetPath);
    mesh.desc.asset = loadAsset(reader, reference, mesh.assetFile, assets);
    mesh.desc.transform = objectToWorld;
    mesh.where = reader.prim().location;
    reader.ignore("extent");  // the asset's bounds; Opal computes its own
    return mesh;
}

}  // namespace opal::scene
