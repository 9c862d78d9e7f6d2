#include "bake/mesh_import.h"

#include "bake/mesh_file_census.h"
#include "bake/ply_header.h"
#include "bake/ply_triangle_strips.h"
#include "bake/usda_mesh_import.h"
#include "schema/error.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>

namespace opal {
namespace {

constexpr std::array<const char*, 5> kAssimpExtensions = {".obj", ".ply", ".gltf", ".glb", ".stl"};
constexpr const char* kUsdaExtension = ".usda";

std::string lowercaseExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool readByAssimp(const std::string& ext) {
    return std::find(kAssimpExtensions.begin(), kAssimpExtensions.end(), ext) != kAssimpExtensions.end();
}

// Accumulates the meshes of an aiScene into one ControlMesh.
class ControlMeshBuilder {
public:
    explicit ControlMeshBuilder(std::string source) { mesh_.source = std::move(source); }

    void append(const aiMesh& part, const aiMatrix4x4& toWorld, bool mirrored) {
        auto base = std::int32_t(mesh_.positions.size());
        for (unsigned v = 0; v < part.mNumVertices; ++v) {
            aiVector3D p = toWorld * part.mVertices[v];
            mesh_.positions.emplace_back(p.x, p.y, p.z);
        }
        appendUvs(part);
        for (unsigned f = 0; f < part.mNumFaces; ++f) appendFace(part.mFaces[f], base, mirrored);
    }

    std::size_t skippedPrimitives() const { return skippedPrimitives_; }
    // Some parts had texture coordinates and others not: all were dropped.
    bool droppedPartialUvs() const { return partsWithUvs_ > 0 && partsWithoutUvs_ > 0; }

    ControlMesh finish() {
        if (partsWithoutUvs_ > 0) {
            mesh_.uvs.clear();
            mesh_.uvIndices.clear();
        }
        return std::move(mesh_);
    }

private:
    // UV indices equal the reader's vertex indices: its vertices are split at seams, so
    // per-vertex UVs are already face-varying once positions are welded.
    void appendUvs(const aiMesh& part) {
        if (!part.HasTextureCoords(0)) {
            ++partsWithoutUvs_;
            return;
        }
        ++partsWithUvs_;
        for (unsigned v = 0; v < part.mNumVertices; ++v) {
            const aiVector3D& t = part.mTextureCoords[0][v];
            mesh_.uvs.emplace_back(t.x, t.y);
        }
    }

    void appendFace(const aiFace& face, std::int32_t base, bool mirrored) {
        if (face.mNumIndices < 3) {  // points and lines: nothing to subdivide
            ++skippedPrimitives_;
            return;
        }
        mesh_.faceVertexCounts.push_back(std::int32_t(face.mNumIndices));
        for (unsigned c = 0; c < face.mNumIndices; ++c) {
            // A mirroring transform turns counter-clockwise into clockwise: reverse.
            unsigned corner = mirrored ? (face.mNumIndices - c) % face.mNumIndices : c;
            std::int32_t index = base + std::int32_t(face.mIndices[corner]);
            mesh_.faceVertexIndices.push_back(index);
            mesh_.uvIndices.push_back(index);
        }
    }

    ControlMesh mesh_;
    std::size_t skippedPrimitives_ = 0;
    std::size_t partsWithUvs_ = 0;
    std::size_t partsWithoutUvs_ = 0;
};

void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                ControlMeshBuilder& builder) {
    aiMatrix4x4 toWorld = parent * node.mTransformation;
    bool mirrored = toWorld.Determinant() < 0;
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
        builder.append(*scene.mMeshes[node.mMeshes[m]], toWorld, mirrored);
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) {
        appendNode(scene, *node.mChildren[c], toWorld, builder);
    }
}

// A truncated file is refused before reading: some readers fill the gap with copies of
// the last face instead of failing.
void checkConsistent(const std::filesystem::path& path, const std::optional<MeshFileCensus>& census) {
    if (census && !census->inconsistency.empty()) {
        throw Error(path.string() + ": the file is truncated or malformed: " + census->inconsistency);
    }
}

// Some readers give up partway and return what they have without an error.
void checkPlausible(const std::filesystem::path& path, const std::optional<MeshFileCensus>& census,
                    const ControlMesh& mesh, std::size_t skipped) {
    std::string where = path.string() + ": ";
    if (mesh.faceCount() == 0) {
        throw Error(where + "the file contains no polygons (" + std::to_string(skipped) +
                    " points/lines, " + std::to_string(mesh.positions.size()) + " vertices)");
    }
    std::uint64_t read = mesh.faceCount() + skipped;
    if (census && read < census->faces) {
        throw Error(where + "the reader returned " + std::to_string(read) + " faces but the file has " +
                    census->evidence + "; the file is probably malformed or truncated");
    }
}

// The polygons' total area (each fanned into triangles from its first corner), in square
// file units; corners outside the positions are skipped (mesh validation reports them).
double totalArea(const ControlMesh& mesh) {
    double area = 0.0;
    std::size_t start = 0;
    const auto at = [&](std::int32_t i) { return Imath::V3d(mesh.positions[std::size_t(i)]); };
    const auto valid = [&](std::int32_t i) { return i >= 0 && std::size_t(i) < mesh.positions.size(); };
    for (std::int32_t count : mesh.faceVertexCounts) {
        if (count < 0 || start + std::size_t(count) > mesh.faceVertexIndices.size()) break;
        const std::int32_t* corners = mesh.faceVertexIndices.data() + start;
        for (std::int32_t c = 2; c < count; ++c) {
            if (!valid(corners[0]) || !valid(corners[c - 1]) || !valid(corners[c])) continue;
            area += 0.5 * (at(corners[c - 1]) - at(corners[0])).cross(at(corners[c]) - at(corners[0])).length();
        }
        start += std::size_t(count);
    }
    return area;
}

// A mesh whose faces cover no area has nothing to scatter light in: its size (and with it
// the profile basis's radius range) is zero. Non-finite positions are left to mesh
// validation, which names the first one.
void checkArea(const std::filesystem::path& path, const ControlMesh& mesh) {
    const double area = totalArea(mesh);
    if (area == 0.0)
        throw Error(path.string() + ": the mesh's " + std::to_string(mesh.faceCount()) + " faces have zero total area (" +
                    std::to_string(mesh.positions.size()) +
                    " vertices, all on one point or line); the file is probably malformed or was misread");
}

std::string readWholeFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw Error(path.string() + ": cannot read the file");
    return bytes;
}

// Assimp returns a single face for a PLY stored as triangle strips: such files are read
// here instead (bake/ply_triangle_strips.h).
ImportedMesh importTriangleStrips(const std::filesystem::path& path, const MeshFileCensus& census) {
    const std::string bytes = readWholeFile(path);
    const PlyHeader header = parsePlyHeader(bytes, path.string());
    PlyStripMesh strips = readPlyTriangleStrips(path, bytes, header);
    if (strips.stripTriangles == 0)
        throw Error(path.string() + ": the file stores its faces as triangle strips (" + census.evidence +
                    ") but no strip holds a triangle (" + std::to_string(strips.degenerate) +
                    " degenerate); the file is probably malformed");
    ImportedMesh result{std::move(strips.mesh), {}, std::nullopt, std::nullopt};
    checkPlausible(path, census, result.mesh, 0);
    return result;
}

ImportedMesh importWithAssimp(const std::filesystem::path& path) {
    std::optional<MeshFileCensus> census = takeMeshFileCensus(path);
    checkConsistent(path, census);
    if (census && census->triangleStrips > 0) return importTriangleStrips(path, *census);
    Assimp::Importer importer;
    // No aiProcess_Triangulate: Catmull-Clark needs the quads as authored.
    const aiScene* scene = importer.ReadFile(path.string(), aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || scene->mRootNode == nullptr) {
        throw Error(path.string() + ": cannot read the mesh: " + importer.GetErrorString());
    }
    ControlMeshBuilder builder(path.string());
    appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), builder);
    std::size_t skipped = builder.skippedPrimitives();
    bool droppedPartialUvs = builder.droppedPartialUvs();
    ImportedMesh result{builder.finish(), {}, std::nullopt, std::nullopt};
    checkPlausible(path, census, result.mesh, skipped);
    if (skipped > 0) {
        result.warnings.push_back("skipped " + std::to_string(skipped) +
                                  " point and line primitives (only polygons are subdivided)");
    }
    if (droppedPartialUvs) {
        result.warnings.push_back("ignored texture coordinates: not every mesh in the file has them");
    }
    return result;
}

void checkReadable(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path.string() + ": no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw Error(path.string() + ": not a regular file");
    if (!std::ifstream(path, std::ios::binary)) throw Error(path.string() + ": cannot open the file for reading");
}

}  // namespace

std::string supportedMeshExtensions() {
    std::string list;
    for (const char* ext : kAssimpExtensions) {
        if (!list.empty()) list += ' ';
        list += ext;
    }
    return list + ' ' + kUsdaExtension;
}

ImportedMesh importMesh(const std::filesystem::path& path) {
    checkReadable(path);
    std::string ext = lowercaseExtension(path);
    if (!readByAssimp(ext) && ext != kUsdaExtension)
        throw Error(path.string() + ": unsupported mesh format '" + ext + "'; supported: " +
                    supportedMeshExtensions());
    ImportedMesh imported = ext == kUsdaExtension ? importUsdaMesh(path) : importWithAssimp(path);
    checkArea(path, imported.mesh);
    return imported;
}

ImportedMesh importMeshPrim(const std::filesystem::path& path, const std::string& primPath) {
    checkReadable(path);
    if (lowercaseExtension(path) != kUsdaExtension)
        throw Error(path.string() + ": --apply-to <" + primPath + "> bakes a prim of a " + kUsdaExtension +
                    " layer; this input is not one");
    ImportedMesh imported = importUsdaMeshPrim(path, primPath);
    checkArea(path, imported.mesh);
    return imported;
}

}  // namespace opal
