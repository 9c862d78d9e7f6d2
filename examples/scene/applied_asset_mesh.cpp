#include "examples/scene/applied_asset_mesh.h"

#include "schema/asset/asset_layer.h"
#include "schema/error.h"

namespace opal::scene {
namespace {

// UsdGeomMesh attributes a user's prim may author, which the asset's render mesh replaces.
constexpr std::string_view kReplacedMeshAttributes[] = {
    "extent",          "doubleSided",        "holeIndices",       "creaseIndices",   "creaseLengths",
    "creaseSharpnesses", "cornerIndices",    "cornerSharpnesses", "interpolateBoundary",
    "faceVaryingLinearInterpolation", "triangleSubdivisionRule", "velocities", "accelerations"};

void checkApiSchemas(const PrimReader& reader) {
    for (const std::string& schema : reader.prim().apiSchemas.composed())
        if (schema != kSubsurfaceApi && schema != "MaterialBindingAPI")
            reader.fail(reader.prim().location, "applies " + quotedName(schema) +
                                                    "; a translucent Mesh applies only OpalSubsurfaceAPI and "
                                                    "MaterialBindingAPI");
}

// The token `name` must hold `expected` (the over-layer's value) when authored.
void requireToken(PrimReader& reader, std::string_view name, const std::string& expected, std::string_view why) {
    const std::optional<std::string> value = reader.get<usda::types::Token>(name);
    if (value && *value != expected)
        reader.failAt(*reader.prim().findAttribute(name),
                      "is " + quotedName(*value) + ", but the asset's render mesh needs \"" + expected + "\" (" +
                          std::string(why) + ")");
}

}  // namespace

bool appliesSubsurface(const usda::Prim& prim) {
    return prim.typeName == "Mesh" && prim.hasApiSchema(kSubsurfaceApi);
}

SceneMesh readAppliedAssetMesh(PrimReader& reader, const Imath::M44d& objectToWorld,
                               const std::filesystem::path& layerFile, AssetCache& assets) {
    checkApiSchemas(reader);
    const std::string stack = "is the over-layer sublayered first, the strongest?";
    requireToken(reader, "subdivisionScheme", "none", "it is already refined; " + stack);
    requireToken(reader, "orientation", "rightHanded", stack);
    for (std::string_view name : assetPrimAttributes()) reader.ignore(name);
    for (std::string_view name : kReplacedMeshAttributes) reader.ignore(name);
    for (const usda::Property* p : reader.withPrefix("primvars:")) reader.ignore(usda::propertyName(*p));
    SceneMesh mesh;
    try {
        mesh.desc.asset = assets.load(reader.prim(), layerFile);
    } catch (const Error& e) {
        reader.fail(reader.prim().location, std::string("cannot load the asset it applies: ") + e.what());
    }
    const usda::Attribute* sidecar = reader.prim().findAttribute("opal:sidecar");
    mesh.assetFile = sidecar && sidecar->location.file ? std::filesystem::path(*sidecar->location.file) : layerFile;
    mesh.applied = true;
    mesh.desc.transform = objectToWorld;
    mesh.where = reader.prim().location;
    return mesh;
}

}  // namespace opal::scene
