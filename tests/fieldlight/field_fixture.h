// What the shadow-field light tests share: a uniformly emitting sphere's field, baked once
// per process and written to a light sidecar (the delegate loads lights from files), and
// small meshes for the ray scene. The sphere's analytic irradiance is the independent truth:
// a sphere of radiance L and radius a seen from distance d by a surface whose normal is
// tilted by theta from the centre, the sphere wholly above the horizon, gives
// E = pi L (a / d)^2 cos(theta).
//
// The field is baked at the shipped map size (6 x 32 x 32, which fixes the visibility
// blocks) with fewer shells and sample directions than the default, so the suite bakes in
// seconds; the delegate's evaluation has no settings of its own.
#pragma once

#include "bake/light/emitter_shapes.h"
#include "bake/light/field_bake.h"
#include "delegate/relight/shadow_field_light.h"
#include "schema/asset/shadow_field_file.h"
#include "tests/render/render_scene.h"
#include "tests/support/open_temp_dir.h"

#include <memory>
#include <numbers>

namespace opal::test {

inline constexpr double kEmitterRadius = 2.0;  // mm
inline const Imath::V3f kEmitterRadiance(3.0f, 2.0f, 1.0f);

struct SphereField {
    OpenTempDir dir;
    std::filesystem::path file;
    std::shared_ptr<const LoadedShadowField> loaded;
};

inline const SphereField& sphereField() {
    static const SphereField* field = [] {
        auto* f = new SphereField;
        FieldSettings settings;
        settings.shells = 8;
        settings.directionFaceSize = 8;
        ShadowField baked = bakeShadowField(sphereEmitter(kEmitterRadius, kEmitterRadiance), settings, nullptr, {});
        f->file = f->dir / "sphere.light.opal";
        writeShadowFieldFile(f->file, baked);
        f->loaded = std::make_shared<const LoadedShadowField>(readShadowFieldFile(f->file));
        return f;
    }();
    return *field;
}

// pi L (a / d)^2 cos(theta) for one channel's radiance L.
inline double sphereIrradiance(double radiance, double radius, double distance, double cosTheta) {
    return std::numbers::pi * radiance * (radius / distance) * (radius / distance) * cosTheta;
}

inline hd::LightDesc fieldLightDesc(const Imath::M44d& transform, double intensity = 1.0) {
    hd::LightDesc d;
    d.kind = hd::LightKind::ShadowField;
    d.transform = transform;
    d.intensity = intensity;
    d.shadowField = sphereField().file.string();
    return d;
}

// An axis-aligned rectangle in the plane y = height over [x0, x1] x [z0, z1], one quad.
inline RenderMesh rectangleY(double height, double x0, double x1, double z0, double z1) {
    RenderMesh mesh;
    const float y = float(height);
    mesh.points = {{float(x0), y, float(z0)}, {float(x1), y, float(z0)}, {float(x1), y, float(z1)},
                   {float(x0), y, float(z1)}};
    mesh.faceVertexCounts = {4};
    mesh.faceVertexIndices = {0, 1, 2, 3};
    return mesh;
}

}  // namespace opal::test
