#include "schema/asset/asset_over_layer.h"

#include "schema/asset/asset_layer.h"
#include "schema/error.h"

#include <vector>

namespace opal {
namespace {

std::vector<std::string> ancestorNames(const std::string& primPath, const std::string& assetName) {
    const std::string suffix = "/" + assetName;
    if (primPath.empty() || primPath[0] != '/' || !primPath.ends_with(suffix))
        throw Error("over-layer: prim path <" + primPath + "> is not an absolute path ending in the asset's name '" +
                    assetName + "'");
    std::vector<std::string> names;
    const std::string parent = primPath.substr(0, primPath.size() - suffix.size());
    for (std::size_t start = 1; start < parent.size();) {
        const std::size_t end = std::min(parent.find('/', start), parent.size());
        if (end == start) throw Error("over-layer: prim path <" + primPath + "> has an empty prim name");
        names.push_back(parent.substr(start, end - start));
        start = end + 1;
    }
    return names;
}

usda::Prim overPrim(std::string name) {
    usda::Prim prim;
    prim.specifier = usda::Specifier::Over;
    prim.name = std::move(name);
    return prim;
}

}  // namespace

usda::Layer assetToOverLayer(const TranslucentAsset& asset, const std::string& sidecarAssetPath,
                             const std::string& primPath) {
    const std::vector<std::string> ancestors = ancestorNames(primPath, asset.name);
    usda::Layer asLayer = assetToLayer(asset, sidecarAssetPath);
    usda::Prim mesh = std::move(asLayer.rootPrims.front());
    // An opinion on the mesh only: the user's def keeps its type and its place in the
    // model hierarchy.
    mesh.specifier = usda::Specifier::Over;
    mesh.typeName.clear();
    mesh.metadata.erase("kind");
    // The render mesh has no holes: the user's holeIndices would name its faces by the
    // control mesh's numbering (the bake already left those faces out).
    mesh.addAttribute("holeIndices", usda::Value::make<usda::types::IntArray>({}));

    usda::Prim top = std::move(mesh);
    for (auto name = ancestors.rbegin(); name != ancestors.rend(); ++name) {
        usda::Prim parent = overPrim(*name);
        parent.addChild(std::move(top));
        top = std::move(parent);
    }
    usda::Layer layer;
    layer.metadata = std::move(asLayer.metadata);
    layer.metadata.erase("defaultPrim");  // the layer defines no prim
    layer.metadata.erase("upAxis");       // the mesh stays in the prim's space, whatever the stage's axis
    layer.metadata.set("doc", usda::Value::string("Opal over-layer: the translucent asset baked from " +
                                                  asset.bake.source + " <" + primPath +
                                                  ">; sublayer it over that layer"));
    layer.addRootPrim(std::move(top));
    return layer;
}

}  // namespace opal
