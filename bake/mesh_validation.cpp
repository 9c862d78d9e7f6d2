#include "bake/mesh_validation.h"

#include "bake/face_orientation.h"
#include "bake/mesh_edges.h"
#include "bake/vertex_welding.h"
#include "schema/error.h"

#include <Imath/ImathBox.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace opal {
namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

class MeshRepair {
public:
    MeshRepair(ControlMesh& mesh, const RepairOptions& options) : mesh_(mesh), options_(options) {}

    ValidationReport run() {
        checkStructure();
        checkFinitePositions();
        weldVertices();
        removeRepeatedCorners();
        dropZeroAreaFaces();
        if (mesh_.faceCount() == 0) fail("no faces are left after dropping degenerate ones");
        MeshEdges edges(mesh_.faceVertexCounts, mesh_.faceVertexIndices);
        checkManifoldEdges(edges);
        makeWindingConsistent(edges);
        orientOutward(edges);
        dropUnreferencedVertices();
        return std::move(report_);
    }

private:
    // ---- refusals -------------------------------------------------------------------

    [[noreturn]] void fail(const std::string& what) const {
        throw Error((mesh_.source.empty() ? std::string("control mesh") : mesh_.source) + ": " + what);
    }

    std::string describeVertex(std::int32_t v) const {
        const Imath::V3f& p = mesh_.positions[v];
        std::ostringstream s;
        s << "vertex " << v << " (" << p.x << ", " << p.y << ", " << p.z << ")";
        return s.str();
    }

    void checkStructure() {
        if (mesh_.positions.empty() || mesh_.faceVertexCounts.empty()) {
            fail("the mesh is empty (" + plural(mesh_.positions.size(), "vertex", "vertices") + ", " +
                 plural(mesh_.faceCount(), "face", "faces") + ")");
        }
        std::size_t corners = 0;
        for (std::size_t f = 0; f < mesh_.faceCount(); ++f) {
            std::int32_t n = mesh_.faceVertexCounts[f];
            if (n < 3) fail("face " + std::to_string(f) + " has " + std::to_string(n) + " corners; a face needs at least 3");
            corners += std::size_t(n);
        }
        if (corners != mesh_.faceVertexIndices.size()) {
            fail("the face sizes add up to " + std::to_string(corners) + " corners but there are " +
                 std::to_string(mesh_.faceVertexIndices.size()) + " face vertex indices");
        }
        checkIndexRange(mesh_.faceVertexIndices, mesh_.positions.size(), "vertex", "vertices");
        if (mesh_.hasUvs()) {
            if (mesh_.uvIndices.size() != corners) {
                fail("there are " + std::to_string(mesh_.uvIndices.size()) + " UV indices for " +
                     std::to_string(corners) + " face corners");
            }
            checkIndexRange(mesh_.uvIndices, mesh_.uvs.size(), "UV", "UVs");
        }
        originalFace_.resize(mesh_.faceCount());
        for (std::size_t f = 0; f < originalFace_.size(); ++f) originalFace_[f] = std::int32_t(f);
    }

    void checkIndexRange(const std::vector<std::int32_t>& indices, std::size_t size, const char* one, const char* many) {
        std::size_t bad = 0, firstBad = 0;
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] >= 0 && std::size_t(indices[i]) < size) continue;
            if (bad++ == 0) firstBad = i;
        }
        if (bad == 0) return;
        auto [face, corner] = faceAndCornerOf(firstBad);
        fail("face " + std::to_string(face) + ", corner " + std::to_string(corner) + " refers to " + one + " " +
             std::to_string(indices[firstBad]) + " but there are " + plural(size, one, many) + " (" +
             plural(bad, "out-of-range index", "out-of-range indices") + " in total)");
    }

    std::pair<std::size_t, std::size_t> faceAndCornerOf(std::size_t cornerIndex) const {
        std::size_t start = 0;
        for (std::size_t f = 0; f < mesh_.faceCount(); ++f) {
            std::size_t n = std::size_t(mesh_.faceVertexCounts[f]);
            if (cornerIndex < start + n) return {f, cornerIndex - start};
            start += n;
        }
        return {mesh_.faceCount(), 0};
    }

    void checkFinitePositions() {
        std::size_t bad = 0;
        std::int32_t firstBad = -1;
        for (std::size_t v = 0; v < mesh_.positions.size(); ++v) {
            const Imath::V3f& p = mesh_.positions[v];
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
            if (bad++ == 0) firstBad = std::int32_t(v);
        }
        if (bad > 0) {
            fail(describeVertex(firstBad) + " is not finite (" +
                 plural(bad, "non-finite vertex", "non-finite vertices") + " in total)");
        }
    }

    void checkManifoldEdges(const MeshEdges& edges) const {
        std::size_t bad = 0;
        const MeshEdges::Edge* first = nullptr;
        for (const MeshEdges::Edge& e : edges.edges()) {
            if (e.useCount <= 2) continue;
            if (bad++ == 0) first = &e;
        }
        if (bad == 0) return;
        std::string faces;
        for (const MeshEdges::Use& u : edges.uses(*first)) {
            faces += (faces.empty() ? "" : ", ") + std::to_string(originalFace_[u.face]);
        }
        fail("non-manifold edge between " + describeVertex(first->low) + " and " + describeVertex(first->high) +
             ": used by " + std::to_string(first->useCount) + " faces (" + faces + "); " +
             plural(bad, "non-manifold edge", "non-manifold edges") + " in total");
    }

    // ---- repairs --------------------------------------------------------------------

    void warn(std::string message) { report_.warnings.push_back(std::move(message)); }

    void weldVertices() {
        VertexWelding identical = weldIdenticalPositions(mesh_.positions);
        representative_ = identical.representative;
        if (identical.welded > 0) {
            warn("welded " + plural(identical.welded, "vertex", "vertices") + " with identical positions");
        }
        if (options_.weldTolerance > 0.0) weldNearbyRepresentatives();
        for (std::int32_t& v : mesh_.faceVertexIndices) v = representative_[v];
    }

    // Welding within a tolerance runs on the vertices that survived the exact weld.
    void weldNearbyRepresentatives() {
        std::vector<std::int32_t> survivors;
        std::vector<Imath::V3f> points;
        Imath::Box3f bounds;
        for (std::size_t v = 0; v < representative_.size(); ++v) {
            if (representative_[v] != std::int32_t(v)) continue;
            survivors.push_back(std::int32_t(v));
            points.push_back(mesh_.positions[v]);
            bounds.extendBy(mesh_.positions[v]);
        }
        float tolerance = float(options_.weldTolerance * (bounds.max - bounds.min).length());
        VertexWelding nearby = weldNearbyPositions(points, tolerance);
        std::vector<std::int32_t> survivorSlot(representative_.size(), -1);
        for (std::size_t i = 0; i < survivors.size(); ++i) survivorSlot[survivors[i]] = std::int32_t(i);
        for (std::int32_t& r : representative_) r = survivors[nearby.representative[survivorSlot[r]]];
        if (nearby.welded > 0) {
            std::ostringstream s;
            s << "welded " << plural(nearby.welded, "vertex", "vertices") << " closer than " << tolerance << " ("
              << options_.weldTolerance << " of the bounding-box diagonal) to another";
            warn(s.str());
        }
    }

    // Rebuilds the face arrays from the faces (with their new corner lists) that are kept.
    struct FaceCorners {
        std::vector<std::int32_t> vertices, uvs;
    };
    template <class EditFace>
    void rewriteFaces(EditFace edit) {
        ControlMesh& m = mesh_;
        std::vector<std::int32_t> counts, indices, uvIndices, original;
        std::size_t start = 0;
        for (std::size_t f = 0; f < m.faceCount(); ++f) {
            std::size_t n = std::size_t(m.faceVertexCounts[f]);
            FaceCorners face;
            face.vertices.assign(m.faceVertexIndices.begin() + start, m.faceVertexIndices.begin() + start + n);
            if (m.hasUvs()) face.uvs.assign(m.uvIndices.begin() + start, m.uvIndices.begin() + start + n);
            start += n;
            if (!edit(f, face)) continue;
            counts.push_back(std::int32_t(face.vertices.size()));
            indices.insert(indices.end(), face.vertices.begin(), face.vertices.end());
            uvIndices.insert(uvIndices.end(), face.uvs.begin(), face.uvs.end());
            original.push_back(originalFace_[f]);
        }
        m.faceVertexCounts = std::move(counts);
        m.faceVertexIndices = std::move(indices);
        if (m.hasUvs()) m.uvIndices = std::move(uvIndices);
        originalFace_ = std::move(original);
    }

    // A corner equal to the one before it (cyclically) adds nothing: welding makes these.
    // What is left must have 3 distinct vertices, each used once.
    void removeRepeatedCorners() {
        std::size_t removedCorners = 0, dropped = 0;
        rewriteFaces([&](std::size_t, FaceCorners& face) {
            FaceCorners kept;
            std::size_t n = face.vertices.size();
            for (std::size_t c = 0; c < n; ++c) {
                if (face.vertices[c] == face.vertices[(c + n - 1) % n]) continue;
                kept.vertices.push_back(face.vertices[c]);
                if (!face.uvs.empty()) kept.uvs.push_back(face.uvs[c]);
            }
            std::vector<std::int32_t> sorted = kept.vertices;
            std::sort(sorted.begin(), sorted.end());
            bool degenerate = sorted.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
            if (degenerate) {
                ++dropped;
                return false;
            }
            removedCorners += n - kept.vertices.size();
            face = std::move(kept);
            return true;
        });
        if (removedCorners > 0) warn("removed " + plural(removedCorners, "repeated corner", "repeated corners"));
        if (dropped > 0) {
            warn("dropped " + plural(dropped, "degenerate face", "degenerate faces") +
                 " (fewer than 3 distinct vertices, or a vertex used twice)");
        }
    }

    // Zero up to float rounding: the face's height above its longest edge is within a few
    // ulps of its largest coordinate, i.e. the corners are collinear as stored.
    bool hasZeroArea(const std::vector<std::int32_t>& corners) const {
        Imath::V3d areaVector(0.0), origin(mesh_.positions[corners[0]]);
        double longestEdge = 0.0, largestCoordinate = 0.0;
        for (std::size_t c = 0; c < corners.size(); ++c) {
            Imath::V3d a = Imath::V3d(mesh_.positions[corners[c]]);
            Imath::V3d b = Imath::V3d(mesh_.positions[corners[(c + 1) % corners.size()]]);
            areaVector += (a - origin).cross(b - origin);
            longestEdge = std::max(longestEdge, (b - a).length());
            largestCoordinate = std::max({largestCoordinate, std::abs(a.x), std::abs(a.y), std::abs(a.z)});
        }
        double height = areaVector.length() / std::max(longestEdge, 1e-300);  // 2 area / base
        return height <= 4.0 * 0x1p-23 * largestCoordinate;
    }

    void dropZeroAreaFaces() {
        std::size_t dropped = 0;
        rewriteFaces([&](std::size_t, FaceCorners& face) {
            if (!hasZeroArea(face.vertices)) return true;
            ++dropped;
            return false;
        });
        if (dropped > 0) warn("dropped " + plural(dropped, "zero-area face", "zero-area faces"));
    }

    // ---- winding --------------------------------------------------------------------

    static bool sameDirection(const MeshEdges& edges, const MeshEdges::Edge& e) {
        std::span<const MeshEdges::Use> u = edges.uses(e);
        return u.size() == 2 && u[0].forward == u[1].forward;
    }

    void makeWindingConsistent(const MeshEdges& edges) {
        std::size_t bad = 0;
        const MeshEdges::Edge* first = nullptr;
        for (const MeshEdges::Edge& e : edges.edges()) {
            if (!sameDirection(edges, e)) continue;
            if (bad++ == 0) first = &e;
        }
        if (bad == 0) return;
        if (!options_.fixWinding) {
            std::span<const MeshEdges::Use> u = edges.uses(*first);
            fail("inconsistent winding: faces " + std::to_string(originalFace_[u[0].face]) + " and " +
                 std::to_string(originalFace_[u[1].face]) + " walk the edge between " + describeVertex(first->low) +
                 " and " + describeVertex(first->high) + " in the same direction (" +
                 plural(bad, "such edge", "such edges") + "); enable winding repair to reorient faces");
        }
        FaceOrientation orientation = orientFacesConsistently(edges, mesh_.faceVertexCounts);
        if (orientation.conflict) {
            fail("the surface is not orientable (like a Moebius strip): reorienting faces reaches face " +
                 std::to_string(originalFace_[orientation.conflict->first]) + " from face " +
                 std::to_string(originalFace_[orientation.conflict->second]) + " with the opposite orientation");
        }
        const std::vector<char>& flip = orientation.reversed;
        std::size_t flipped = std::count(flip.begin(), flip.end(), 1);
        rewriteFaces([&](std::size_t f, FaceCorners& face) {
            if (flip[f]) reverseCorners(face);
            return true;
        });
        warn("reversed the winding of " + plural(flipped, "face", "faces") + " to agree with their neighbours (" +
             plural(bad, "edge was", "edges were") + " walked the same way by both faces)");
    }

    // Keeps the first corner, so a face's "first vertex" does not move.
    static void reverseCorners(FaceCorners& face) {
        std::reverse(face.vertices.begin() + 1, face.vertices.end());
        if (!face.uvs.empty()) std::reverse(face.uvs.begin() + 1, face.uvs.end());
    }

    // Only a closed mesh has an inside; flipping an open one would be a guess.
    void orientOutward(const MeshEdges& edges) {
        bool closed = std::all_of(edges.edges().begin(), edges.edges().end(),
                                  [](const MeshEdges::Edge& e) { return e.useCount == 2; });
        if (!closed || enclosedVolume(mesh_.positions, mesh_.faceVertexCounts, mesh_.faceVertexIndices) >= 0.0) return;
        rewriteFaces([](std::size_t, FaceCorners& face) {
            reverseCorners(face);
            return true;
        });
        warn("reversed all " + plural(mesh_.faceCount(), "face", "faces") +
             ": the closed mesh was inside out (its faces enclosed a negative volume)");
    }

    // Vertices welded into another one disappear silently (the weld warned); others that
    // no face uses are reported.
    void dropUnreferencedVertices() {
        std::vector<char> used(mesh_.positions.size(), 0);
        for (std::int32_t v : mesh_.faceVertexIndices) used[v] = 1;
        std::vector<std::int32_t> newIndex(mesh_.positions.size(), -1);
        std::vector<Imath::V3f> kept;
        std::size_t unreferenced = 0;
        for (std::size_t v = 0; v < mesh_.positions.size(); ++v) {
            if (used[v]) {
                newIndex[v] = std::int32_t(kept.size());
                kept.push_back(mesh_.positions[v]);
            } else if (representative_[v] == std::int32_t(v)) {
                ++unreferenced;
            }
        }
        for (std::int32_t& v : mesh_.faceVertexIndices) v = newIndex[v];
        mesh_.positions = std::move(kept);
        if (unreferenced > 0) warn("dropped " + plural(unreferenced, "unreferenced vertex", "unreferenced vertices"));
    }

    ControlMesh& mesh_;
    RepairOptions options_;
    ValidationReport report_;
    std::vector<std::int32_t> originalFace_;    // input index of each current face
    std::vector<std::int32_t> representative_;  // weld target of each input vertex
};

}  // namespace

ValidationReport validateAndRepair(ControlMesh& mesh, const RepairOptions& options) {
    return MeshRepair(mesh, options).run();
}

}  // namespace opal
