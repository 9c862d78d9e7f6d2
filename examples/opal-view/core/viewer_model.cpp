#include "examples/opal-view/core/viewer_model.h"

#include "examples/opal-view/core/material_edit.h"
#include "examples/scene/render_settings_prim.h"
#include "schema/error.h"

namespace opal::view {
namespace {

bool sameCamera(const hd::CameraDesc& a, const hd::CameraDesc& b) {
    return a.transform == b.transform && a.focalLength == b.focalLength && a.horizontalAperture == b.horizontalAperture &&
           a.verticalAperture == b.verticalAperture && a.nearClip == b.nearClip && a.farClip == b.farClip;
}

}  // namespace

ViewerModel::ViewerModel(hd::RenderDelegate& delegate, int width, int height) : delegate_(delegate) {
    viewport_ = {ViewCameraPath, width, height, {}};
}

void ViewerModel::open(const std::filesystem::path& file) {
    SceneDocument document = loadDocument(file, assets_);
    for (const std::string& warning : assets_.takeWarnings()) document.scene.warnings.push_back(warning);
    const BoundingSphere bounds = sceneBounds(document.scene);
    if (document.scene.renderSettings) scene::applyRenderSettings(*document.scene.renderSettings, delegate_);

    session_.reset();  // one index per delegate at a time: the old one goes first
    file_ = file;
    bounds_ = bounds;
    loadWarnings_ = document.scene.warnings;
    selectedMesh_ = document.scene.meshes.begin()->first;
    selectedLight.reset();
    if (!document.scene.lights.empty()) selectedLight = document.scene.lights.begin()->first;
    document_ = std::move(document);
    home_ = initialCamera();
    camera = home_;
    scene::Scene scene = document_->scene;
    scene.cameras[ViewCameraPath] = {cameraDesc(camera, bounds_), {}};
    edited_.emplace(scene);
    session_ = std::make_unique<RenderSession>(delegate_, std::move(scene), viewport_);
    submitted_ = viewport_;
}

OrbitCamera ViewerModel::initialCamera() const {
    if (document_->sceneCamera) return orbitFromCamera(document_->scene.cameras.at(*document_->sceneCamera).desc, bounds_);
    OrbitCamera framed;
    framed.yaw = 20.0;
    framed.pitch = 15.0;
    frame(framed, bounds_, aspect());
    return framed;
}

std::vector<std::string> ViewerModel::takeLoadWarnings() {
    std::vector<std::string> warnings;
    warnings.swap(loadWarnings_);
    return warnings;
}

void ViewerModel::selectMesh(const hd::SdfPath& mesh) {
    if (!scene().meshes.count(mesh)) throw Error("no mesh <" + mesh + "> in the scene");
    selectedMesh_ = mesh;
}

const TranslucentAsset& ViewerModel::selectedAsset() const { return *scene().meshes.at(selectedMesh_).desc.asset; }

const hd::SdfPath& ViewerModel::selectedMaterialPath() const { return scene().meshes.at(selectedMesh_).desc.material; }

const hd::MaterialDesc& ViewerModel::selectedMaterial() const {
    return scene().materials.at(selectedMaterialPath()).desc;
}

void ViewerModel::setSelectedMaterial(const hd::MaterialDesc& desc) { edited_->setMaterial(selectedMaterialPath(), desc); }

void ViewerModel::setMaterialParameter(std::string_view parameter, std::span<const double> values) {
    setSelectedMaterial(withParameter(selectedMaterial(), parameter, values, selectedAsset()));
}

void ViewerModel::resetMaterial() { setSelectedMaterial(bakedDefault(selectedAsset())); }

const hd::LightDesc& ViewerModel::light(const hd::SdfPath& path) const {
    const auto it = scene().lights.find(path);
    if (it == scene().lights.end()) {
        std::string known;
        for (const auto& entry : scene().lights) known += (known.empty() ? "<" : ", <") + entry.first + ">";
        throw Error("no light <" + path + "> in the scene (lights: " + (known.empty() ? "none" : known) + ")");
    }
    return it->second.desc;
}

void ViewerModel::setLight(const hd::SdfPath& path, const hd::LightDesc& desc) { edited_->setLight(path, desc); }

void ViewerModel::moveLight(const hd::SdfPath& path, const Imath::V3d& position) {
    setLight(path, movedLight(light(path), position));
}

void ViewerModel::frameAll() { frame(camera, bounds_, aspect()); }

void ViewerModel::resetCamera() { camera = home_; }

void ViewerModel::setViewport(int width, int height) {
    viewport_.width = std::max(width, 1);
    viewport_.height = std::max(height, 1);
}

int ViewerModel::update() {
    if (!session_) return 0;
    const hd::CameraDesc desc = cameraDesc(camera, bounds_);
    if (!sameCamera(desc, scene().cameras.at(ViewCameraPath).desc)) edited_->setCamera(ViewCameraPath, desc);
    if (!edited_->changed() && viewport_ == submitted_) return 0;
    if (!session_->firstPassDone()) return 0;  // the edits wait, merged, for the next frame
    submitted_ = viewport_;
    return session_->submit(scene(), edited_->takeChanges(), viewport_);
}

bool ViewerModel::settled() const { return session_ && !edited_->changed() && viewport_ == submitted_ && session_->settled(); }

}  // namespace opal::view
