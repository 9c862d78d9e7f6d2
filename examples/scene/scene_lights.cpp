#include "examples/scene/scene_lights.h"

#include "examples/scene/layer_reference.h"
#include "schema/usd/time_samples.h"
#include "schema/usd/usda_reader.h"

#include <algorithm>
#include <array>

namespace opal::scene {
namespace {

using namespace usda::types;

constexpr double DistantLightIntensityFallback = 50000.0;  // UsdLux's DistantLight override

// LightAPI's inputs, and the standard ones Opal accepts only at their fallback.
void readLightApi(PrimReader& reader, hd::LightDesc& desc) {
    desc.intensity = reader.real("inputs:intensity", Float, Bounds::atLeast(0.0)).value_or(desc.intensity);
    desc.exposure = reader.real("inputs:exposure", Float).value_or(desc.exposure);
    desc.color = reader.color("inputs:color", Bounds::atLeast(0.0)).value_or(desc.color);
    desc.normalize = reader.get<Bool>("inputs:normalize").value_or(desc.normalize);
    reader.requireFallback<Float>("inputs:diffuse", 1.0f, "per-light diffuse multipliers are not implemented");
    reader.requireFallback<Float>("inputs:specular", 1.0f, "per-light specular multipliers are not implemented");
    desc.enableColorTemperature =
        reader.get<Bool>("inputs:enableColorTemperature").value_or(desc.enableColorTemperature);
    desc.colorTemperature =
        reader.real("inputs:colorTemperature", Float, Bounds::closed(500.0, 40000.0)).value_or(desc.colorTemperature);
    reader.requireFallback<Bool>("collection:lightLink:includeRoot", true, "light linking is not implemented");
    reader.requireFallback<Bool>("collection:shadowLink:includeRoot", true, "shadow linking is not implemented");
    reader.ignore("light:shaderId");
}

// inputs:shaping:cone:<name>, or its pre-USD-21.05 spelling shaping:cone:<name>.
std::optional<double> shapingInput(PrimReader& reader, std::string_view name, Bounds bounds) {
    const std::string current = "inputs:shaping:cone:" + std::string(name), old = "shaping:cone:" + std::string(name);
    const std::optional<double> a = reader.real(current, Float, bounds), b = reader.real(old, Float, bounds);
    if (a && b) reader.failAt(*reader.find(old, {Float}), "repeats " + quotedName(current) + " (author one spelling)");
    return a ? a : b;
}

void readSphere(PrimReader& reader, hd::LightDesc& desc) {
    desc.radius = reader.real("inputs:radius", Float, Bounds::atLeast(0.0)).value_or(desc.radius);
    desc.treatAsPoint = reader.get<Bool>("treatAsPoint").value_or(desc.treatAsPoint);
    desc.shapingConeAngle = shapingInput(reader, "angle", Bounds::closed(0.0, MaxConeAngle));
    desc.shapingConeSoftness = shapingInput(reader, "softness", Bounds::closed(0.0, MaxConeSoftness)).value_or(0.0);
    reader.requireFallback<Float>("inputs:shaping:focus", 0.0f, "shaping focus is not implemented");
}

void readDistant(PrimReader& reader, hd::LightDesc& desc) {
    desc.angle = reader.real("inputs:angle", Float, Bounds::closed(0.0, MaxDistantAngle)).value_or(desc.angle);
    if (!reader.find("inputs:intensity", {Float})) desc.intensity = DistantLightIntensityFallback;
}

void readDome(PrimReader& reader, hd::LightDesc& desc, const std::filesystem::path& layerFile) {
    if (const auto file = reader.existingFile("inputs:texture:file", layerFile)) {
        desc.textureFile = file->string();
        const usda::Value* space = reader.find("inputs:texture:file", {Asset})->metadata.find("colorSpace");
        if (space) desc.textureColorSpace = space->get<Token>("colorSpace metadata");
    }
    if (const usda::Attribute* format = reader.find("inputs:texture:format", {Token})) {
        const std::string& value = std::get<std::string>(format->value->data());
        if (value != "latlong" && value != "automatic")
            reader.failAt(*format, "is " + quotedName(value) + "; Opal reads lat-long images only (\"latlong\")");
    }
    // UsdLux has no camera visibility for a dome; Opal's own attribute (opal-view's
    // "show as background" switch saves it).
    desc.visibleToCamera = reader.get<Bool>("opal:visibleToCamera").value_or(desc.visibleToCamera);
    reader.ignore("guideRadius");  // viewport display only
}

void readShadowField(PrimReader& reader, hd::LightDesc& desc, const std::filesystem::path& layerFile) {
    const auto field = reader.existingFile("opal:field", layerFile);
    if (field) desc.shadowField = field->string();
    if (desc.shadowField.empty())
        reader.fail(reader.prim().location, "needs opal:field, the light asset holding its shadow field");
    desc.flicker.amplitude =
        reader.real("opal:flicker:amplitude", Float, Bounds::closed(0.0, 1.0)).value_or(desc.flicker.amplitude);
    desc.flicker.frequency =
        reader.real("opal:flicker:frequency", Float, Bounds::closed(0.0, 1000.0)).value_or(desc.flicker.frequency);
    if (const auto seed = reader.get<Int>("opal:flicker:seed")) desc.flicker.seed = std::uint64_t(std::uint32_t(*seed));
}

}  // namespace

std::optional<LightType> lightTypeOf(std::string_view usdTypeName) {
    static const std::array<std::pair<std::string_view, LightType>, 4> types = {{
        {"SphereLight", {hd::PrimType::SphereLight, hd::LightKind::Sphere}},
        {"DistantLight", {hd::PrimType::DistantLight, hd::LightKind::Distant}},
        {"DomeLight", {hd::PrimType::DomeLight, hd::LightKind::Dome}},
        {"OpalShadowFieldLight", {hd::PrimType::ShadowFieldLight, hd::LightKind::ShadowField}},
    }};
    for (const auto& [name, type] : types)
        if (name == usdTypeName) return type;
    return std::nullopt;
}

hd::LightDesc readLight(PrimReader& reader, const Imath::M44d& objectToWorld, const std::filesystem::path& layerFile,
                        hd::LightDesc base) {
    hd::LightDesc desc = std::move(base);
    desc.kind = lightTypeOf(reader.prim().typeName).value().kind;
    desc.transform = objectToWorld;
    readLightApi(reader, desc);
    switch (desc.kind) {
        case hd::LightKind::Sphere: readSphere(reader, desc); break;
        case hd::LightKind::Distant: readDistant(reader, desc); break;
        case hd::LightKind::Dome: readDome(reader, desc, layerFile); break;
        case hd::LightKind::ShadowField: readShadowField(reader, desc, layerFile); break;
    }
    return desc;
}

ReferencedLight referencedLight(PrimReader& reader, const std::filesystem::path& layerFile, double timeCode) {
    const LayerReference referenced =
        referencedLayer(reader, layerFile, "a light references exactly one baked light layer");
    const usda::Reference& reference = *referenced.reference;
    const std::filesystem::path& file = referenced.file;
    const usda::Layer layer = usda::readUsdaFile(file);
    const std::string name = reference.primPath.empty() ? layer.defaultPrim() : reference.primPath.substr(1);
    const auto prim = std::find_if(layer.rootPrims.begin(), layer.rootPrims.end(),
                                   [&](const usda::Prim& p) { return p.name == name; });
    if (prim == layer.rootPrims.end() || prim->typeName != reader.prim().typeName)
        reader.fail(reader.prim().location, "references @" + reference.assetPath + "@, which has no " +
                                                reader.prim().typeName + " prim </" + name + ">");
    const usda::Prim atTime = usda::propertiesAt(*prim, timeCode);
    PrimReader light(atTime, "/" + name);
    hd::LightDesc desc = readLight(light, Imath::M44d(), file);
    light.ignore("opal:bakeId");  // the layer's record of its bake (the sidecar checks it)
    light.finish();
    return {std::move(desc), usda::mightBeTimeVarying(*prim)};
}

}  // namespace opal::scene
