#include "bake/subdivision.h"

#include "bake/mesh_edges.h"

#include "schema/error.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

namespace opal {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// The primvar type Far's PrimvarRefiner interpolates: it needs Clear and AddWithWeight.
// Sums run in double so deep levels do not accumulate float round-off.
struct RefinedPoint {
    double x = 0, y = 0, z = 0;

    void Clear(void* = nullptr) { x = y = z = 0; }
    void AddWithWeight(const RefinedPoint& p, float weight) {
        x += double(weight) * p.x;
        y += double(weight) * p.y;
        z += double(weight) * p.z;
    }
    Imath::V3d vec() const { return {x, y, z}; }
};

std::string where(const ControlMesh& mesh) {
    return (mesh.source.empty() ? std::string("control mesh") : mesh.source) + ": ";
}

// Level and size: OpenSubdiv stores the level in 4 bits, and the refined corner count
// (about corners x 4^level) must fit the 32-bit indices of RenderMesh.
void checkLevel(const ControlMesh& mesh, int level) {
    if (level < 0 || level > 15) {
        throw Error(where(mesh) + "subdivision level " + std::to_string(level) + " is outside 0..15");
    }
    double corners = double(mesh.faceVertexIndices.size()) * std::pow(4.0, level);
    if (corners > double(std::numeric_limits<std::int32_t>::max())) {
        throw Error(where(mesh) + "subdivision level " + std::to_string(level) + " would make about " +
                    std::to_string(std::int64_t(corners)) + " face corners, more than 32-bit indices hold");
    }
}

std::unique_ptr<Far::TopologyRefiner> createRefiner(const ControlMesh& mesh, SubdivisionScheme scheme) {
    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = int(mesh.positions.size());
    descriptor.numFaces = int(mesh.faceVertexCounts.size());
    descriptor.numVertsPerFace = mesh.faceVertexCounts.data();
    descriptor.vertIndicesPerFace = mesh.faceVertexIndices.data();

    Sdc::Options sdcOptions;
    sdcOptions.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    Sdc::SchemeType type = scheme == SubdivisionScheme::Loop       ? Sdc::SCHEME_LOOP
                           : scheme == SubdivisionScheme::Bilinear ? Sdc::SCHEME_BILINEAR
                                                                   : Sdc::SCHEME_CATMARK;
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(descriptor, Factory::Options(type, sdcOptions)));
    if (!refiner) {
        throw Error(where(mesh) + "OpenSubdiv rejected the mesh topology (its message is printed above)");
    }
    return refiner;
}

// Interpolates positions level by level; returns the last level's points.
std::vector<RefinedPoint> refinePositions(const Far::TopologyRefiner& refiner, const ControlMesh& mesh) {
    std::vector<RefinedPoint> current(mesh.positions.size());
    for (std::size_t v = 0; v < current.size(); ++v) {
        current[v] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
    }
    Far::PrimvarRefiner primvarRefiner(refiner);
    for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
        std::vector<RefinedPoint> next(std::size_t(refiner.GetLevel(level).GetNumVertices()));
        primvarRefiner.Interpolate(level, current, next);
        current = std::move(next);
    }
    return current;
}

void copyFaces(const Far::TopologyLevel& level, RenderMesh& out) {
    out.faceVertexCounts.resize(std::size_t(level.GetNumFaces()));
    out.faceVertexIndices.clear();
    out.faceVertexIndices.reserve(std::size_t(level.GetNumFaceVertices()));
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        Far::ConstIndexArray corners = level.GetFaceVertices(f);
        out.faceVertexCounts[f] = corners.size();
        for (int c = 0; c < corners.size(); ++c) out.faceVertexIndices.push_back(corners[c]);
    }
}

// Where du x dv vanishes (it can at some extraordinary or boundary configurations) the
// normal falls back to the area-weighted normal of the faces around the vertex.
std::vector<Imath::V3d> faceNormalSums(const RenderMesh& mesh) {
    std::vector<Imath::V3d> sums(mesh.points.size(), Imath::V3d(0.0));
    std::size_t start = 0;
    for (std::int32_t n : mesh.faceVertexCounts) {
        Imath::V3d area(0.0);
        for (std::int32_t c = 0; c < n; ++c) {
            Imath::V3d a(mesh.points[mesh.faceVertexIndices[start + c]]);
            Imath::V3d b(mesh.points[mesh.faceVertexIndices[start + (c + 1) % n]]);
            area += a.cross(b);
        }
        for (std::int32_t c = 0; c < n; ++c) sums[mesh.faceVertexIndices[start + c]] += area;
        start += std::size_t(n);
    }
    return sums;
}

void setLimitPointsAndNormals(const Far::TopologyRefiner& refiner, const std::vector<RefinedPoint>& refined,
                              RenderMesh& out) {
    std::vector<RefinedPoint> limit(refined.size()), du(refined.size()), dv(refined.size());
    Far::PrimvarRefiner(refiner).Limit(refined, limit, du, dv);
    out.points.resize(refined.size());
    for (std::size_t v = 0; v < refined.size(); ++v) out.points[v] = Imath::V3f(limit[v].vec());
    std::vector<Imath::V3d> fallback = faceNormalSums(out);
    out.normals.resize(refined.size());
    tbb::parallel_for(std::size_t(0), refined.size(), [&](std::size_t v) {
        Imath::V3d n = du[v].vec().cross(dv[v].vec());
        double scale = du[v].vec().length() * dv[v].vec().length();
        if (!(n.length() > 1e-6 * scale) || scale == 0.0) n = fallback[v];
        out.normals[v] = Imath::V3f(n.normalized());
    });
}

// Bilinear refinement leaves the points on the control polygons: they are the surface.
void setFlatPointsAndNormals(const std::vector<RefinedPoint>& refined, RenderMesh& out) {
    out.points.resize(refined.size());
    for (std::size_t v = 0; v < refined.size(); ++v) out.points[v] = Imath::V3f(refined[v].vec());
    std::vector<Imath::V3d> sums = faceNormalSums(out);
    out.normals.resize(refined.size());
    for (std::size_t v = 0; v < refined.size(); ++v) out.normals[v] = Imath::V3f(sums[v].normalized());
}

}  // namespace

SubdivisionScheme parseSubdivisionScheme(std::string_view name) {
    if (name == "auto") return SubdivisionScheme::Automatic;
    if (name == "catmullClark") return SubdivisionScheme::CatmullClark;
    if (name == "loop") return SubdivisionScheme::Loop;
    throw Error("unknown subdivision scheme '" + std::string(name) + "'; use auto, catmullClark or loop");
}

std::string_view subdivisionSchemeName(SubdivisionScheme scheme) {
    switch (scheme) {
    case SubdivisionScheme::Automatic: return "auto";
    case SubdivisionScheme::CatmullClark: return "catmullClark";
    case SubdivisionScheme::Loop: return "loop";
    case SubdivisionScheme::Bilinear: return "bilinear";
    }
    return "auto";
}

SubdivisionScheme resolveSubdivisionScheme(const ControlMesh& mesh, SubdivisionScheme requested) {
    const std::vector<std::int32_t>& counts = mesh.faceVertexCounts;
    auto firstNonTriangle = std::find_if(counts.begin(), counts.end(), [](std::int32_t n) { return n != 3; });
    bool allTriangles = firstNonTriangle == counts.end();
    if (requested == SubdivisionScheme::Automatic) {
        return allTriangles ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
    }
    if (requested == SubdivisionScheme::Loop && !allTriangles) {
        auto others = std::count_if(counts.begin(), counts.end(), [](std::int32_t n) { return n != 3; });
        throw Error(where(mesh) + "Loop subdivision needs triangles, but face " +
                    std::to_string(firstNonTriangle - counts.begin()) + " has " + std::to_string(*firstNonTriangle) +
                    " corners (" + std::to_string(others) + " non-triangular faces); use catmullClark");
    }
    return requested;
}

std::uint32_t automaticSubdivisionLevel(const ControlMesh& mesh, SubdivisionScheme scheme, std::uint64_t samples) {
    scheme = resolveSubdivisionScheme(mesh, scheme);
    const MeshEdges edges(mesh.faceVertexCounts, mesh.faceVertexIndices);
    double vertices = double(mesh.positions.size()), edgeCount = double(edges.edges().size());
    double faces = double(mesh.faceCount()), corners = double(mesh.faceVertexIndices.size());
    std::uint32_t level = 0;
    for (; level < kMaxAutomaticLevel && vertices < double(samples); ++level) {
        if (scheme == SubdivisionScheme::Loop) {  // each triangle into 4: a new vertex per edge
            vertices += edgeCount;
            edgeCount = 2.0 * edgeCount + 3.0 * faces;
            faces *= 4.0;
        } else {  // each n-gon into n quads: a new vertex per edge and per face
            vertices += edgeCount + faces;
            edgeCount = 2.0 * edgeCount + corners;
            faces = corners;
            corners = 4.0 * faces;
        }
    }
    return level;
}

RenderMesh subdivide(const ControlMesh& mesh, const SubdivisionOptions& options) {
    checkLevel(mesh, options.level);
    SubdivisionScheme scheme = resolveSubdivisionScheme(mesh, options.scheme);
    std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(mesh, scheme);
    if (options.level > 0) {
        Far::TopologyRefiner::UniformOptions uniform(options.level);
        uniform.fullTopologyInLastLevel = true;  // Limit() needs the last level's full topology
        refiner->RefineUniform(uniform);
    }
    std::vector<RefinedPoint> refined = refinePositions(*refiner, mesh);
    RenderMesh out;
    copyFaces(refiner->GetLevel(refiner->GetMaxLevel()), out);
    if (scheme == SubdivisionScheme::Bilinear) {
        setFlatPointsAndNormals(refined, out);
    } else {
        setLimitPointsAndNormals(*refiner, refined, out);
    }
    return out;
}

}  // namespace opal
