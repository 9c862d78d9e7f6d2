// The material Sprim (Opal's material override): subsurface coefficients and the specular
// layer. Materials sync before meshes; commitResources hands every mesh bound to a material
// whose version changed the new values, which the relighting engine applies in O(K N)
// without new sparse products (docs/ARCHITECTURE.md#relighting).
#pragma once

#include "delegate/hd/prim.h"
#include "delegate/prim_version.h"

namespace opal {

class OpalMaterial final : public hd::Sprim {
public:
    OpalMaterial(const hd::SdfPath& id, PrimVersions& versions) : hd::Sprim(id), versions_(versions) {}

    // Pulls the description on any dirty bit. Throws opal::Error naming the prim for a
    // non-positive or non-finite coefficient, eta < 1, or a roughness outside [0, 1].
    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) override;
    hd::DirtyBits initialDirtyBits() const override { return hd::Dirty::Material | hd::Dirty::Params; }

    std::uint64_t version() const { return version_; }
    const hd::MaterialDesc& desc() const { return desc_; }

private:
    PrimVersions& versions_;
    std::uint64_t version_ = 0;
    hd::MaterialDesc desc_;
};

}  // namespace opal
