#include "examples/scene/scene_mesh.h"

#include "examples/scene/layer_reference.h"
#include "schema/error.h"

namespace opal::scene {
namespace {

std::shared_ptr<const TranslucentAsset> loadAsset(const PrimReader& reader, const usda::Reference& reference,
                                                  const std::filesystem::path& file, AssetCache& assets) {
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
    const LayerReference layer =
        referencedLayer(reader, layerFile, "a translucent mesh references exactly one baked asset");
    SceneMesh mesh;
    mesh.assetFile = layer.file;
    mesh.desc.asset = loadAsset(reader, *layer.reference, mesh.assetFile, assets);
    mesh.desc.transform = objectToWorld;
    mesh.where = reader.prim().location;
    reader.ignore("extent");  // the asset's bounds; Opal computes its own
    return mesh;
}

}  // namespace opal::scene
