#include "delegate/preview/preview_scene.h"

#include "delegate/hd/mesh_material.h"
#include "delegate/preview/preview_prims.h"
#include "schema/error.h"
#include "schema/scatter/material.h"

namespace opal::preview {
namespace {

Material materialOf(const hd::RenderIndex& index, const ShadedMesh& mesh) {
    const auto* prim =
        mesh.material.empty() ? nullptr : dynamic_cast<const PreviewMaterial*>(index.sprim(mesh.material));
    return hd::meshMaterial(mesh.material, *mesh.asset, prim ? &prim->desc() : nullptr).subsurface;
}

}  // namespace

PreviewScene::PreviewScene(const hd::RenderIndex& index) {
    int primId = 0;
    index.forEachRprim([&](hd::Rprim& rprim) {
        const auto* prim = dynamic_cast<const PreviewMesh*>(&rprim);
        const int id = primId++;
        if (!prim || !prim->desc().visible) return;
        const hd::MeshDesc& desc = prim->desc();
        if (!desc.asset) throw Error("preview delegate: mesh <" + prim->id() + "> has no asset");
        try {
            rays_.addMesh(desc.asset->mesh, desc.transform);
        } catch (const Error& e) {
            throw Error("preview delegate: mesh <" + prim->id() + ">: " + e.what());
        }
        meshes_.push_back({prim->id(), desc.asset, desc.transform.inverse().transposed(), desc.material, Rgb(0.0), id});
        triangles_ += rays_.triangles(rays_.meshCount() - 1).size() / 3;
    });
    rays_.commit();
}

void PreviewScene::updateAlbedos(const hd::RenderIndex& index) {
    for (ShadedMesh& mesh : meshes_) {
        try {
            mesh.albedo = toArtist(materialOf(index, mesh)).albedo;
        } catch (const Error& e) {
            throw Error("preview delegate: mesh <" + mesh.path + ">: " + e.what());
        }
    }
}

Imath::V3f PreviewScene::shadingNormal(const RayHit& hit) const {
    const ShadedMesh& mesh = meshes_[hit.prim];
    const std::array<std::uint32_t, 3> v = rays_.triangleVertices(hit.prim, hit.triangle);
    const std::vector<Imath::V3f>& normals = mesh.asset->mesh.normals;
    if (normals.size() != mesh.asset->mesh.points.size()) return hit.geometricNormal.normalized();
    Imath::V3f local = normals[v[0]] * (1.0f - hit.u - hit.v) + normals[v[1]] * hit.u + normals[v[2]] * hit.v;
    Imath::V3d world;
    mesh.normalToWorld.multDirMatrix(Imath::V3d(local), world);
    const double length = world.length();
    // Normals that cancel there: the triangle's own.
    if (!(length > 0.0)) return hit.geometricNormal.normalized();
    return Imath::V3f(world / length);
}

}  // namespace opal::preview
