#include "examples/opal-view/core/viewer_model.h"

#include "examples/opal-view/core/layer_precision.h"
#include "examples/opal-view/core/light_layer.h"
#include "examples/opal-view/core/material_edit.h"
#include "examples/opal-view/core/prim_path.h"
#include "examples/opal-view/core/setting_text.h"
#include "examples/opal-view/core/usda_export.h"
#include "examples/scene/render_settings_prim.h"
#include "examples/scene/scene_reader.h"
#include "examples/scene/scene_material.h"
#include "schema/error.h"

#include <algorithm>
#include <cmath>

namespace opal::view {
namespace {

const hd::Token ReferenceSetting = "opal:reference";

// The settings for the reference session: opal:reference stays on.
RenderSettingChanges asReference(RenderSettingChanges settings) {
    for (auto& [key, value] : settings)
        if (key == ReferenceSetting) value = true;
    return settings;
}

bool sameCamera(const hd::CameraDesc& a, const hd::CameraDesc& b) {
    return a.transform == b.transform && a.focalLength == b.focalLength && a.horizontalAperture == b.horizontalAperture &&
           a.verticalAperture == b.verticalAperture && a.nearClip == b.nearClip && a.farClip == b.farClip;
}

}  // namespace

// The settings that differ from their defaults (those waiting for the worker included):
// what a saved scene authors.
RenderSettingChanges ViewerModel::changedSettings() const {
    RenderSettingChanges changed;
    for (const hd::RenderSettingDescriptor& setting : delegate_->renderSettingDescriptors()) {
        // The viewer's own draft pictures (viewer.cpp) change no converged pixel: not the scene's.
        if (setting.key == "opal:draftBlock") continue;
        const hd::Value value = renderSetting(setting.key);
        if (!(value == setting.defaultValue)) changed.emplace_back(setting.key, value);
    }
    return changed;
}

ViewerModel::ViewerModel(hd::RenderDelegate& delegate, int width, int height) : delegate_(&delegate) {
    viewport_ = {ViewCameraPath, width, height, {}};
}

void ViewerModel::open(const std::filesystem::path& file) {
    SceneDocument document = loadDocument(file, assets_);
    for (const std::string& warning : assets_.takeWarnings()) document.scene.warnings.push_back(warning);
    const BoundingSphere bounds = sceneBounds(document.scene);
    if (document.scene.renderSettings) scene::applyRenderSettings(*document.scene.renderSettings, *delegate_);

    referenceSession_.reset();
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
    usedCamera_.reset();
    viewport_.camera = ViewCameraPath;
    scene::Scene scene = document_->scene;
    scene.cameras[ViewCameraPath] = {cameraDesc(camera, bounds_), {}};
    edited_.emplace(scene);
    undo_.clear();
    merging_ = gestureOpen_ = false;
    savedRevision_ = edited_->revision();
    timeCode_ = document_->scene.timeCode;
    timeSource_ = file;
    playing = false;
    session_ = std::make_unique<RenderSession>(*delegate_, std::move(scene), viewport_);
    submitted_ = viewport_;
    startReference();
}

void ViewerModel::useDelegate(hd::RenderDelegate& delegate) {
    referenceSession_.reset();
    referenceDelegate_ = nullptr;  // the old renderer's
    session_.reset();  // one index per delegate at a time: the old one goes first
    delegate_ = &delegate;
    pendingSettings_.clear();      // the old delegate's
    if (!edited_) return;
    if (document_->scene.renderSettings) scene::applyRenderSettings(*document_->scene.renderSettings, delegate);
    edited_->takeChanges();        // the new session's first sync takes every prim
    session_ = std::make_unique<RenderSession>(delegate, edited_->renderedScene(), viewport_);
    submitted_ = viewport_;
}

void ViewerModel::showReference(hd::RenderDelegate* reference) {
    if (reference) {
        const auto settings = reference->renderSettingDescriptors();
        if (std::none_of(settings.begin(), settings.end(), [](const auto& s) { return s.key == ReferenceSetting; }))
            throw Error("the renderer has no '" + ReferenceSetting + "' setting to render a reference with");
    }
    referenceSession_.reset();
    referenceDelegate_ = reference;
    startReference();
}

void ViewerModel::startReference() {
    if (!referenceDelegate_ || !session_) return;
    for (const hd::RenderSettingDescriptor& setting : delegate_->renderSettingDescriptors())
        referenceDelegate_->setRenderSetting(setting.key, renderSetting(setting.key));
    referenceDelegate_->setRenderSetting(ReferenceSetting, true);
    referenceSession_ = std::make_unique<RenderSession>(*referenceDelegate_, edited_->renderedScene(), submitted_);
}

void ViewerModel::setTime(double timeCode) {
    if (!isOpen()) throw Error("no scene is open");
    if (!std::isfinite(timeCode)) throw Error("the time code is not finite");
    if (timeCode == timeCode_) return;
    std::optional<scene::Scene> atTime;
    // The whole file at the new time (lights' layers included; assets come from the cache):
    // a few milliseconds for a scene, once per interface frame while playing.
    if (!scene().timeVarying.empty()) atTime = scene::readScene(timeSource_, assets_, timeCode);
    edited_->setTime(atTime ? &*atTime : nullptr, timeCode);
    timeCode_ = timeCode;
}

bool ViewerModel::animated() const {
    if (!isOpen()) return false;
    if (!scene().timeVarying.empty()) return true;
    return std::any_of(scene().lights.begin(), scene().lights.end(),
                       [](const auto& light) { return light.second.desc.flicker.amplitude > 0.0; });
}

void ViewerModel::advance(double seconds) {
    if (!playing || !isOpen()) return;
    double next = timeCode_ + seconds * scene().timeCodesPerSecond;
    const scene::Scene& s = scene();
    if (s.startTimeCode && s.endTimeCode && *s.endTimeCode > *s.startTimeCode && next > *s.endTimeCode)
        next = *s.startTimeCode + std::fmod(next - *s.startTimeCode, *s.endTimeCode - *s.startTimeCode);
    try {
        setTime(next);
    } catch (const Error&) {
        playing = false;  // one message, not one a frame
        throw;
    }
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

void ViewerModel::setSelectedMaterial(const hd::MaterialDesc& desc) {
    recordUndo();
    edited_->setMaterial(selectedMaterialPath(), storable(desc));
}

void ViewerModel::setMaterialParameter(std::string_view parameter, std::span<const double> values) {
    setSelectedMaterial(withParameter(selectedMaterial(), parameter, values, selectedAsset()));
}

void ViewerModel::resetMaterial() { setSelectedMaterial(bakedDefault(selectedAsset())); }

void ViewerModel::applyPreset(std::string_view name) {
    const std::optional<Material> preset = findPreset(name);
    if (!preset) throw Error("unknown material preset '" + std::string(name) + "' (presets: " + scene::presetNames() + ")");
    hd::MaterialDesc desc = selectedMaterial();
    const TranslucentAsset& asset = selectedAsset();
    try {
        const double sigmaS[] = {preset->sigmaSPrime[0], preset->sigmaSPrime[1], preset->sigmaSPrime[2]};
        const double sigmaA[] = {preset->sigmaA[0], preset->sigmaA[1], preset->sigmaA[2]};
        desc = withParameter(desc, "sigma_s", sigmaS, asset);
        desc = withParameter(desc, "sigma_a", sigmaA, asset);
        const double eta[] = {preset->eta};
        desc = withParameter(desc, "eta", eta, asset);
    } catch (const Error& e) {
        throw Error("preset '" + std::string(name) + "': " + e.what());
    }
    setSelectedMaterial(desc);
}

const hd::LightDesc& ViewerModel::light(const hd::SdfPath& path) const {
    const auto it = scene().lights.find(path);
    if (it == scene().lights.end()) {
        std::string known;
        for (const auto& entry : scene().lights) known += (known.empty() ? "<" : ", <") + entry.first + ">";
        throw Error("no light <" + path + "> in the scene (lights: " + (known.empty() ? "none" : known) + ")");
    }
    return it->second.desc;
}

void ViewerModel::setLight(const hd::SdfPath& path, const hd::LightDesc& desc) {
    light(path);  // throws for an unknown light before anything is recorded
    recordUndo();
    edited_->setLight(path, storable(desc));
}

hd::SdfPath ViewerModel::addLight(NewLightKind kind, const std::optional<hd::SdfPath>& path) {
    std::string name = newLightKindName(kind);
    name[0] = char(name[0] - 'a' + 'A');
    return addSceneLight(name, newLight(kind, bounds_), path);
}

hd::SdfPath ViewerModel::addShadowFieldLight(const std::filesystem::path& lightLayer, const std::optional<hd::SdfPath>& path) {
    if (path) requireNewPrimPath(scene(), *path);  // before the layer is read
    return addSceneLight("ShadowField", newShadowFieldLight(readLightLayer(lightLayer), bounds_), path);
}

// At `path`, or under </_OpalView/Lights> as NAME1, NAME2, ...
hd::SdfPath ViewerModel::addSceneLight(std::string name, scene::SceneLight light, const std::optional<hd::SdfPath>& path) {
    hd::SdfPath where;
    if (path) {
        requireNewPrimPath(scene(), *path);
        where = *path;
    } else {
        for (int n = 1; where.empty() || scene().lights.count(where); ++n)
            where = ViewerRoot + "/Lights/" + name + std::to_string(n);
    }
    recordUndo();
    edited_->addLight(where, std::move(light));
    selectedLight = where;
    return where;
}

void ViewerModel::removeLight(const hd::SdfPath& path) {
    light(path);
    recordUndo();
    edited_->removeLight(path);
    if (selectedLight == path) selectedLight.reset();
}

hd::SdfPath ViewerModel::renameLight(const hd::SdfPath& path, std::string_view name) {
    light(path);
    if (!isIdentifier(name))
        throw Error("'" + std::string(name) + "' is not a prim name (a letter or _ followed by letters, digits or _)");
    const hd::SdfPath to = siblingPath(path, name);
    if (to == path) return path;
    requireNewPrimPath(scene(), to);
    recordUndo();
    edited_->renameLight(path, to);
    if (selectedLight == path) selectedLight = to;
    return to;
}

void ViewerModel::setLightEnabled(const hd::SdfPath& path, bool enabled) {
    if (lightEnabled(path) == enabled) return;
    recordUndo();
    edited_->setLightEnabled(path, enabled);
}

bool ViewerModel::lightEnabled(const hd::SdfPath& path) const {
    light(path);
    return !edited_->disabledLights().count(path);
}

void ViewerModel::recordUndo() {
    if (gestureOpen_) return;
    undo_.push(edited_->state());
    gestureOpen_ = merging_;
}

void ViewerModel::setMergingEdits(bool merging) {
    merging_ = merging;
    if (!merging) gestureOpen_ = false;
}

void ViewerModel::restore(const EditState& state) {
    edited_->restore(state);
    if (selectedLight && !scene().lights.count(*selectedLight)) selectedLight.reset();
    gestureOpen_ = false;
}

bool ViewerModel::undo() {
    if (!edited_) return false;
    std::optional<EditState> state = undo_.undo(edited_->state());
    if (state) restore(*state);
    return state.has_value();
}

bool ViewerModel::redo() {
    if (!edited_) return false;
    std::optional<EditState> state = undo_.redo(edited_->state());
    if (state) restore(*state);
    return state.has_value();
}

bool ViewerModel::unsaved() const { return edited_ && edited_->revision() != savedRevision_; }

std::string ViewerModel::title() const {
    if (!isOpen()) return "opal-view";
    return "opal-view - " + file_.filename().string() + (unsaved() ? " *" : "") + " (" +
           std::filesystem::absolute(file_).parent_path().lexically_normal().string() + ")";
}

void ViewerModel::saveScene(const std::filesystem::path& file) {
    if (!isOpen()) throw Error("no scene is open");
    SceneExport out{scene(), edited_->disabledLights(), {}, viewport_.camera, viewport_.width, viewport_.height,
                    changedSettings()};
    out.scene.cameras.at(ViewCameraPath).desc = cameraDesc(camera, bounds_);
    if (!document_->assetOnly) {
        // A material as the file authored it, when the artist left it so (exact for presets
        // and artist parameters, which floats would round).
        for (auto& [path, prim] : authoredMaterialPrims(document_->scene.file)) {
            const auto original = document_->scene.materials.find(path);
            const auto now = scene().materials.find(path);
            if (original != document_->scene.materials.end() && now != scene().materials.end() &&
                sameMaterial(original->second.desc, now->second.desc))
                out.authoredMaterials.emplace(path, std::move(prim));
        }
    }
    saveSceneLayer(out, file);
    file_ = file;
    savedRevision_ = edited_->revision();
}

void ViewerModel::moveLight(const hd::SdfPath& path, const Imath::V3d& position) {
    setLight(path, movedLight(light(path), position));
}

std::vector<hd::SdfPath> ViewerModel::sceneCameras() const {
    std::vector<hd::SdfPath> cameras;
    for (const auto& entry : scene().cameras)
        if (entry.first != ViewCameraPath) cameras.push_back(entry.first);
    return cameras;
}

void ViewerModel::useCamera(const hd::SdfPath& path) {
    const std::vector<hd::SdfPath> cameras = sceneCameras();
    if (std::find(cameras.begin(), cameras.end(), path) == cameras.end()) {
        std::string known;
        for (const hd::SdfPath& camera : cameras) known += (known.empty() ? "<" : ", <") + camera + ">";
        throw Error("no camera <" + path + "> in the scene (cameras: " + (known.empty() ? "none" : known) + ")");
    }
    usedCamera_ = path;
    viewport_.camera = path;
}

OrbitCamera& ViewerModel::useFreeCamera() {
    camera = viewedCamera();
    usedCamera_.reset();
    viewport_.camera = ViewCameraPath;
    return camera;
}

OrbitCamera ViewerModel::viewedCamera() const {
    if (!usedCamera_) return camera;
    OrbitCamera viewed = orbitFromCamera(scene().cameras.at(*usedCamera_).desc, bounds_);
    viewed.nearClip = camera.nearClip;
    viewed.farClip = camera.farClip;
    return viewed;
}

void ViewerModel::frameAll() { frame(useFreeCamera(), bounds_, aspect()); }

void ViewerModel::frameSelection() { frame(useFreeCamera(), meshBounds(scene(), selectedMesh_), aspect()); }

void ViewerModel::resetCamera() {
    useFreeCamera();
    camera = home_;
}

void ViewerModel::setViewport(int width, int height) {
    viewport_.width = std::max(width, 1);
    viewport_.height = std::max(height, 1);
}

void ViewerModel::setRenderSetting(std::string_view key, const hd::Value& value) {
    const std::vector<hd::RenderSettingDescriptor> settings = delegate_->renderSettingDescriptors();
    const hd::RenderSettingDescriptor& setting = findSetting(settings, key);
    checkSettingValue(setting, value);
    pendingSettings_.emplace_back(setting.key, value);
}

void ViewerModel::setRenderSettingText(std::string_view key, std::string_view value) {
    const std::vector<hd::RenderSettingDescriptor> settings = delegate_->renderSettingDescriptors();
    setRenderSetting(key, parseSettingValue(findSetting(settings, key), value));
}

hd::Value ViewerModel::renderSetting(const hd::Token& key) const {
    for (auto it = pendingSettings_.rbegin(); it != pendingSettings_.rend(); ++it)
        if (it->first == key) return it->second;
    return delegate_->renderSetting(key);
}

int ViewerModel::update() {
    if (!session_) return 0;
    const hd::CameraDesc desc = cameraDesc(camera, bounds_);
    if (!sameCamera(desc, scene().cameras.at(ViewCameraPath).desc)) edited_->setCamera(ViewCameraPath, desc);
    if (!edited_->changed() && viewport_ == submitted_ && pendingSettings_.empty()) return 0;
    if (!session_->firstPassDone()) return 0;  // the edits wait, merged, for the next frame
    submitted_ = viewport_;
    const scene::Scene scene = edited_->renderedScene();
    const DirtyPrims changes = edited_->takeChanges();
    const RenderSettingChanges settings = std::exchange(pendingSettings_, {});
    if (referenceSession_) referenceSession_->submit(scene, changes, viewport_, asReference(settings));
    return session_->submit(scene, changes, viewport_, settings);
}

// A camera moved since the last update() is not in the picture yet, however converged the
// picture is.
bool ViewerModel::settled() const {
    if (!session_ || !sameCamera(cameraDesc(camera, bounds_), scene().cameras.at(ViewCameraPath).desc)) return false;
    return !edited_->changed() && viewport_ == submitted_ && pendingSettings_.empty() && session_->settled() &&
           (!referenceSession_ || referenceSession_->settled());
}

}  // namespace opal::view
