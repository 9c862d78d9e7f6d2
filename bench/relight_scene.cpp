#include "bench/relight_scene.h"

#include "schema/error.h"

#include <Imath/ImathBox.h>
#include <Imath/ImathMatrixAlgo.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal::bench {

namespace {

constexpr double kLightDistance = 3.0;       // bounding radii from the centre
constexpr double kFramingMargin = 1.1;       // the bounding box fills 1/1.1 of the frame (at its front)
constexpr double kGoldenAngle = 137.50776;   // degrees: successive steps never repeat a direction

Imath::M44d translation(const Imath::V3d& t) {
    Imath::M44d m;
    m.setTranslation(t);
    return m;
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

RelightScene::RelightScene(std::shared_ptr<const TranslucentAsset> asset, const Material& material,
                           std::string domeFile, double aspect, Key key)
    : asset_(std::move(asset)), domeFile_(std::move(domeFile)), key_(key) {
    if (!asset_ || asset_->mesh.points.empty()) throw Error("relight scene: the asset has no render mesh");
    for (const Imath::V3f& p : asset_->mesh.points) bounds_.extendBy(Imath::V3d(p));
    centre_ = bounds_.center();
    radius_ = std::max(0.5 * bounds_.size().length(), 1e-6);
    material_.subsurface = material;

    // A point light of radiant intensity pi * intensity (treatAsPoint): E_perp = 1 at the
    // centre from kLightDistance radii.
    keyLight_.kind = hd::LightKind::Sphere;
    keyLight_.treatAsPoint = true;
    keyLight_.intensity = std::pow(kLightDistance * radius_, 2) / std::numbers::pi;
    if (key_ == Key::Distant) {
        // Normalized: E_perp = intensity whatever the angle.
        keyLight_.kind = hd::LightKind::Distant;
        keyLight_.normalize = true;
        keyLight_.intensity = 1.0;
    }
    keyLight_ = keyLightAt(0);

    dome_.kind = hd::LightKind::Dome;
    dome_.textureFile = domeFile_;

    camera_ = framingCamera(aspect);
}

// UsdGeomCamera's default film (36 x 24 mm, 50 mm lens) on +Z looking down -Z at the
// box's centre, as close as lets the box's front face (its nearest part, so the widest
// angle) fit the image with a margin: the film's height fits ("fit" conform), and the
// image's aspect sets the horizontal half angle.
hd::CameraDesc RelightScene::framingCamera(double aspect) const {
    hd::CameraDesc camera;
    const double tanVertical = 0.5 * camera.verticalAperture / camera.focalLength;
    const double filmAspect = camera.horizontalAperture / camera.verticalAperture;
    const double tanHorizontal = tanVertical * std::max(aspect, filmAspect);
    const Imath::V3d half = 0.5 * bounds_.size();
    const double front = kFramingMargin * std::max(half.y / tanVertical, half.x / tanHorizontal);
    const double distance = half.z + std::max(front, 1e-6);
    camera.transform = translation(centre_ + Imath::V3d(0.0, 0.0, distance));
    camera.nearClip = 0.01 * distance;
    camera.farClip = 100.0 * distance;
    return camera;
}

Imath::V3d RelightScene::keyLightPosition(int step) const {
    const double azimuth = radians(30.0 + kGoldenAngle * step);
    const double elevation = radians(step % 2 == 0 ? 35.0 : 15.0);
    const Imath::V3d direction(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                               std::cos(elevation) * std::cos(azimuth));
    return centre_ + kLightDistance * radius_ * direction;
}

void RelightScene::populate(hd::RenderIndex& index) const {
    index.insertSprim(hd::PrimType::Material, *this, MaterialPath);
    if (key_ == Key::Point) index.insertSprim(hd::PrimType::SphereLight, *this, KeyLightPath);
    if (key_ == Key::Distant) index.insertSprim(hd::PrimType::DistantLight, *this, KeyLightPath);
    if (hasDome()) index.insertSprim(hd::PrimType::DomeLight, *this, DomePath);
    index.insertSprim(hd::PrimType::Camera, *this, CameraPath);
    index.insertRprim(hd::PrimType::TranslucentMesh, *this, MeshPath);
}

void RelightScene::setMaterial(hd::RenderIndex& index, const Material& material) {
    material_.subsurface = material;
    index.changeTracker().markDirty(MaterialPath, hd::Dirty::Material);
}

hd::LightDesc RelightScene::keyLightAt(int step) const {
    hd::LightDesc key = keyLight_;
    const Imath::V3d position = keyLightPosition(step);
    if (key.kind == hd::LightKind::Distant) {
        // -Z (the direction a distant light shines along) turned towards the centre.
        key.transform = Imath::rotationMatrix(Imath::V3d(0.0, 0.0, -1.0), (centre_ - position).normalized());
    } else {
        key.transform = translation(position);
    }
    return key;
}

hd::LightDesc RelightScene::domeAt(double degrees) const {
    hd::LightDesc dome = dome_;
    dome.transform.setAxisAngle(Imath::V3d(0.0, 1.0, 0.0), radians(degrees));
    return dome;
}

void RelightScene::moveKeyLight(hd::RenderIndex& index, int step) {
    keyLight_ = keyLightAt(step);
    index.changeTracker().markDirty(KeyLightPath, hd::Dirty::Transform);
}

void RelightScene::rotateDome(hd::RenderIndex& index, double degrees) {
    dome_ = domeAt(degrees);
    index.changeTracker().markDirty(DomePath, hd::Dirty::Transform);
}

hd::MeshDesc RelightScene::mesh(const hd::SdfPath& id) const {
    if (id != MeshPath) throw Error("relight scene: no mesh '" + id + "'");
    return hd::MeshDesc{asset_, Imath::M44d(), MaterialPath, true};
}

hd::MaterialDesc RelightScene::material(const hd::SdfPath& id) const {
    if (id != MaterialPath) throw Error("relight scene: no material '" + id + "'");
    return material_;
}

hd::LightDesc RelightScene::light(const hd::SdfPath& id) const {
    if (id == KeyLightPath && hasKeyLight()) return keyLight_;
    if (id == DomePath && hasDome()) return dome_;
    throw Error("relight scene: no light '" + id + "'");
}

hd::CameraDesc RelightScene::camera(const hd::SdfPath& id) const {
    if (id != CameraPath) throw Error("relight scene: no camera '" + id + "'");
    return camera_;
}

}  // namespace opal::bench
