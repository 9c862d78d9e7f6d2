#include "schema/asset/asset_layer.h"

#include "schema/asset/bake_id.h"
#include "schema/asset/display_color.h"
#include "schema/asset/point_range.h"
#include "schema/asset/sidecar.h"
#include "schema/asset/sidecar_checks.h"
#include "schema/error.h"
#include "schema/usd/usda_error.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <Imath/ImathBox.h>

#include <cctype>

namespace opal {

namespace {

using usda::Value;
namespace types = usda::types;

usda::Vec3f toVec(const Imath::V3f& v) { return {v.x, v.y, v.z}; }
usda::Vec3f toColor(const Rgb& c) { return {float(c[0]), float(c[1]), float(c[2])}; }

std::vector<usda::Vec3f> toVecs(const std::vector<Imath::V3f>& points) {
    std::vector<usda::Vec3f> out;
    out.reserve(points.size());
    for (const Imath::V3f& p : points) out.push_back(toVec(p));
    return out;
}

std::vector<Imath::V3f> fromVecs(const std::vector<usda::Vec3f>& points) {
    std::vector<Imath::V3f> out;
    out.reserve(points.size());
    for (const usda::Vec3f& p : points) out.emplace_back(p[0], p[1], p[2]);
    return out;
}

void addMesh(usda::Prim& prim, const RenderMesh& mesh) {
    Imath::Box3f box;
    for (const Imath::V3f& p : mesh.points) box.extendBy(p);
    prim.addAttribute("extent", Value::make<types::Float3Array>({toVec(box.min), toVec(box.max)}));
    prim.addAttribute("faceVertexCounts", Value::make<types::IntArray>(mesh.faceVertexCounts));
    prim.addAttribute("faceVertexIndices", Value::make<types::IntArray>(mesh.faceVertexIndices));
    usda::Attribute& normals = prim.addAttribute("normals", Value::make<types::Normal3fArray>(toVecs(mesh.normals)));
    normals.metadata.set("interpolation", Value::token("vertex"));
    prim.addAttribute("orientation", Value::token("rightHanded"), true);
    prim.addAttribute("points", Value::make<types::Point3fArray>(toVecs(mesh.points)));
    // The render mesh is already the refined limit surface: USD must not subdivide again.
    prim.addAttribute("subdivisionScheme", Value::token("none"), true);
}

// The preview for hosts without Opal (display_color.h); Opal itself never reads it.
void addDisplayColor(usda::Prim& prim, const TranslucentAsset& asset) {
    const std::vector<Imath::V3f> colors = displayColors(asset);
    if (colors.empty()) return;
    std::vector<usda::Vec3f> values;
    values.reserve(colors.size());
    for (const Imath::V3f& c : colors) values.push_back(toVec(c));
    usda::Attribute& color = prim.addAttribute("primvars:displayColor", Value::make<types::Color3fArray>(std::move(values)));
    color.metadata.set("interpolation", Value::token("vertex"));
}

void addSubsurface(usda::Prim& prim, const TranslucentAsset& asset, const std::string& sidecar) {
    const Material& m = asset.defaultMaterial;
    prim.addAttribute("opal:eta", Value::make<types::Float>(float(m.eta)));
    prim.addAttribute("opal:sigmaA", Value::make<types::Color3f>(toColor(m.sigmaA)));
    prim.addAttribute("opal:sigmaSPrime", Value::make<types::Color3f>(toColor(m.sigmaSPrime)));
    prim.addAttribute("opal:unitsPerMm", Value::make<types::Double>(asset.unitsPerMm), true);
    const EditableRange& r = asset.range;
    prim.addAttribute("opal:range:sigmaSPrime", Value::make<types::Double2>({r.sigmaSPrimeMin, r.sigmaSPrimeMax}), true);
    prim.addAttribute("opal:range:sigmaA", Value::make<types::Double2>({r.sigmaAMin, r.sigmaAMax}), true);
    prim.addAttribute("opal:range:eta", Value::make<types::Double2>({r.etaMin, r.etaMax}), true);
    const ProfileBasis& b = asset.basis;
    prim.addAttribute("opal:basis:K", Value::make<types::Int>(b.K()), true);
    const auto doubles = [](std::span<const double> v) { return std::vector<double>(v.begin(), v.end()); };
    prim.addAttribute("opal:basis:eigenvalues", Value::make<types::DoubleArray>(doubles(b.eigenvalues())), true);
    prim.addAttribute("opal:basis:radii", Value::make<types::DoubleArray>(doubles(b.radii())), true);
    prim.addAttribute("opal:basis:weights", Value::make<types::DoubleArray>(doubles(b.weights())), true);
    prim.addAttribute("opal:basis:values", Value::make<types::DoubleArray>(doubles(b.values())), true);
    prim.addAttribute("opal:sidecar", Value::asset(sidecar), true);
    if (asset.bake.identifier)
        prim.addAttribute(std::string(kBakeIdAttribute), Value::string(formatBakeId(*asset.bake.identifier)), true);
}

std::optional<std::uint64_t> readBakeIdAttribute(const usda::Prim& prim) {
    const usda::Attribute* attribute = prim.findAttribute(kBakeIdAttribute);
    if (!attribute) return std::nullopt;
    const std::string& text = attribute->get<types::String>();
    const std::optional<std::uint64_t> id = parseBakeId(text);
    if (!id)
        throw Error(attribute->location.str() + ": " + std::string(kBakeIdAttribute) + " is \"" + text +
                    "\", expected " + std::to_string(kBakeIdDigits) + " lowercase hexadecimal digits");
    return id;
}

std::string idText(const std::optional<std::uint64_t>& id) { return id ? formatBakeId(*id) : "none"; }

// Both halves carry the bake's identifier and they agree; or neither does: an asset
// baked before the identifier existed loads with one warning.
void checkSameBake(const std::filesystem::path& usdaPath, const std::filesystem::path& sidecarPath,
                   const std::optional<std::uint64_t>& layerId, const std::optional<std::uint64_t>& sidecarId,
                   std::vector<std::string>* warnings) {
    if (layerId == sidecarId) {
        if (!layerId && warnings)
            warnings->push_back(usdaPath.string() + ": asset baked before Opal recorded bake identifiers: its layer "
                                "and its sidecar " + sidecarPath.filename().string() +
                                " cannot be checked to come from the same bake; re-bake it with opal-bake");
        return;
    }
    throw Error("sidecar and layer are not from the same bake: " + usdaPath.string() + " has bake id " +
                idText(layerId) + ", " + sidecarPath.lexically_normal().string() + " has bake id " + idText(sidecarId) +
                " (re-bake the asset)");
}

usda::Dictionary bakeDictionary(const BakeSettings& bake) {
    usda::Dictionary d;
    d.set("envError", Value::make<types::Double>(bake.envError));
    d.set("envTerms", Value::make<types::UInt>(bake.envTerms));
    d.set("level", Value::make<types::UInt>(bake.level));
    d.set("scheme", Value::token(bake.scheme));
    d.set("seed", Value::make<types::UInt64>(bake.seed));
    d.set("source", Value::string(bake.source));
    return d;
}

Rgb toRgb(const usda::Vec3f& c) { return Rgb(c[0], c[1], c[2]); }

BakeSettings readBakeSettings(const usda::Prim& prim) {
    BakeSettings bake;
    const usda::Dictionary* custom = prim.customData();
    const usda::Value* dict = custom ? custom->find("opalBake") : nullptr;
    if (!dict) return bake;
    const usda::Dictionary& d = dict->get<types::Dictionary>("customData 'opalBake'");
    if (const Value* v = d.find("envError")) bake.envError = v->get<types::Double>("opalBake 'envError'");
    if (const Value* v = d.find("envTerms")) bake.envTerms = v->get<types::UInt>("opalBake 'envTerms'");
    if (const Value* v = d.find("level")) bake.level = v->get<types::UInt>("opalBake 'level'");
    if (const Value* v = d.find("scheme")) bake.scheme = v->get<types::Token>("opalBake 'scheme'");
    if (const Value* v = d.find("seed")) bake.seed = v->get<types::UInt64>("opalBake 'seed'");
    if (const Value* v = d.find("source")) bake.source = v->get<types::String>("opalBake 'source'");
    return bake;
}

std::string where(const usda::Prim& prim) { return prim.location.str(); }

}  // namespace

std::string assetNameFrom(std::string_view text) {
    std::string out;
    for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "_" + out;
    return out;
}

usda::Layer assetToLayer(const TranslucentAsset& asset, const std::string& sidecarAssetPath) {
    usda::Prim prim;
    prim.specifier = usda::Specifier::Def;
    prim.typeName = "Mesh";
    if (asset.name != assetNameFrom(asset.name))
        throw Error("asset name '" + asset.name + "' is not a prim name (it would be '" + assetNameFrom(asset.name) +
                    "'; name assets with assetNameFrom)");
    prim.name = asset.name;
    prim.apiSchemas.prepended = {std::string(kSubsurfaceApi)};
    prim.metadata.set("kind", Value::token("component"));
    usda::Dictionary custom;
    custom.set("opalBake", Value::dictionary(bakeDictionary(asset.bake)));
    prim.metadata.set("customData", Value::dictionary(std::move(custom)));
    addMesh(prim, asset.mesh);
    addDisplayColor(prim, asset);
    addSubsurface(prim, asset, sidecarAssetPath);

    usda::Layer layer;
    layer.metadata.set("doc", Value::string("Opal translucent asset baked from " + asset.bake.source));
    layer.metadata.set("defaultPrim", Value::token(prim.name));
    layer.metadata.set("metersPerUnit", Value::make<types::Double>(0.001 / asset.unitsPerMm));
    layer.metadata.set("upAxis", Value::token("Y"));
    layer.addRootPrim(std::move(prim));
    return layer;
}

void writeAssetLayer(const std::filesystem::path& usdaPath, const TranslucentAsset& asset,
                     const std::string& sidecarAssetPath) {
    usda::writeUsdaFile(usdaPath, assetToLayer(asset, sidecarAssetPath));
}

std::span<const std::string_view> assetPrimAttributes() {
    static constexpr std::string_view attributes[] = {
        "opal:eta",         "opal:sigmaA",        "opal:sigmaSPrime",       "opal:unitsPerMm",   "opal:range:sigmaSPrime",
        "opal:range:sigmaA", "opal:range:eta",    "opal:basis:K",           "opal:basis:eigenvalues",
        "opal:basis:radii", "opal:basis:weights", "opal:basis:values",      "opal:sidecar",      kBakeIdAttribute,
        "points",           "normals",            "faceVertexCounts",       "faceVertexIndices"};
    return attributes;
}

std::string primToAsset(const usda::Prim& prim, TranslucentAsset& asset) {
    if (!prim.hasApiSchema(kSubsurfaceApi))
        throw Error(where(prim) + ": prim '" + prim.name + "' does not apply " + std::string(kSubsurfaceApi));
    asset.name = prim.name;
    asset.mesh.points = fromVecs(prim.requiredValue<types::Point3fArray>("points"));
    asset.mesh.normals = fromVecs(prim.requiredValue<types::Normal3fArray>("normals"));
    asset.mesh.faceVertexCounts = prim.requiredValue<types::IntArray>("faceVertexCounts");
    asset.mesh.faceVertexIndices = prim.requiredValue<types::IntArray>("faceVertexIndices");

    asset.defaultMaterial.eta = prim.requiredValue<types::Float>("opal:eta");
    asset.defaultMaterial.sigmaA = toRgb(prim.requiredValue<types::Color3f>("opal:sigmaA"));
    asset.defaultMaterial.sigmaSPrime = toRgb(prim.requiredValue<types::Color3f>("opal:sigmaSPrime"));
    asset.unitsPerMm = prim.requiredValue<types::Double>("opal:unitsPerMm");
    const auto sigmaS = prim.requiredValue<types::Double2>("opal:range:sigmaSPrime");
    const auto sigmaA = prim.requiredValue<types::Double2>("opal:range:sigmaA");
    const auto eta = prim.requiredValue<types::Double2>("opal:range:eta");
    asset.range = EditableRange{sigmaS[0], sigmaS[1], sigmaA[0], sigmaA[1], eta[0], eta[1]};

    const int K = prim.requiredValue<types::Int>("opal:basis:K");
    const auto& eigenvalues = prim.requiredValue<types::DoubleArray>("opal:basis:eigenvalues");
    if (K < 1 || std::size_t(K) != eigenvalues.size())
        throw Error(where(prim) + ": opal:basis:K is " + std::to_string(K) + " but there are " +
                    std::to_string(eigenvalues.size()) + " eigenvalues");
    try {
        sidecar::checkUnitsPerMm(asset.unitsPerMm, "opal:unitsPerMm");
        checkPointRange(asset.mesh.points, asset.unitsPerMm, "points", "point");
        asset.range.validate("opal:range");
        validateMaterial(asset.defaultMaterial, "default material");
        asset.basis = ProfileBasis(prim.requiredValue<types::DoubleArray>("opal:basis:radii"),
                                   prim.requiredValue<types::DoubleArray>("opal:basis:weights"),
                                   prim.requiredValue<types::DoubleArray>("opal:basis:values"), eigenvalues, asset.range);
    } catch (const usda::UsdaError&) {
        throw;
    } catch (const Error& e) {
        throw Error(where(prim) + ": prim '" + prim.name + "': " + e.what());
    }
    asset.bake = readBakeSettings(prim);
    asset.bake.identifier = readBakeIdAttribute(prim);
    return prim.requiredValue<types::Asset>("opal:sidecar");
}

TranslucentAsset readAsset(const std::filesystem::path& usdaPath, std::vector<std::string>* warnings) {
    const usda::Layer layer = usda::readUsdaFile(usdaPath);
    const std::string defaultPrim = layer.defaultPrim();
    if (layer.rootPrims.empty()) throw Error(usdaPath.string() + ": the layer has no prims");
    const usda::Prim& prim = defaultPrim.empty() ? layer.rootPrims.front() : layer.prim("/" + defaultPrim);
    return readAsset(prim, usdaPath, warnings);
}

TranslucentAsset readAsset(const usda::Prim& prim, const std::filesystem::path& anchorFile,
                           std::vector<std::string>* warnings) {
    TranslucentAsset asset;
    const std::string sidecar = primToAsset(prim, asset);
    const std::filesystem::path sidecarPath = anchorFile.parent_path() / sidecar;
    const SidecarHeader header = readSidecar(sidecarPath, asset);
    checkSameBake(anchorFile, sidecarPath, asset.bake.identifier, header.bakeId, warnings);
    checkSidecarMatches(header, asset, sidecarPath);
    return asset;
}

}  // namespace opal
