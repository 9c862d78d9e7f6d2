#include "examples/opal-view/core/usda_export.h"

#include "examples/opal-view/core/scene_document.h"
#include "schema/error.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"
#include "schema/usd/xform_op.h"

#include <functional>

namespace opal::view {
namespace {

using usda::Value;
namespace types = usda::types;

// Where the viewer's own prims go: "/OpalView", or "/OpalView2", ... when the scene uses it.
std::string savedViewerRoot(const scene::Scene& scene) {
    std::set<std::string> roots;
    const auto collect = [&](const auto& prims) {
        for (const auto& entry : prims) roots.insert(entry.first.substr(0, entry.first.find('/', 1)));
    };
    collect(scene.meshes);
    collect(scene.materials);
    collect(scene.lights);
    collect(scene.cameras);
    if (scene.renderSettings) roots.insert(scene.renderSettings->path.substr(0, scene.renderSettings->path.find('/', 1)));
    std::string root = "/OpalView";
    for (int n = 2; roots.count(root); ++n) root = "/OpalView" + std::to_string(n);
    return root;
}

class PathMap {
public:
    explicit PathMap(std::string root) : root_(std::move(root)) {}
    hd::SdfPath operator()(const hd::SdfPath& path) const {
        if (path == ViewerRoot) return root_;
        if (path.starts_with(ViewerRoot + "/")) return root_ + path.substr(ViewerRoot.size());
        return path;
    }

private:
    std::string root_;
};

// The prim at `path` in `layer`, made (with typeless groups above it) when missing.
usda::Prim& primAt(usda::Layer& layer, const hd::SdfPath& path) {
    std::vector<usda::Prim>* siblings = &layer.rootPrims;
    usda::Prim* prim = nullptr;
    for (std::size_t start = 1; start <= path.size();) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        const std::string name = path.substr(start, end - start);
        auto it = std::find_if(siblings->begin(), siblings->end(), [&](const usda::Prim& p) { return p.name == name; });
        if (it == siblings->end()) {
            usda::Prim group;
            group.name = name;
            siblings->push_back(std::move(group));
            it = siblings->end() - 1;
        }
        prim = &*it;
        siblings = &prim->children;
        start = end + 1;
    }
    if (!prim) throw Error("cannot write a prim at <" + path + ">");
    return *prim;
}

// `file` as an asset path anchored at `target`'s folder: "./x" when it lies beside or below
// it, "../x" when a relative path reaches it, the absolute path otherwise.
std::string anchored(const std::filesystem::path& file, const std::filesystem::path& target) {
    const std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
    const std::filesystem::path folder = std::filesystem::absolute(target).parent_path().lexically_normal();
    const std::filesystem::path relative = absolute.lexically_relative(folder);
    if (relative.empty() || relative.is_absolute()) return absolute.generic_string();
    const std::string text = relative.generic_string();
    return text.starts_with("..") ? text : "./" + text;
}

usda::Vec3f color(const Rgb& c) { return {float(c[0]), float(c[1]), float(c[2])}; }

void place(usda::Prim& prim, const Imath::M44d& m) {
    usda::Matrix4d rows;
    for (int r = 0; r < 4; ++r) rows[r] = {m[r][0], m[r][1], m[r][2], m[r][3]};
    prim.addAttribute("xformOp:transform", Value::make<types::Matrix4d>(rows));
    prim.addAttribute("xformOpOrder",
                      Value::make<types::TokenArray>({std::string(usda::kResetXformStack), "xformOp:transform"}), true);
}

void addFloat(usda::Prim& prim, const char* name, double value) {
    prim.addAttribute(name, Value::make<types::Float>(float(value)));
}

void writeMesh(usda::Layer& layer, const PathMap& map, const hd::SdfPath& path, const scene::SceneMesh& mesh,
               const std::filesystem::path& target) {
    // A reference to an over-layer would not load (its prims are overs, it names no
    // defaultPrim); writing the layer stack back is not done yet.
    if (mesh.applied)
        throw Error(target.string() + ": cannot save " + path + ": its asset is applied through an over-layer "
                    "(subLayers), which the saved layer cannot yet reproduce");
    usda::Prim& prim = primAt(layer, map(path));
    prim.references.prepended.push_back({anchored(mesh.assetFile, target), "", {}});
    if (!mesh.desc.material.empty()) {
        prim.apiSchemas.prepended.push_back("MaterialBindingAPI");
        prim.addRelationship("material:binding", {map(mesh.desc.material)});
    }
    if (!mesh.desc.visible) prim.addAttribute("visibility", Value::token("invisible"));
    place(prim, mesh.desc.transform);
}

void writeMaterial(usda::Layer& layer, const PathMap& map, const hd::SdfPath& path, const hd::MaterialDesc& desc,
                   const usda::Prim* authored) {
    usda::Prim& prim = primAt(layer, map(path));
    prim.typeName = "Material";
    if (authored) {
        prim.properties = authored->properties;
        return;
    }
    prim.addAttribute("opal:sigmaSPrime", Value::make<types::Color3f>(color(desc.subsurface.sigmaSPrime)));
    prim.addAttribute("opal:sigmaA", Value::make<types::Color3f>(color(desc.subsurface.sigmaA)));
    addFloat(prim, "opal:eta", desc.subsurface.eta);
    prim.addAttribute("opal:specular", Value::make<types::Bool>(desc.specular));
    addFloat(prim, "opal:specularRoughness", desc.specularRoughness);
}

const char* lightTypeName(hd::LightKind kind) {
    switch (kind) {
    case hd::LightKind::Sphere: return "SphereLight";
    case hd::LightKind::Distant: return "DistantLight";
    case hd::LightKind::Dome: return "DomeLight";
    case hd::LightKind::ShadowField: return "OpalShadowFieldLight";
    }
    return "";
}

void writeLightKind(usda::Prim& prim, const hd::LightDesc& light, const std::filesystem::path& target) {
    switch (light.kind) {
    case hd::LightKind::Sphere:
        addFloat(prim, "inputs:radius", light.radius);
        prim.addAttribute("treatAsPoint", Value::make<types::Bool>(light.treatAsPoint));
        if (light.shapingConeAngle) {
            prim.apiSchemas.prepended.push_back("ShapingAPI");
            addFloat(prim, "inputs:shaping:cone:angle", *light.shapingConeAngle);
            addFloat(prim, "inputs:shaping:cone:softness", light.shapingConeSoftness);
        }
        break;
    case hd::LightKind::Distant: addFloat(prim, "inputs:angle", light.angle); break;
    case hd::LightKind::Dome:
        if (!light.textureFile.empty()) {
            usda::Attribute& file = prim.addAttribute("inputs:texture:file", Value::asset(anchored(light.textureFile, target)));
            file.metadata.set("colorSpace", Value::token(light.textureColorSpace));
        }
        prim.addAttribute("opal:visibleToCamera", Value::make<types::Bool>(light.visibleToCamera));
        break;
    case hd::LightKind::ShadowField:
        prim.addAttribute("opal:field", Value::asset(anchored(light.shadowField, target)));
        addFloat(prim, "opal:flicker:amplitude", light.flicker.amplitude);
        addFloat(prim, "opal:flicker:frequency", light.flicker.frequency);
        prim.addAttribute("opal:flicker:seed", Value::make<types::Int>(std::int32_t(std::uint32_t(light.flicker.seed))));
        break;
    }
}

void writeLight(usda::Layer& layer, const PathMap& map, const hd::SdfPath& path, const hd::LightDesc& light,
                bool disabled, const std::filesystem::path& target) {
    usda::Prim& prim = primAt(layer, map(path));
    prim.typeName = lightTypeName(light.kind);
    addFloat(prim, "inputs:intensity", light.intensity);
    addFloat(prim, "inputs:exposure", light.exposure);
    prim.addAttribute("inputs:color", Value::make<types::Color3f>(color(light.color)));
    prim.addAttribute("inputs:normalize", Value::make<types::Bool>(light.normalize));
    if (light.enableColorTemperature) {
        prim.addAttribute("inputs:enableColorTemperature", Value::make<types::Bool>(true));
        addFloat(prim, "inputs:colorTemperature", light.colorTemperature);
    }
    writeLightKind(prim, light, target);
    // The reader leaves an invisible light out of the render: a disabled light stays in the
    // layer, switched off.
    if (disabled) prim.addAttribute("visibility", Value::token("invisible"));
    place(prim, light.transform);
}

void writeCamera(usda::Layer& layer, const PathMap& map, const hd::SdfPath& path, const hd::CameraDesc& camera) {
    usda::Prim& prim = primAt(layer, map(path));
    prim.typeName = "Camera";
    addFloat(prim, "focalLength", camera.focalLength);
    addFloat(prim, "horizontalAperture", camera.horizontalAperture);
    addFloat(prim, "verticalAperture", camera.verticalAperture);
    prim.addAttribute("clippingRange", Value::make<types::Float2>({float(camera.nearClip), float(camera.farClip)}));
    place(prim, camera.transform);
}

Value settingValue(const hd::Token& key, const hd::Value& value) {
    if (const bool* b = std::get_if<bool>(&value)) return Value::make<types::Bool>(*b);
    if (const int* i = std::get_if<int>(&value)) return Value::make<types::Int>(*i);
    if (const double* d = std::get_if<double>(&value)) return Value::make<types::Double>(*d);
    if (const std::string* s = std::get_if<std::string>(&value)) return Value::string(*s);
    throw Error("render setting '" + key + "' has a type a scene layer cannot author");
}

void writeRenderSettings(usda::Layer& layer, const PathMap& map, const SceneExport& in) {
    const hd::SdfPath path = in.scene.renderSettings ? in.scene.renderSettings->path : map(ViewerRoot) + "/RenderSettings";
    usda::Prim& prim = primAt(layer, path);
    prim.typeName = "RenderSettings";
    prim.addAttribute("resolution", Value::make<types::Int2>({in.width, in.height}), true);
    prim.addRelationship("camera", {map(in.camera)});
    for (const auto& [key, value] : in.settings) prim.addAttribute(key, settingValue(key, value));
}

void writeLayerMetadata(usda::Layer& layer, const SceneExport& in) {
    const scene::Scene& scene = in.scene;
    layer.metadata.set("doc", Value::string("Saved by opal-view from " + scene.file.filename().string()));
    if (scene.metersPerUnit) layer.metadata.set("metersPerUnit", Value::make<types::Double>(*scene.metersPerUnit));
    layer.metadata.set("upAxis", Value::token(scene.upAxis));
    if (scene.timeCodesPerSecond != 24.0)
        layer.metadata.set("timeCodesPerSecond", Value::make<types::Double>(scene.timeCodesPerSecond));
}

void collectMaterials(const usda::Prim& prim, const hd::SdfPath& parent, std::map<hd::SdfPath, usda::Prim>& out) {
    const hd::SdfPath path = parent + "/" + prim.name;
    if (prim.typeName == "Material") out[path] = prim;
    for (const usda::Prim& child : prim.children) collectMaterials(child, path, out);
}

}  // namespace

usda::Layer exportLayer(const SceneExport& in, const std::filesystem::path& target) {
    const PathMap map(savedViewerRoot(in.scene));
    usda::Layer layer;
    writeLayerMetadata(layer, in);
    for (const auto& [path, mesh] : in.scene.meshes) writeMesh(layer, map, path, mesh, target);
    for (const auto& [path, material] : in.scene.materials) {
        const auto authored = in.authoredMaterials.find(path);
        writeMaterial(layer, map, path, material.desc, authored == in.authoredMaterials.end() ? nullptr : &authored->second);
    }
    for (const auto& [path, light] : in.scene.lights)
        writeLight(layer, map, path, light.desc, in.disabledLights.count(path) > 0, target);
    for (const auto& [path, camera] : in.scene.cameras) writeCamera(layer, map, path, camera.desc);
    writeRenderSettings(layer, map, in);
    return layer;
}

void saveSceneLayer(const SceneExport& scene, const std::filesystem::path& target) {
    usda::Layer layer;
    try {
        layer = exportLayer(scene, target);
    } catch (const Error& e) {
        throw Error(target.string() + ": " + e.what());
    }
    usda::writeUsdaFile(target, layer);
}

std::map<hd::SdfPath, usda::Prim> authoredMaterialPrims(const std::filesystem::path& file) {
    std::map<hd::SdfPath, usda::Prim> materials;
    for (const usda::Prim& prim : usda::readUsdaFile(file).rootPrims) collectMaterials(prim, "", materials);
    return materials;
}

}  // namespace opal::view
