#include "bake/light/emitter.h"

#include "schema/error.h"

#include <Imath/ImathBox.h>

#include <algorithm>

namespace opal {

BoundingSphere boundingSphere(const Emitter& emitter) {
    Imath::Box3d box;
    for (const EmitterPart& part : emitter.parts)
        for (const Imath::V3f& p : part.mesh.points) box.extendBy(Imath::V3d(p));
    if (box.isEmpty()) throw Error("emitter '" + emitter.kind + "' has no points");
    BoundingSphere sphere{box.center(), 0.0};
    for (const EmitterPart& part : emitter.parts)
        for (const Imath::V3f& p : part.mesh.points)
            sphere.radius = std::max(sphere.radius, (Imath::V3d(p) - sphere.centre).length());
    return sphere;
}

EmissionProfile frontFaceEmission(const Imath::V3f& rgb) {
    return [rgb](const EmitterHit& hit) { return hit.direction.dot(hit.normal) < 0.0f ? rgb : Imath::V3f(0.0f); };
}

}  // namespace opal
