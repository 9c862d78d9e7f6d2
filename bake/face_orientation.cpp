#include "bake/face_orientation.h"

#include "schema/asset/fan_triangulation.h"

#include <Imath/ImathBox.h>

namespace opal {
namespace {

std::vector<std::size_t> faceStarts(std::span<const std::int32_t> counts) {
    std::vector<std::size_t> starts(counts.size() + 1, 0);
    for (std::size_t f = 0; f < counts.size(); ++f) starts[f + 1] = starts[f] + std::size_t(counts[f]);
    return starts;
}

// The breadth-first walk over one component: flip[f] is -1 until f is reached, then 1 if f
// must be reversed relative to the seed.
class OrientationWalk {
public:
    OrientationWalk(const MeshEdges& edges, std::span<const std::int32_t> counts)
        : edges_(edges), starts_(faceStarts(counts)), flip_(counts.size(), -1) {}

    FaceOrientation run() {
        FaceOrientation result;
        result.reversed.assign(flip_.size(), 0);
        for (std::size_t seed = 0; seed < flip_.size() && !result.conflict; ++seed) {
            if (flip_[seed] < 0) walkComponent(std::int32_t(seed), result);
        }
        return result;
    }

private:
    void walkComponent(std::int32_t seed, FaceOrientation& result) {
        std::vector<std::int32_t> component{seed};
        flip_[seed] = 0;
        for (std::size_t head = 0; head < component.size() && !result.conflict; ++head) {
            std::int32_t f = component[head];
            for (std::size_t c = starts_[f]; c < starts_[f + 1] && !result.conflict; ++c) {
                visitAcross(f, c, component, result);
            }
        }
        std::size_t flips = 0;
        for (std::int32_t f : component) flips += std::size_t(flip_[f] == 1);
        bool invert = 2 * flips > component.size();  // keep the majority's orientation
        for (std::int32_t f : component) result.reversed[f] = char((flip_[f] == 1) != invert);
    }

    // The face across the edge that starts at `corner` of face f.
    void visitAcross(std::int32_t f, std::size_t corner, std::vector<std::int32_t>& component,
                     FaceOrientation& result) {
        const MeshEdges::Edge& e = edges_.edges()[edges_.edgeOfCorner(corner)];
        if (e.useCount != 2) return;
        std::span<const MeshEdges::Use> u = edges_.uses(e);
        bool firstIsMine = u[0].corner == std::int32_t(corner);
        const MeshEdges::Use& mine = firstIsMine ? u[0] : u[1];
        const MeshEdges::Use& theirs = firstIsMine ? u[1] : u[0];
        // Walking the edge the same way means opposite orientations.
        auto expected = static_cast<signed char>(flip_[f] ^ (mine.forward == theirs.forward ? 1 : 0));
        if (flip_[theirs.face] < 0) {
            flip_[theirs.face] = expected;
            component.push_back(theirs.face);
        } else if (flip_[theirs.face] != expected) {
            result.conflict = std::pair{theirs.face, f};
        }
    }

    const MeshEdges& edges_;
    std::vector<std::size_t> starts_;
    std::vector<signed char> flip_;
};

}  // namespace

FaceOrientation orientFacesConsistently(const MeshEdges& edges, std::span<const std::int32_t> faceVertexCounts) {
    return OrientationWalk(edges, faceVertexCounts).run();
}

double enclosedVolume(std::span<const Imath::V3f> positions, std::span<const std::int32_t> faceVertexCounts,
                      std::span<const std::int32_t> faceVertexIndices) {
    Imath::Box3d bounds;
    for (const Imath::V3f& p : positions) bounds.extendBy(Imath::V3d(p));
    Imath::V3d centre = bounds.center();  // about the centre: less cancellation
    auto at = [&](std::int32_t vertex) { return Imath::V3d(positions[std::size_t(vertex)]) - centre; };
    double sixTimesVolume = 0.0;
    forEachFanTriangle(faceVertexCounts, faceVertexIndices, [&](std::size_t, const std::array<std::int32_t, 3>& v) {
        sixTimesVolume += at(v[0]).dot(at(v[1]).cross(at(v[2])));
    });
    return sixTimesVolume / 6.0;
}

}  // namespace opal
