// The preview delegate's prims: each keeps the description its sync pulls from the scene
// delegate, for the render pass and commitResources to read. Meshes, materials and
// cameras are used; lights are kept only so that a lit scene populates (the preview lights
// every mesh from the camera, whatever the scene's lights).
#pragma once

#include "delegate/hd/prim.h"

namespace opal::preview {

template <class Desc, Desc (hd::SceneDelegate::*Pull)(const hd::SdfPath&) const, class Base>
class PulledPrim final : public Base {
public:
    // `syncs` (may be null) counts this prim's syncs: the delegate rebuilds what depends on
    // it when the count moved. It must outlive the prim.
    explicit PulledPrim(hd::SdfPath id, int* syncs = nullptr) : Base(std::move(id)), syncs_(syncs) {}

    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) override {
        desc_ = (scene.*Pull)(this->id());
        if (syncs_) ++*syncs_;
        *dirtyBits = hd::Dirty::Clean;
    }
    hd::DirtyBits initialDirtyBits() const override { return hd::Dirty::AllDirty; }
    const Desc& desc() const { return desc_; }

private:
    Desc desc_;
    int* syncs_;
};

using PreviewMesh = PulledPrim<hd::MeshDesc, &hd::SceneDelegate::mesh, hd::Rprim>;
using PreviewMaterial = PulledPrim<hd::MaterialDesc, &hd::SceneDelegate::material, hd::Sprim>;
using PreviewCamera = PulledPrim<hd::CameraDesc, &hd::SceneDelegate::camera, hd::Sprim>;
using PreviewLight = PulledPrim<hd::LightDesc, &hd::SceneDelegate::light, hd::Sprim>;

}  // namespace opal::preview
