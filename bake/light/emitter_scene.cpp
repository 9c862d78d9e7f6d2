#include "bake/light/emitter_scene.h"

#include "schema/error.h"

#include <Imath/ImathMatrix.h>

namespace opal {

EmitterScene::EmitterScene(const Emitter& emitter) : emitter_(emitter), bounds_(boundingSphere(emitter)) {
    for (const EmitterPart& part : emitter.parts) scene_.addMesh(part.mesh, Imath::M44d());
    scene_.commit();
}

Imath::V3f EmitterScene::radiance(const Ray& ray, const std::optional<RayHit>& hit) const {
    if (!hit) return Imath::V3f(0.0f);
    const EmitterPart& part = emitter_.parts[hit->prim];
    if (!part.emission) return Imath::V3f(0.0f);
    const float length = hit->geometricNormal.length();
    if (!(length > 0.0f)) return Imath::V3f(0.0f);
    return part.emission({ray.origin() + ray.direction() * hit->t, ray.direction(), hit->geometricNormal / length});
}

}  // namespace opal
