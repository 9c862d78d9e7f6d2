// A local light's emitter (docs/ARCHITECTURE.md#shadow-field): triangle-mesh parts in the
// light's frame (millimetres, right-handed, +Y up), each with an emission profile giving
// the radiance a ray sees where it hits the part, RGB per channel in scene-linear units
// (radiance: power per area per steradian; the light's intensity, color and exposure
// scale it). A part without a profile is opaque and black (a lamp's shade): it blocks
// rays and emits nothing.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <Imath/ImathVec.h>

#include <functional>
#include <string>
#include <vector>

namespace opal {

// Where a ray met an emitter part.
struct EmitterHit {
    Imath::V3f point;      // light frame, mm
    Imath::V3f direction;  // the ray's unit direction (from the viewer toward the emitter)
    Imath::V3f normal;     // unit geometric normal of the triangle hit (outward)
};

using EmissionProfile = std::function<Imath::V3f(const EmitterHit&)>;

struct EmitterPart {
    std::string name;
    RenderMesh mesh;          // light frame, mm; faces wind counter-clockwise seen from the front
    EmissionProfile emission;  // empty: opaque, emits nothing
};

struct Emitter {
    std::string kind;         // "sphere", "flame", ...
    std::string description;  // every parameter that shapes the emission, as canonical text
    std::vector<EmitterPart> parts;
};

struct BoundingSphere {
    Imath::V3d centre{0.0};
    double radius = 0.0;
};

// The sphere about the centre of the emitter's bounding box that holds every point of
// every part. Throws opal::Error for an emitter without points.
BoundingSphere boundingSphere(const Emitter& emitter);

// Uniform radiance `rgb` seen from the front (rays against the face normal), black from behind.
EmissionProfile frontFaceEmission(const Imath::V3f& rgb);

}  // namespace opal
