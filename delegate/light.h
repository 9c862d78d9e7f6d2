// The light Sprims (UsdLux SphereLight with its spot shaping, DistantLight, DomeLight, and
// Opal's OpalShadowFieldLight): each pulls its hd::LightDesc and turns it into what
// irradiance and the specular layer use, an AnalyticLight, an EnvironmentLight over the
// (cached) dome texture or a ShadowFieldLight over the (cached) baked field. The delegate's
// commitResources recomputes E only for the lights whose version changed
// (docs/ARCHITECTURE.md#irradiance).
#pragma once

#include "delegate/relight/analytic_light.h"
#include "delegate/dome_texture.h"
#include "delegate/relight/environment_light.h"
#include "delegate/hd/prim.h"
#include "delegate/prim_version.h"
#include "delegate/shadow_field_cache.h"

#include <Imath/ImathMatrix.h>

#include <memory>
#include <optional>

namespace opal {

class OpalLight final : public hd::Sprim {
public:
    // type: hd::PrimType::SphereLight, DistantLight, DomeLight or ShadowFieldLight (throws
    // opal::Error otherwise).
    OpalLight(const hd::SdfPath& id, const hd::Token& type, DomeTextureCache& textures, ShadowFieldCache& fields,
              PrimVersions& versions);

    // Pulls the description on any dirty bit. Throws opal::Error naming the prim when the
    // description's kind is not the prim's type, its parameters are invalid or a dome's
    // texture or a shadow field's sidecar does not load; the light keeps its previous state then.
    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) override;
    hd::DirtyBits initialDirtyBits() const override {
        return hd::Dirty::Transform | hd::Dirty::Params | hd::Dirty::Visibility;
    }
    // Re-reads a dome's texture through `textures` (after the OCIO config changed).
    void reloadTexture();

    std::uint64_t version() const { return version_; }
    bool isDome() const { return kind_ == hd::LightKind::Dome; }
    hd::LightKind kind() const { return kind_; }
    const hd::LightDesc& desc() const { return desc_; }
    // Set after a successful sync for sphere and distant lights.
    const std::optional<AnalyticLight>& analytic() const { return analytic_; }
    // Set after a successful sync for a shadow-field light.
    const std::shared_ptr<const ShadowFieldLight>& field() const { return field_; }
    // Set after a successful sync for a dome.
    const std::shared_ptr<const EnvironmentLight>& environment() const { return environment_; }
    const std::shared_ptr<const LatLongMap>& domeMap() const { return map_; }
    // A dome's world-to-dome rotation and its scale color * intensity * 2^exposure.
    const Imath::M33d& domeFromWorld() const { return domeFromWorld_; }
    const Rgb& domeScale() const { return domeScale_; }

private:
    void build(const hd::LightDesc& desc, std::shared_ptr<const LatLongMap> map,
               std::shared_ptr<const LoadedShadowField> field);

    hd::LightKind kind_;
    DomeTextureCache& textures_;
    ShadowFieldCache& fields_;
    PrimVersions& versions_;
    std::uint64_t version_ = 0;
    hd::LightDesc desc_;
    std::optional<AnalyticLight> analytic_;
    std::shared_ptr<const ShadowFieldLight> field_;
    std::shared_ptr<const LatLongMap> map_;
    std::shared_ptr<const EnvironmentLight> environment_;
    Imath::M33d domeFromWorld_;
    Rgb domeScale_{0.0, 0.0, 0.0};
};

// "sphere", "distant", "dome" or "shadow field": for messages.
const char* lightKindName(hd::LightKind kind);

}  // namespace opal
