#include "delegate/preview/preview_delegate.h"

#include "delegate/hd/light_types.h"
#include "delegate/preview/preview_aovs.h"
#include "delegate/preview/preview_pass.h"
#include "delegate/preview/preview_prims.h"

#include <utility>

namespace opal::preview {

PreviewRenderDelegate::PreviewRenderDelegate(const std::map<hd::Token, hd::Value>& settings) {
    for (const auto& [key, value] : settings) settings_.set(key, value);
}

std::vector<hd::Token> PreviewRenderDelegate::supportedRprimTypes() const { return {hd::PrimType::TranslucentMesh}; }

std::vector<hd::Token> PreviewRenderDelegate::supportedSprimTypes() const {
    std::vector<hd::Token> types = {hd::PrimType::Camera, hd::PrimType::Material};
    types.insert(types.end(), hd::lightPrimTypes().begin(), hd::lightPrimTypes().end());
    return types;
}

std::vector<hd::Token> PreviewRenderDelegate::supportedBprimTypes() const { return {hd::PrimType::RenderBuffer}; }

std::unique_ptr<hd::Rprim> PreviewRenderDelegate::createRprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type != hd::PrimType::TranslucentMesh) return nullptr;
    return std::make_unique<PreviewMesh>(id, &meshSyncs_);
}

std::unique_ptr<hd::Sprim> PreviewRenderDelegate::createSprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::Camera) return std::make_unique<PreviewCamera>(id);
    if (type == hd::PrimType::Material) return std::make_unique<PreviewMaterial>(id);
    if (!hd::isLightPrimType(type)) return nullptr;
    std::lock_guard lock(mutex_);
    ++lights_;
    return std::make_unique<PreviewLight>(id);
}

std::unique_ptr<hd::Bprim> PreviewRenderDelegate::createBprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type != hd::PrimType::RenderBuffer) return nullptr;
    return std::make_unique<hd::RenderBuffer>(id);
}

void PreviewRenderDelegate::destroyPrim(std::unique_ptr<hd::Prim> prim) {
    if (dynamic_cast<PreviewMesh*>(prim.get())) ++meshSyncs_;
    if (dynamic_cast<PreviewLight*>(prim.get())) {
        std::lock_guard lock(mutex_);
        --lights_;
    }
    prim.reset();
}

void PreviewRenderDelegate::finalizeRenderIndex(hd::RenderIndex&) {
    std::lock_guard lock(mutex_);
    scene_.reset();
    builtAt_ = -1;
}

std::vector<hd::AovDescriptor> PreviewRenderDelegate::aovDescriptors() const { return previewAovs(); }

void PreviewRenderDelegate::setRenderSetting(const hd::Token& key, const hd::Value& value) {
    std::lock_guard lock(mutex_);
    settings_.set(key, value);
}

hd::Value PreviewRenderDelegate::renderSetting(const hd::Token& key) const {
    std::lock_guard lock(mutex_);
    return settings_.value(key);
}

std::map<hd::Token, hd::Value> PreviewRenderDelegate::renderSettings() const {
    std::lock_guard lock(mutex_);
    return settings_.all();
}

std::vector<hd::RenderSettingDescriptor> PreviewRenderDelegate::renderSettingDescriptors() const {
    return PreviewSettings::descriptors();
}

std::map<hd::Token, hd::Value> PreviewRenderDelegate::renderStats() const {
    std::lock_guard lock(mutex_);
    return {{"passes", passes_},
            {"frameMs", frameMs_},
            {"meshes", scene_ ? int(scene_->rays().meshCount()) : 0},
            {"triangles", scene_ ? int(scene_->triangleCount()) : 0},
            {"lightsIgnored", lights_}};
}

std::unique_ptr<hd::RenderPass> PreviewRenderDelegate::createRenderPass(hd::RenderIndex& index) {
    return std::make_unique<PreviewRenderPass>(index, *this);
}

void PreviewRenderDelegate::commitResources(hd::RenderIndex& index) {
    try {
        if (!scene_ || builtAt_ != meshSyncs_) {
            auto built = std::make_unique<PreviewScene>(index);
            std::lock_guard lock(mutex_);  // renderStats reads the scene's counts
            scene_ = std::move(built);
            builtAt_ = meshSyncs_;
        }
        scene_->updateAlbedos(index);
    } catch (const std::exception& e) {
        reportError(e.what());
    }
}

void PreviewRenderDelegate::reportError(std::string message) {
    std::lock_guard lock(mutex_);
    errors_.push_back(std::move(message));
}

std::vector<std::string> PreviewRenderDelegate::takeErrors() {
    std::lock_guard lock(mutex_);
    return std::exchange(errors_, {});
}

std::vector<std::string> PreviewRenderDelegate::takeWarnings() {
    std::lock_guard lock(mutex_);
    return settings_.takeWarnings();
}

FrameLook PreviewRenderDelegate::look() const {
    std::lock_guard lock(mutex_);
    return {settings_.shading(), settings_.headlight()};
}

void PreviewRenderDelegate::framed(bool done, double milliseconds) {
    std::lock_guard lock(mutex_);
    passes_ = done ? 1 : 0;
    if (done) frameMs_ = milliseconds;
}

}  // namespace opal::preview
