// An emitter ready for ray tracing: its parts in one Embree scene (raytrace/ray_scene.h,
// the light's frame is the scene's world), and what a ray that hits a part sees.
#pragma once

#include "bake/light/emitter.h"
#include "raytrace/ray_scene.h"

#include <optional>

namespace opal {

class EmitterScene {
public:
    // Throws opal::Error for an emitter without parts or with a part Embree refuses.
    explicit EmitterScene(const Emitter& emitter);

    const BoundingSphere& bounds() const { return bounds_; }
    const RayScene& rays() const { return scene_; }
    // The radiance arriving along `ray` from what it hit (black for a miss or an opaque part).
    Imath::V3f radiance(const Ray& ray, const std::optional<RayHit>& hit) const;

private:
    const Emitter& emitter_;
    BoundingSphere bounds_;
    RayScene scene_{RayScene::BuildQuality::High};
};

}  // namespace opal
