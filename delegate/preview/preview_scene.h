// What the preview renders of a render index: its visible meshes in world space as one
// Embree scene (raytrace/), and per mesh what shading needs: the vertex normals, the
// matrix taking them to world space, the albedo of its material, and its primId (the
// mesh's number in path order, as Opal numbers meshes; hidden meshes keep theirs).
#pragma once

#include "delegate/hd/render_index.h"
#include "raytrace/ray_scene.h"
#include "schema/scatter/rgb.h"

#include <memory>
#include <vector>

namespace opal::preview {

struct ShadedMesh {
    hd::SdfPath path;                               // the mesh prim, for errors
    std::shared_ptr<const TranslucentAsset> asset;  // keeps the normals alive
    Imath::M44d normalToWorld;  // the inverse transpose of object to world (row vectors)
    hd::SdfPath material;       // empty: the asset's default material
    Rgb albedo;                 // the material's total diffuse reflectance (toArtist)
    int primId = 0;
};

class PreviewScene {
public:
    // The index's meshes (PreviewMesh prims) as they synced. Throws opal::Error for a mesh
    // without an asset or with points Embree refuses (naming the mesh).
    explicit PreviewScene(const hd::RenderIndex& index);

    // Every mesh's albedo from its material prim now (materials change without geometry).
    // Throws opal::Error naming the material for one toArtist refuses.
    void updateAlbedos(const hd::RenderIndex& index);

    const RayScene& rays() const { return rays_; }
    // By RayHit::prim.
    const ShadedMesh& mesh(std::uint32_t prim) const { return meshes_[prim]; }
    std::size_t triangleCount() const { return triangles_; }

    // The unit world-space shading normal at a hit: the vertex normals interpolated.
    Imath::V3f shadingNormal(const RayHit& hit) const;

private:
    RayScene rays_;
    std::vector<ShadedMesh> meshes_;
    std::size_t triangles_ = 0;
};

}  // namespace opal::preview
