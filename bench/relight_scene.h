// The scene `opal-bench relight` drives through the render delegate (as a host would, via
// hd::RenderIndex): the asset at the origin bound to a material prim, a point light, an
// optional dome (the environment map) and a camera framing the asset's bounding box. Each
// edit changes the scene's description and marks the prim dirty with the bit a host would
// set; the next RenderIndex::sync() pulls it and commits, which is what the bench times.
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/hd/scene_delegate.h"

#include <Imath/ImathBox.h>
#include <Imath/ImathVec.h>

#include <memory>
#include <string>

namespace opal::bench {

class RelightScene final : public hd::SceneDelegate {
public:
    static inline const hd::SdfPath MeshPath = "/World/Asset";
    static inline const hd::SdfPath MaterialPath = "/World/Looks/Subsurface";
    static inline const hd::SdfPath KeyLightPath = "/World/Lights/Key";
    static inline const hd::SdfPath DomePath = "/World/Lights/Dome";
    static inline const hd::SdfPath CameraPath = "/World/Camera";

    // The key light: a point light (a sphere prim treated as a point), a distant light
    // shining from the point light's position towards the asset's centre, or none.
    enum class Key { Point, Distant, None };

    // domeFile empty: no dome. The key light starts at keyLightPosition(0), the dome at 0
    // degrees, the material prim holds `material`; the camera frames the asset's bounding
    // box in images of width / height = aspect. Either key light gives E_perp = 1 at the
    // asset's centre.
    RelightScene(std::shared_ptr<const TranslucentAsset> asset, const Material& material, std::string domeFile,
                 double aspect, Key key = Key::Point);

    // Inserts every prim into `index` (all dirty).
    void populate(hd::RenderIndex& index) const;

    // The edits: each sets the new value and marks the prim dirty in `index`.
    void setMaterial(hd::RenderIndex& index, const Material& material);
    void moveKeyLight(hd::RenderIndex& index, int step);     // to keyLightAt(step)
    void rotateDome(hd::RenderIndex& index, double degrees);  // to domeAt(degrees)

    // The lights as the edits leave them, without editing.
    hd::LightDesc keyLightAt(int step) const;
    hd::LightDesc domeAt(double degrees) const;  // rotated about world +Y

    // Step i of the key light's path: a distinct point for every i (golden-angle turns
    // about the asset's vertical axis, alternating elevations), 3 bounding radii from the
    // centre, so the light never enters the asset.
    Imath::V3d keyLightPosition(int step) const;

    bool hasDome() const { return !domeFile_.empty(); }
    bool hasKeyLight() const { return key_ != Key::None; }
    const hd::LightDesc& keyLight() const { return keyLight_; }
    const hd::LightDesc& dome() const { return dome_; }

    hd::MeshDesc mesh(const hd::SdfPath& id) const override;
    hd::MaterialDesc material(const hd::SdfPath& id) const override;
    hd::LightDesc light(const hd::SdfPath& id) const override;
    hd::CameraDesc camera(const hd::SdfPath& id) const override;

private:
    hd::CameraDesc framingCamera(double aspect) const;

    std::shared_ptr<const TranslucentAsset> asset_;
    std::string domeFile_;
    Key key_ = Key::Point;
    Imath::Box3d bounds_;
    Imath::V3d centre_;
    double radius_ = 1.0;  // half the bounding box's diagonal
    hd::MaterialDesc material_;
    hd::LightDesc keyLight_, dome_;
    hd::CameraDesc camera_;
};

}  // namespace opal::bench
