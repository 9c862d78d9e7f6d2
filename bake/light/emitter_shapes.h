// The emitters of simple shapes, in the light's frame (mm, +Y up), each emitting a uniform
// RGB radiance from its front (outward) faces:
//   sphere     radius a about the origin (128 x 64 facets: its projected area is within
//              1e-3 of the true sphere's; 4 times as many facets cost 30% more bake time);
//   disk       radius a in the XZ plane at the origin, emitting toward -Y (a ceiling
//              light), dark and opaque from above;
//   rectangle  width (X) x height (Z) in the XZ plane centred at the origin, toward -Y;
//   lamp       an emissive closed cylinder (radius, height; axis +Y, centred at the
//              origin) inside an opaque, black, open-ended tube, the shade (shadeRadius >
//              radius, shadeHeight, same axis and centre): light leaves only through the
//              shade's openings;
//   mesh       the polygons of a file (bake/mesh_import.h), emitting from their front
//              faces (counter-clockwise seen from the front).
#pragma once

#include "bake/light/emitter.h"

#include <filesystem>

namespace opal {

Emitter sphereEmitter(double radius, const Imath::V3f& radiance);
Emitter diskEmitter(double radius, const Imath::V3f& radiance);
Emitter rectangleEmitter(double width, double height, const Imath::V3f& radiance);

struct LampShape {
    double radius = 0.0, height = 0.0;
    double shadeRadius = 0.0, shadeHeight = 0.0;
};
// Throws opal::Error unless every size is positive and finite and shadeRadius > radius.
Emitter lampEmitter(const LampShape& shape, const Imath::V3f& radiance);

// Throws opal::Error (naming the file) when it cannot be read.
Emitter meshEmitter(const std::filesystem::path& file, const Imath::V3f& radiance);

// A surface of revolution about +Y (bake/procedural_mesh.h) as a render mesh.
RenderMesh revolvedMesh(std::span<const Imath::V2f> profile, int segments, const std::string& name);

}  // namespace opal
