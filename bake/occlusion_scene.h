// An Embree 3 scene of the render mesh, for the bake's visibility rays. Polygons are
// fanned into triangles. Thread-safe for queries after construction.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <embree3/rtcore.h>

namespace opal {

class OcclusionScene {
public:
    explicit OcclusionScene(const RenderMesh& mesh);
    ~OcclusionScene();
    OcclusionScene(const OcclusionScene&) = delete;
    OcclusionScene& operator=(const OcclusionScene&) = delete;

    // True when the segment origin + t dir, t in (tNear, tFar), hits the mesh.
    bool occluded(const Imath::V3f& origin, const Imath::V3f& dir, float tNear, float tFar) const;
    // The diagonal of the mesh's bounding box: the scale for ray offsets.
    float extent() const { return extent_; }

private:
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    float extent_ = 0.0f;
};

}  // namespace opal
