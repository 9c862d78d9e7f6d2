#include "bake/usda_mesh_import.h"

#include "bake/prim_transform.h"
#include "bake/usda_prim_lookup.h"
#include "schema/asset/point_range.h"
#include "schema/error.h"
#include "schema/usd/usda_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace opal {
namespace {

namespace types = usda::types;
using usda::Attribute;
using usda::Prim;

// What a prim hands down to its children.
struct Inherited {
    std::string path;     // "" for the layer itself
    Imath::M44d toWorld;  // identity for the layer
    std::string purpose;  // a non-default purpose an ancestor authored; "" otherwise
};

std::string bracketed(const std::string& primPath) { return "<" + primPath + ">"; }

[[noreturn]] void fail(const usda::SourceLocation& where, const std::string& primPath, std::string_view property,
                       const std::string& problem) {
    std::string what = bracketed(primPath);
    if (!property.empty()) what += "." + std::string(property);
    throw Error(where.str() + ": " + what + ": " + problem);
}

const usda::SourceLocation& locationOf(const Prim& prim, std::string_view name) {
    const Attribute* attr = prim.findAttribute(name);
    return attr ? attr->location : prim.location;
}

template <usda::ValueType T>
const usda::StorageOf<T>& required(const Prim& prim, const std::string& path, std::string_view name) {
    if (const usda::StorageOf<T>* value = prim.findValue<T>(name, bracketed(path))) return *value;
    const bool declared = prim.findAttribute(name) != nullptr;
    fail(locationOf(prim, name), path, name,
         std::string(declared ? "has no value" : "missing") +
             "; a Mesh needs points, faceVertexCounts and faceVertexIndices");
}

// A token attribute restricted to `allowed`; `fallback` when it is not authored.
std::string token(const Prim& prim, const std::string& path, std::string_view name,
                  std::initializer_list<std::string_view> allowed, std::string_view fallback) {
    const std::string* value = prim.findValue<types::Token>(name, bracketed(path));
    if (!value) return std::string(fallback);
    if (std::find(allowed.begin(), allowed.end(), *value) != allowed.end()) return *value;
    std::string names;
    for (std::string_view a : allowed) names += (names.empty() ? "" : ", ") + std::string(a);
    fail(locationOf(prim, name), path, name, "'" + *value + "' is not one of " + names);
}

bool isActive(const Prim& prim) {
    const usda::Value* active = prim.metadata.find("active");
    return !active || active->get<types::Bool>("metadata 'active'");
}

bool holdsMesh(const Prim& prim) {
    if (prim.typeName == "Mesh") return true;
    return std::any_of(prim.children.begin(), prim.children.end(), [](const Prim& c) {
        return c.specifier == usda::Specifier::Def && holdsMesh(c);
    });
}

// Renderable geometry that is not a Mesh: the bake leaves it out, with a warning.
bool isOtherGprim(std::string_view type) {
    constexpr std::string_view kOthers[] = {"Cube",       "Sphere",      "Cylinder",      "Cone",
                                            "Capsule",    "Plane",       "NurbsPatch",    "BasisCurves",
                                            "NurbsCurves", "HermiteCurves", "Points",     "PointInstancer",
                                            "TetMesh"};
    return std::find(std::begin(kOthers), std::end(kOthers), type) != std::end(kOthers);
}

// "</A>, </B>, ... (12 in total)": at most five named.
std::string listed(const std::vector<std::string>& items) {
    constexpr std::size_t kNamed = 5;
    std::string text;
    for (std::size_t i = 0; i < std::min(items.size(), kNamed); ++i) text += (i ? ", " : "") + items[i];
    if (items.size() > kNamed) text += ", ... (" + std::to_string(items.size()) + " in total)";
    return text;
}

// faceVertexCounts and faceVertexIndices agree with each other and with the points.
void checkTopology(const Prim& prim, const std::string& path, std::size_t points,
                   const std::vector<std::int32_t>& counts, const std::vector<std::int32_t>& indices) {
    std::uint64_t corners = 0;
    for (std::size_t f = 0; f < counts.size(); ++f) {
        if (counts[f] < 3) {
            fail(locationOf(prim, "faceVertexCounts"), path, "faceVertexCounts",
                 "face " + std::to_string(f) + " has " + std::to_string(counts[f]) +
                     " corners; a face needs at least 3");
        }
        corners += std::uint64_t(counts[f]);
    }
    if (corners != indices.size()) {
        fail(locationOf(prim, "faceVertexIndices"), path, "faceVertexIndices",
             std::to_string(indices.size()) + " indices, but faceVertexCounts add up to " + std::to_string(corners) +
                 " corners");
    }
    std::size_t bad = 0, first = 0;
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= 0 && std::size_t(indices[i]) < points) continue;
        if (bad++ == 0) first = i;
    }
    if (bad > 0) {
        fail(locationOf(prim, "faceVertexIndices"), path, "faceVertexIndices",
             "index " + std::to_string(indices[first]) + " out of range (" + std::to_string(points) +
                 " points) at position " + std::to_string(first) +
                 (bad > 1 ? "; " + std::to_string(bad) + " out-of-range indices in total" : ""));
    }
}

// holeIndices: faces USD does not draw. The bake leaves them out.
std::vector<bool> holeFaces(const Prim& prim, const std::string& path, std::size_t faces) {
    std::vector<bool> holes(faces, false);
    const std::vector<std::int32_t>* indices = prim.findValue<types::IntArray>("holeIndices", bracketed(path));
    if (!indices) return holes;
    for (std::int32_t f : *indices) {
        if (f < 0 || std::size_t(f) >= faces) {
            fail(locationOf(prim, "holeIndices"), path, "holeIndices",
                 "face " + std::to_string(f) + " out of range (" + std::to_string(faces) + " faces)");
        }
        holes[std::size_t(f)] = true;
    }
    return holes;
}

// Authored subdivision tags that Opal's uniform refinement does not apply.
std::vector<std::string> ignoredTags(const Prim& prim, const std::string& path) {
    std::vector<std::string> tags;
    for (std::string_view name : {"creaseIndices", "cornerIndices"}) {
        const std::vector<std::int32_t>* indices = prim.findValue<types::IntArray>(name, bracketed(path));
        if (indices && !indices->empty()) tags.emplace_back(name);
    }
    const std::pair<std::string_view, std::string_view> defaults[] = {{"interpolateBoundary", "edgeAndCorner"},
                                                                      {"triangleSubdivisionRule", "catmullClark"}};
    for (const auto& [name, fallback] : defaults) {
        const std::string* value = prim.findValue<types::Token>(name, bracketed(path));
        if (value && *value != fallback) tags.push_back(std::string(name) + " '" + *value + "'");
    }
    return tags;
}


std::optional<SubdivisionScheme> schemeOfToken(const std::string& token) {
    if (token == "catmullClark") return SubdivisionScheme::CatmullClark;
    if (token == "loop") return SubdivisionScheme::Loop;
    if (token == "bilinear" || token == "none") return SubdivisionScheme::Bilinear;
    return std::nullopt;
}

// Walks the layer's prims and merges every Mesh prim USD would render.
class MeshCollector {
public:
    // unitsPerMm: the layer's (0.001 / metersPerUnit), for the range every point must lie in.
    MeshCollector(std::string file, double unitsPerMm) : file_(std::move(file)), unitsPerMm_(unitsPerMm) {
        mesh_.source = file_;
    }

    void visitAll(const std::vector<Prim>& prims, const Inherited& parent) {
        for (const Prim& p : prims) visit(p, parent);
    }

    // One Mesh prim in its own space: neither its xformOps nor its ancestors' apply.
    void addLocal(const Prim& prim, const std::string& path) {
        for (const std::string& op : primTransform(prim, path).unusedOps)
            warnings_.push_back(bracketed(path) + "." + op + " is not in xformOpOrder: ignored, as USD does");
        append(prim, path, Imath::M44d());
    }

    ImportedMesh finish(std::optional<double> metersPerUnit) {
        if (meshes_.empty()) throw Error(file_ + ": " + nothingToBake());
        ImportedMesh result;
        result.mesh = std::move(mesh_);
        result.warnings = std::move(warnings_);
        if (!skipped_.empty()) {
            result.warnings.push_back("skipped " + std::to_string(skipped_.size()) +
                                      " prims holding meshes USD does not render: " + listed(skipped_));
        }
        if (!others_.empty()) {
            result.warnings.push_back("ignored " + std::to_string(others_.size()) +
                                      " geometry prims that are not Mesh prims: " + listed(others_));
        }
        result.authoredScheme = commonScheme(result.warnings);
        result.metersPerUnit = metersPerUnit;
        return result;
    }

private:
    void visit(const Prim& prim, const Inherited& parent) {
        // USD's default traversal: `class` prims are abstract, `over` prims define nothing.
        if (prim.specifier != usda::Specifier::Def || !isActive(prim)) return;
        Inherited here{parent.path + "/" + prim.name, parent.toWorld, parent.purpose};
        const std::string& path = here.path;
        if (here.purpose.empty()) {  // the topmost authored non-default purpose wins
            std::string own = token(prim, path, "purpose", {"default", "render", "proxy", "guide"}, "default");
            if (own != "default") here.purpose = std::move(own);
        }
        std::string hidden;
        if (token(prim, path, "visibility", {"inherited", "invisible"}, "inherited") == "invisible") {
            hidden = "invisible";
        }
        if (here.purpose == "proxy" || here.purpose == "guide") hidden = "purpose " + here.purpose;
        if (!hidden.empty()) {  // nothing below is rendered: its transforms and contents do not matter
            if (holdsMesh(prim)) skipped_.push_back(bracketed(path) + " (" + hidden + ")");
            return;
        }
        if (prim.references.authored()) {
            fail(prim.location, path, "",
                 "references are not composed by Opal: flatten the layer first (usdcat --flatten)");
        }
        const PrimTransform transform = primTransform(prim, path);
        for (const std::string& op : transform.unusedOps)
            warnings_.push_back(bracketed(path) + "." + op + " is not in xformOpOrder: ignored, as USD does");
        here.toWorld = transform.resetsXformStack ? transform.local : transform.local * parent.toWorld;
        if (prim.typeName == "Mesh") {
            append(prim, path, here.toWorld);
        } else if (isOtherGprim(prim.typeName)) {
            others_.push_back(bracketed(path) + " (" + prim.typeName + ")");
        }
        visitAll(prim.children, here);
    }

    void append(const Prim& prim, const std::string& path, const Imath::M44d& toWorld) {
        const auto& points = required<types::Point3fArray>(prim, path, "points");
        const auto& counts = required<types::IntArray>(prim, path, "faceVertexCounts");
        const auto& indices = required<types::IntArray>(prim, path, "faceVertexIndices");
        checkTopology(prim, path, points.size(), counts, indices);
        const std::vector<bool> holes = holeFaces(prim, path, counts.size());
        const bool leftHanded =
            token(prim, path, "orientation", {"rightHanded", "leftHanded"}, "rightHanded") == "leftHanded";
        std::string scheme = token(prim, path, "subdivisionScheme", {"catmullClark", "loop", "bilinear", "none"}, "");
        for (const std::string& tag : ignoredTags(prim, path))
            warnings_.push_back(bracketed(path) + ": ignored " + tag + " (the bake refines without subdivision tags)");
        if (counts.empty()) {
            emptyMeshes_.push_back(bracketed(path));
            return;
        }
        meshes_.push_back(path);
        schemes_.push_back(std::move(scheme));
        const auto base = appendPoints(prim, path, points, toWorld);
        // A mirroring transform turns counter-clockwise into clockwise, as leftHanded does.
        appendFaces(counts, indices, holes, base, leftHanded != (toWorld.determinant() < 0.0));
    }

    std::int32_t appendPoints(const Prim& prim, const std::string& path, const std::vector<usda::Vec3f>& points,
                              const Imath::M44d& toWorld) {
        const std::size_t base = mesh_.positions.size();
        if (points.size() > std::size_t(std::numeric_limits<std::int32_t>::max()) - base) {
            fail(locationOf(prim, "points"), path, "points", "the merged mesh would exceed 2^31 points");
        }
        for (std::size_t v = 0; v < points.size(); ++v) {
            const Imath::V3d world = Imath::V3d(points[v][0], points[v][1], points[v][2]) * toWorld;
            const double largest = std::max({std::abs(world.x), std::abs(world.y), std::abs(world.z)});
            if (!(largest <= kMaxDistanceMm * unitsPerMm_)) {  // point_range.h; false for NaN
                std::ostringstream s;
                s << "point " << v << " (" << points[v][0] << ", " << points[v][1] << ", " << points[v][2]
                  << ") is (" << world.x << ", " << world.y << ", " << world.z << ") after the prim's transform: ";
                if (std::isfinite(largest))
                    s << largest / unitsPerMm_ << " mm from the origin at the layer's metersPerUnit "
                      << 0.001 / unitsPerMm_ << ", beyond the 1e9 mm (1,000 km) an asset may span";
                else
                    s << "not finite";
                fail(locationOf(prim, "points"), path, "points", s.str());
            }
            mesh_.positions.emplace_back(world);
        }
        return std::int32_t(base);
    }

    void appendFaces(const std::vector<std::int32_t>& counts, const std::vector<std::int32_t>& indices,
                     const std::vector<bool>& holes, std::int32_t base, bool reverse) {
        std::size_t start = 0;
        for (std::size_t f = 0; f < counts.size(); ++f) {
            const std::int32_t n = counts[f];
            if (!holes[f]) {
                mesh_.faceVertexCounts.push_back(n);
                for (std::int32_t c = 0; c < n; ++c) {
                    const std::int32_t corner = reverse ? (n - c) % n : c;  // keeps corner 0, as the Assimp path
                    mesh_.faceVertexIndices.push_back(base + indices[start + std::size_t(corner)]);
                }
            }
            start += std::size_t(n);
        }
    }

    std::string nothingToBake() const {
        std::string what = emptyMeshes_.empty() ? "the layer has no Mesh prim to bake"
                                                : "the layer's Mesh prims have no faces: " + listed(emptyMeshes_);
        if (!skipped_.empty()) what += "; skipped (not rendered by USD): " + listed(skipped_);
        if (!others_.empty()) what += "; not Mesh prims: " + listed(others_);
        return what;
    }

    // The scheme every merged Mesh prim authors; nullopt when none does or they differ.
    std::optional<SubdivisionScheme> commonScheme(std::vector<std::string>& warnings) const {
        if (std::all_of(schemes_.begin(), schemes_.end(), [&](const std::string& s) { return s == schemes_[0]; })) {
            return schemeOfToken(schemes_[0]);
        }
        std::vector<std::string> each;
        for (std::size_t m = 0; m < meshes_.size(); ++m)
            each.push_back(bracketed(meshes_[m]) + " " + (schemes_[m].empty() ? "not authored" : schemes_[m]));
        warnings.push_back("the Mesh prims disagree on subdivisionScheme (" + listed(each) +
                           "); the merged mesh gets the automatic choice (--scheme overrides it)");
        return std::nullopt;
    }

    std::string file_;
    double unitsPerMm_ = 1.0;
    ControlMesh mesh_;
    std::vector<std::string> warnings_;
    std::vector<std::string> meshes_;       // paths of the Mesh prims merged, in layer order
    std::vector<std::string> schemes_;      // their subdivisionScheme; "" when not authored
    std::vector<std::string> emptyMeshes_;  // Mesh prims without faces
    std::vector<std::string> skipped_;      // hidden prims holding meshes, with the reason
    std::vector<std::string> others_;       // geometry that is not a Mesh, with its type
};

// The layer, read and checked for what both imports refuse; its metersPerUnit.
std::pair<usda::Layer, std::optional<double>> readMeshLayer(const std::filesystem::path& path) {
    usda::Layer layer = usda::readUsdaFile(path);
    if (!layer.subLayers.empty()) {
        throw Error(path.string() + ": the layer has subLayers (@" + layer.subLayers.front() +
                    "@), which opal-bake does not compose: flatten it first (usdcat --flatten)");
    }
    const std::optional<double> metersPerUnit = layer.metersPerUnit();
    if (metersPerUnit && !(*metersPerUnit > 0.0)) {
        std::ostringstream s;
        s << path.string() << ": metersPerUnit is " << *metersPerUnit << "; it must be positive";
        throw Error(s.str());
    }
    return {std::move(layer), metersPerUnit};
}

// USD's fallback metersPerUnit is 0.01 (centimetres).
double unitsPerMmOf(std::optional<double> metersPerUnit) { return 0.001 / metersPerUnit.value_or(0.01); }

}  // namespace

ImportedMesh importUsdaMesh(const std::filesystem::path& path) {
    const auto [layer, metersPerUnit] = readMeshLayer(path);
    MeshCollector collector(path.string(), unitsPerMmOf(metersPerUnit));
    collector.visitAll(layer.rootPrims, Inherited{});
    return collector.finish(metersPerUnit);
}

ImportedMesh importUsdaMeshPrim(const std::filesystem::path& path, const std::string& primPath) {
    const auto [layer, metersPerUnit] = readMeshLayer(path);
    const Prim& prim = findBakeablePrim(layer, path.string(), primPath);
    MeshCollector collector(path.string(), unitsPerMmOf(metersPerUnit));
    collector.addLocal(prim, primPath);
    return collector.finish(metersPerUnit);
}

}  // namespace opal
