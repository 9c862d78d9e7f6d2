// What the preview tests render: a unit sphere at the origin (a UV sphere of exact unit
// normals) seen from a camera on +Z, served by a scene delegate of its own, and the closed
// form the picture must follow: the ray through a pixel, worked out here from the camera's
// film (not with the delegate's CameraView), hits the true sphere where n . v is known.
#pragma once

#include "delegate/hd/render_index.h"
#include "schema/scatter/material.h"

#include <Imath/ImathVec.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>

namespace opal::test {

inline constexpr int Width = 64, Height = 48;
inline constexpr double CameraDistance = 4.0;  // the camera at (0, 0, 4), looking down -Z
inline const hd::SdfPath SpherePath = "/World/Sphere", CameraPath = "/World/Camera", MaterialPath = "/World/Look";

// rings x segments quads (triangles at the poles' rings, as quads with a repeated pole).
inline std::shared_ptr<TranslucentAsset> uvSphere(int rings = 48, int segments = 96) {
    auto asset = std::make_shared<TranslucentAsset>();
    asset->name = "uvSphere";
    RenderMesh& mesh = asset->mesh;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const double theta = std::numbers::pi * r / rings, phi = 2.0 * std::numbers::pi * s / segments;
            const Imath::V3f p(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                               float(-std::sin(theta) * std::sin(phi)));
            mesh.points.push_back(p);
            mesh.normals.push_back(p.normalized());
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const int a = r * (segments + 1) + s, b = a + segments + 1;
            mesh.faceVertexCounts.push_back(4);
            for (const int v : {a, b, b + 1, a + 1}) mesh.faceVertexIndices.push_back(v);
        }
    // Albedo (0.6, 0.4, 0.2), 1 mm mean free path: what the picture must show head on.
    asset->defaultMaterial = fromArtist({{0.6, 0.4, 0.2}, {1.0, 1.0, 1.0}, 1.3});
    return asset;
}

struct SphereScene final : hd::SceneDelegate {
    hd::MeshDesc meshDesc;
    std::map<hd::SdfPath, hd::MaterialDesc> materials;
    hd::CameraDesc cameraDesc;

    SphereScene() {
        meshDesc.asset = uvSphere();
        cameraDesc.transform.setTranslation(Imath::V3d(0.0, 0.0, CameraDistance));
    }
    hd::MeshDesc mesh(const hd::SdfPath&) const override { return meshDesc; }
    hd::MaterialDesc material(const hd::SdfPath& id) const override { return materials.at(id); }
    hd::LightDesc light(const hd::SdfPath&) const override { return {}; }
    hd::CameraDesc camera(const hd::SdfPath&) const override { return cameraDesc; }

    void populate(hd::RenderIndex& index) const {
        for (const auto& [path, desc] : materials) index.insertSprim(hd::PrimType::Material, *this, path);
        index.insertSprim(hd::PrimType::Camera, *this, CameraPath);
        index.insertSprim(hd::PrimType::SphereLight, *this, "/World/Key");  // accepted, unused
        index.insertRprim(hd::PrimType::TranslucentMesh, *this, SpherePath);
    }
};

// n . v where the ray through pixel (x, y)'s centre meets the unit sphere, none if it
// misses. The 36 x 24 mm film at 50 mm is fitted into the 64 x 48 image: its width fills it.
inline std::optional<double> sphereCosine(int x, int y) {
    const double halfWidth = 18.0 / 50.0, halfHeight = halfWidth * Height / Width;
    const Imath::V3d d = Imath::V3d((2.0 * (x + 0.5) / Width - 1.0) * halfWidth,
                                    (1.0 - 2.0 * (y + 0.5) / Height) * halfHeight, -1.0).normalized();
    const Imath::V3d o(0.0, 0.0, CameraDistance);
    const double b = o.dot(d), c = o.dot(o) - 1.0, discriminant = b * b - c;
    if (discriminant < 0.0) return std::nullopt;
    const Imath::V3d p = o + d * (-b - std::sqrt(discriminant));
    return p.dot(-d);  // |p| = 1: p is the normal
}

}  // namespace opal::test
