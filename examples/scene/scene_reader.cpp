#include "examples/scene/scene_reader.h"

#include "examples/scene/applied_asset_mesh.h"
#include "examples/scene/layer_stack.h"
#include "examples/scene/scene_camera.h"
#include "examples/scene/scene_lights.h"
#include "examples/scene/scene_material.h"
#include "examples/scene/scene_mesh.h"
#include "examples/scene/scene_path.h"
#include "examples/scene/xformable.h"
#include "schema/asset/shadow_field_layer.h"
#include "schema/usd/time_samples.h"
#include "schema/usd/usda_reader.h"

#include <cmath>
#include <set>

namespace opal::scene {
namespace {

constexpr const char* SupportedTypes =
    "Xform, Scope, Mesh or a typeless prim referencing a baked asset, Mesh applying OpalSubsurfaceAPI, Material, SphereLight, DistantLight, "
    "DomeLight, OpalShadowFieldLight, Camera, RenderSettings";

bool isSupportedType(const std::string& type) {
    for (const char* known : {"", "Xform", "Scope", "Mesh", "Material", "Camera", "RenderSettings"})
        if (type == known) return true;
    return lightTypeOf(type).has_value();
}

// The API schemas a scene prim may apply (a mesh: scene_mesh.cpp).
void checkApiSchemas(const PrimReader& reader) {
    const std::string& type = reader.prim().typeName;
    const bool group = type.empty() || type == "Scope" || type == "Xform";
    for (const std::string& schema : reader.prim().apiSchemas.composed()) {
        if (group && schema == "MaterialBindingAPI") continue;
        if (type == "SphereLight" && schema == "ShapingAPI") continue;
        reader.fail(reader.prim().location, "applies " + quotedName(schema) +
                                                ", which Opal's scene subset does not support on this prim type "
                                                "(see examples/SCENES.md)");
    }
}

// Which common properties a prim takes: an xformOp stack (UsdGeomXformable) and a
// material binding (groups and meshes); nullopt for Material and RenderSettings, which
// take neither (nor visibility).
struct PrimRole {
    bool transformable = false;
    bool bindable = false;
};

std::optional<PrimRole> roleOf(const usda::Prim& prim) {
    const std::string& type = prim.typeName;
    if (type == "Material" || type == "RenderSettings") return std::nullopt;
    if (type == "Scope" || (type.empty() && !isAssetReference(prim))) return PrimRole{false, true};
    if (type == "Xform" || isAssetReference(prim) || appliesSubsurface(prim)) return PrimRole{true, true};
    return PrimRole{true, false};
}

// A material binding in effect (UsdShadeMaterialBindingAPI), and who authored it.
struct Binding {
    hd::SdfPath material;
    usda::SourceLocation where;
    std::string owner;  // "Xform </World>"
    bool strongerThanDescendants = false;
};

// What a prim inherits from its ancestors.
struct Inherited {
    hd::SdfPath path = "/";
    Imath::M44d toWorld;  // the parent's object-to-world matrix
    bool visible = true;
    bool timeVarying = false;  // the prim's own xformOps or an ancestor's are animated
    std::optional<Binding> binding;
};

// Materials and render settings are read once, at load: an animated one would silently
// show one frame (and opal-render's --material override would be lost on a re-read).
void rejectAnimation(const usda::Prim& prim, const PrimReader& reader) {
    for (const usda::Property& p : prim.properties)
        if (const auto* a = std::get_if<usda::Attribute>(&p); a && usda::mightBeTimeVarying(*a))
            reader.failAt(*a, "has timeSamples, which Opal reads on lights, cameras and xformOps only");
}

class SceneReader {
public:
    SceneReader(const std::filesystem::path& file, AssetCache& assets, double timeCode) : assets_(assets) {
        scene_.file = file;
        scene_.timeCode = timeCode;
    }

    Scene read() {
        const usda::Layer layer = composeLayerStack(scene_.file);
        readLayerMetadata(layer);
        for (const usda::Prim& prim : layer.rootPrims) readPrim(prim, Inherited{});
        checkBindings();
        checkRenderCamera();
        for (std::string& warning : assets_.takeWarnings()) scene_.warnings.push_back(std::move(warning));
        return std::move(scene_);
    }

private:
    void readLayerMetadata(const usda::Layer& layer);
    void readPrim(const usda::Prim& prim, const Inherited& parent);
    Inherited readCommon(PrimReader& reader, const Inherited& parent, PrimRole role);
    void readTyped(PrimReader& reader, const Inherited& self);
    void readBinding(PrimReader& reader, Inherited& self);
    void addMesh(PrimReader& reader, const Inherited& self);
    void addLight(PrimReader& reader, const Inherited& self, hd::LightDesc base);
    void addRenderSettings(PrimReader& reader);
    void checkUnitsOf(const SceneMesh& mesh);
    void checkBindings() const;
    void checkRenderCamera() const;

    AssetCache& assets_;
    Scene scene_;
    std::set<std::filesystem::path> unitsChecked_;
    std::vector<Binding> bindings_;  // every one authored, checked once all prims are read
};

void SceneReader::readLayerMetadata(const usda::Layer& layer) {
    if (const usda::Value* up = layer.metadata.find("upAxis")) {
        scene_.upAxis = up->get<usda::types::Token>("metadata 'upAxis'");
        if (scene_.upAxis != "Y" && scene_.upAxis != "Z")
            throw usda::UsdaError(up->location(), "upAxis is '" + scene_.upAxis + "', expected \"Y\" or \"Z\"");
    }
    if (const usda::Value* rate = layer.metadata.find("timeCodesPerSecond")) {
        scene_.timeCodesPerSecond = rate->get<usda::types::Double>("metadata 'timeCodesPerSecond'");
        if (!(scene_.timeCodesPerSecond > 0.0) || !std::isfinite(scene_.timeCodesPerSecond))
            throw usda::UsdaError(rate->location(), "timeCodesPerSecond is " +
                                                        formatNumber(scene_.timeCodesPerSecond) +
                                                        ", expected a positive number");
    }
    for (const auto& [key, field] : {std::pair{"startTimeCode", &Scene::startTimeCode},
                                     std::pair{"endTimeCode", &Scene::endTimeCode}})
        if (const usda::Value* code = layer.metadata.find(key)) {
            const double value = code->get<usda::types::Double>("metadata '" + std::string(key) + "'");
            if (!std::isfinite(value)) throw usda::UsdaError(code->location(), std::string(key) + " is not finite");
            scene_.*field = value;
        }
    if (const usda::Value* mpu = layer.metadata.find("metersPerUnit")) {
        scene_.metersPerUnit = mpu->get<usda::types::Double>("metadata 'metersPerUnit'");
        if (!(*scene_.metersPerUnit > 0.0) || !std::isfinite(*scene_.metersPerUnit))
            throw usda::UsdaError(mpu->location(), "metersPerUnit is " + formatNumber(*scene_.metersPerUnit) +
                                                       ", expected a positive number");
    }
}

void SceneReader::readPrim(const usda::Prim& prim, const Inherited& parent) {
    if (prim.specifier == usda::Specifier::Class) return;  // abstract: never rendered
    const hd::SdfPath path = childPath(parent.path, prim.name);
    if (prim.specifier == usda::Specifier::Over)
        throw usda::UsdaError(prim.location, "over <" + path + ">: no layer of the scene's stack defines this prim "
                                             "(a def in the scene layer or one of its subLayers)");
    if (const usda::Value* active = prim.metadata.find("active"); active && !active->get<usda::types::Bool>("active"))
        return;
    std::optional<usda::Prim> atTime;  // the prim's properties at the scene time, when any is sampled
    if (usda::hasTimeSamples(prim)) atTime = usda::propertiesAt(prim, scene_.timeCode);
    PrimReader reader(atTime ? *atTime : prim, path);
    // A prim that comes and goes would change the render index, not just descriptions.
    if (const usda::Attribute* v = prim.findAttribute("visibility"); v && usda::mightBeTimeVarying(*v))
        reader.failAt(*v, "has timeSamples; animated visibility is not supported");
    if (!isSupportedType(prim.typeName))
        reader.fail(prim.location, "unsupported prim type " + quotedName(prim.typeName) + " (Opal's scene subset: " +
                                       SupportedTypes + "; see examples/SCENES.md)");
    Inherited self = parent;
    if (const std::optional<PrimRole> role = roleOf(prim)) self = readCommon(reader, parent, *role);
    else rejectAnimation(prim, reader);
    self.path = path;
    self.timeVarying = parent.timeVarying || usda::mightBeTimeVarying(prim);
    readTyped(reader, self);
    reader.finish();
    for (const usda::Prim& child : prim.children) readPrim(child, self);
}

// Transformation, visibility and material binding, as the prim's role allows.
Inherited SceneReader::readCommon(PrimReader& reader, const Inherited& parent, PrimRole role) {
    Inherited self = parent;
    if (role.transformable) {
        const LocalTransform local = readLocalTransform(reader);
        self.toWorld = local.resetsXformStack ? local.matrix : local.matrix * parent.toWorld;
    } else {
        rejectTransform(reader);
    }
    if (const usda::Attribute* visibility = reader.find("visibility", {usda::types::Token})) {
        const std::string& value = std::get<std::string>(visibility->value->data());
        if (value != "inherited" && value != "invisible")
            reader.failAt(*visibility, "is " + quotedName(value) + ", expected \"inherited\" or \"invisible\"");
        self.visible = parent.visible && value == "inherited";
    }
    if (role.bindable) readBinding(reader, self);
    return self;
}

void SceneReader::readBinding(PrimReader& reader, Inherited& self) {
    const usda::Relationship* rel = reader.relationship("material:binding");
    if (!rel || !rel->targets || rel->targets->empty()) return;
    if (rel->targets->size() != 1)
        reader.failAt(*rel, "has " + std::to_string(rel->targets->size()) + " targets, expected one Material");
    Binding binding;
    try {
        binding.material = resolveTargetPath(reader.path(), rel->targets->front());
    } catch (const Error& e) {
        reader.failAt(*rel, e.what());
    }
    binding.where = rel->location;
    binding.owner = reader.describe();
    if (const usda::Value* strength = rel->metadata.find("bindMaterialAs")) {
        const std::string& value = strength->get<usda::types::Token>("bindMaterialAs");
        if (value != "strongerThanDescendants" && value != "weakerThanDescendants")
            reader.failAt(*rel, "has bindMaterialAs " + quotedName(value) +
                                    ", expected \"strongerThanDescendants\" or \"weakerThanDescendants\"");
        binding.strongerThanDescendants = value == "strongerThanDescendants";
    }
    bindings_.push_back(binding);
    if (!self.binding || !self.binding->strongerThanDescendants) self.binding = std::move(binding);
}

void SceneReader::readTyped(PrimReader& reader, const Inherited& self) {
    const std::string& type = reader.prim().typeName;
    const bool reference = isAssetReference(reader.prim());
    if (reference && (type.empty() || type == "Mesh")) return addMesh(reader, self);
    if (!reference && appliesSubsurface(reader.prim())) return addMesh(reader, self);
    if (reference && type == kShadowFieldLightType) {
        ReferencedLight referenced = referencedLight(reader, scene_.file, scene_.timeCode);
        Inherited light = self;
        light.timeVarying = self.timeVarying || referenced.timeVarying;
        return addLight(reader, light, std::move(referenced.desc));
    }
    if (reference)
        reader.fail(reader.prim().location, "references an asset, but its stronger type '" + type +
                                                "' would replace the asset's Mesh (as in USD): use def \"Name\" or "
                                                "def Mesh \"Name\"");
    checkApiSchemas(reader);
    if (type.empty() || type == "Scope" || type == "Xform") return;
    if (type == "Mesh")
        reader.fail(reader.prim().location, "is a Mesh without a reference: Opal renders baked translucent assets "
                                            "(references = @./asset.usda@, or an over-layer from opal-bake "
                                            "--apply-to sublayered over this layer)");
    if (type == "Material") {
        scene_.materials[self.path] = {readMaterial(reader), reader.prim().location};
    } else if (lightTypeOf(type)) {
        addLight(reader, self, {});
    } else if (type == "Camera") {
        scene_.cameras[self.path] = {readCamera(reader, self.toWorld), reader.prim().location};
        if (self.timeVarying) scene_.timeVarying.insert(self.path);
    } else {
        addRenderSettings(reader);
    }
}

void SceneReader::addMesh(PrimReader& reader, const Inherited& self) {
    if (self.timeVarying) scene_.timeVarying.insert(self.path);
    SceneMesh mesh = isAssetReference(reader.prim()) ? readMesh(reader, self.toWorld, scene_.file, assets_)
                                                     : readAppliedAssetMesh(reader, self.toWorld, scene_.file, assets_);
    mesh.desc.visible = self.visible;
    if (self.binding) {
        mesh.desc.material = self.binding->material;
    }
    checkUnitsOf(mesh);
    scene_.meshes[self.path] = std::move(mesh);
}

void SceneReader::addLight(PrimReader& reader, const Inherited& self, hd::LightDesc base) {
    const LightType light = lightTypeOf(reader.prim().typeName).value();
    hd::LightDesc desc = readLight(reader, self.toWorld, scene_.file, std::move(base));
    if (!self.visible) return;
    scene_.lights[self.path] = {light.primType, std::move(desc), reader.prim().location};
    if (self.timeVarying) scene_.timeVarying.insert(self.path);
}

void SceneReader::addRenderSettings(PrimReader& reader) {
    if (scene_.renderSettings)
        reader.fail(reader.prim().location, "is a second RenderSettings prim (the first is <" +
                                                scene_.renderSettings->path + "> at " +
                                                scene_.renderSettings->where.str() + ")");
    scene_.renderSettings = readRenderSettings(reader, scene_.file);
}

// USD does not rescale references between layers of different units, and neither does
// Opal: a mismatch is worth a warning, since the asset then appears at the wrong size.
void SceneReader::checkUnitsOf(const SceneMesh& mesh) {
    if (!scene_.metersPerUnit || !unitsChecked_.insert(mesh.assetFile).second) return;
    const double assetMetersPerUnit = 0.001 / mesh.desc.asset->unitsPerMm;
    if (std::abs(assetMetersPerUnit / *scene_.metersPerUnit - 1.0) > 1e-6)
        scene_.warnings.push_back(mesh.where.str() + ": the scene has metersPerUnit " +
                                  formatNumber(*scene_.metersPerUnit) + " but " + mesh.assetFile.string() + " has " +
                                  formatNumber(assetMetersPerUnit) +
                                  "; references are not rescaled (author an xformOp:scale to convert)");
}

void SceneReader::checkBindings() const {
    for (const Binding& binding : bindings_) {
        if (scene_.materials.count(binding.material)) continue;
        throw usda::UsdaError(binding.where, binding.owner + ": relationship 'material:binding' targets <" +
                                                 binding.material + ">, which is not a Material prim of the scene");
    }
}

void SceneReader::checkRenderCamera() const {
    const std::optional<SceneRenderSettings>& settings = scene_.renderSettings;
    if (!settings || !settings->camera || scene_.cameras.count(*settings->camera)) return;
    throw usda::UsdaError(settings->cameraWhere, "RenderSettings <" + settings->path +
                                                     ">: relationship 'camera' targets <" + *settings->camera +
                                                     ">, which is not a Camera prim of the scene");
}

}  // namespace

Scene readScene(const std::filesystem::path& file, AssetCache& assets, double timeCode) {
    return SceneReader(file, assets, timeCode).read();
}

}  // namespace opal::scene
