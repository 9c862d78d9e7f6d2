#include "delegate/render_delegate.h"

#include "delegate/camera.h"
#include "delegate/commit_steps.h"
#include "delegate/image/camera_view.h"
#include "delegate/hd/light_types.h"
#include "delegate/hd/render_index.h"
#include "delegate/light.h"
#include "delegate/material_prim.h"
#include "delegate/render_pass.h"
#include "delegate/translucent_mesh.h"
#include "schema/error.h"

#include <algorithm>
#include <chrono>
#include <climits>

namespace opal {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int saturated(std::uint64_t n) { return n > std::uint64_t(INT_MAX) ? INT_MAX : int(n); }

}  // namespace

OpalRenderDelegate::OpalRenderDelegate(const std::map<hd::Token, hd::Value>& settings) {
    for (const auto& [key, value] : settings) setRenderSetting(key, value);
    textures_.reset(settings_.ocioConfig);
    texturesConfig_ = settings_.ocioConfig;
}

OpalRenderDelegate::~OpalRenderDelegate() = default;

std::vector<hd::Token> OpalRenderDelegate::supportedRprimTypes() const { return {hd::PrimType::TranslucentMesh}; }

std::vector<hd::Token> OpalRenderDelegate::supportedSprimTypes() const {
    std::vector<hd::Token> types = {hd::PrimType::Camera, hd::PrimType::Material};
    types.insert(types.end(), hd::lightPrimTypes().begin(), hd::lightPrimTypes().end());
    return types;
}

std::vector<hd::Token> OpalRenderDelegate::supportedBprimTypes() const { return {hd::PrimType::RenderBuffer}; }

std::unique_ptr<hd::Rprim> OpalRenderDelegate::createRprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::TranslucentMesh) return std::make_unique<TranslucentMesh>(id);
    return nullptr;
}

std::unique_ptr<hd::Sprim> OpalRenderDelegate::createSprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::Camera) return std::make_unique<OpalCamera>(id);
    if (type == hd::PrimType::Material) return std::make_unique<OpalMaterial>(id, versions_);
    if (hd::isLightPrimType(type)) return std::make_unique<OpalLight>(id, type, textures_, fields_, versions_);
    return nullptr;
}

std::unique_ptr<hd::Bprim> OpalRenderDelegate::createBprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::RenderBuffer) return std::make_unique<hd::RenderBuffer>(id);
    return nullptr;
}

void OpalRenderDelegate::setRenderSetting(const hd::Token& key, const hd::Value& value) {
    const bool commitAffecting = key == "opal:reference" || key == "opal:ocioConfig";
    if (settings_.set(key, value) && commitAffecting) ++settingsVersion_;
}

hd::Value OpalRenderDelegate::renderSetting(const hd::Token& key) const { return settings_.get(key); }

std::map<hd::Token, hd::Value> OpalRenderDelegate::renderSettings() const { return settings_.all(); }

std::vector<hd::RenderSettingDescriptor> OpalRenderDelegate::renderSettingDescriptors() const {
    const auto rows = RenderSettings::descriptors();
    return {rows.begin(), rows.end()};
}

std::vector<hd::AovDescriptor> OpalRenderDelegate::aovDescriptors() const {
    const auto rows = hd::aovTable();
    return {rows.begin(), rows.end()};
}

std::map<hd::Token, hd::Value> OpalRenderDelegate::renderStats() const {
    std::map<hd::Token, hd::Value> stats;
    const int done = passesDone_.load(), passes = passCount_.load();
    stats["percentDone"] = passes == 0 ? 0.0 : 100.0 * done / passes;
    // Pass 0 is the centre sample; pass p >= 1 brings the estimate to p pattern samples. A
    // draft holds no pixel's own sample.
    const int sampled = std::max(0, done - draftPasses_.load());
    stats["samplesPerPixel"] = sampled <= 1 ? sampled : sampled - 1;
    stats["passes"] = done;
    stats["passMs"] = lastPassMs_.load();
    stats["convergedMs"] = convergedMs_.load();
    std::lock_guard lock(statsMutex_);
    stats["converged"] = converged_.load();
    stats["commits"] = saturated(commits_);
    stats["commitMs"] = lastCommit_.totalMs;
    stats["rayScenesMs"] = lastCommit_.rayScenesMs;
    stats["irradianceMs"] = lastCommit_.irradianceMs;
    stats["lightMomentsMs"] = lastCommit_.lightMomentsMs;
    stats["productsMs"] = lastCommit_.productsMs;
    stats["materialMs"] = lastCommit_.materialMs;
    stats["referenceMs"] = lastCommit_.referenceMs;
    stats["projectedValues"] = saturated(lastCommit_.projectedValues);
    stats["deepestProjected"] = lastCommit_.deepestProjected;
    stats["projectedIrradiance"] = saturated(lastCommit_.projectedIrradiance);
    stats["deepestIrradiance"] = lastCommit_.deepestIrradiance;
    stats["rayScenes"] = saturated(totals_.rayScenes);
    stats["lightEvaluations"] = saturated(totals_.lightEvaluations);
    stats["irradianceProducts"] = saturated(totals_.irradianceProducts);
    stats["materialUpdates"] = saturated(totals_.materialUpdates);
    stats["referenceGathers"] = saturated(totals_.referenceGathers);
    double total = 0.0;
    for (const auto& [path, bytes] : meshMemory_) {
        stats["memoryBytes:" + path] = double(bytes);
        total += double(bytes);
    }
    stats["memoryBytes"] = total;
    return stats;
}

std::unique_ptr<hd::RenderPass> OpalRenderDelegate::createRenderPass(hd::RenderIndex& index) {
    return std::make_unique<OpalRenderPass>(*this, index);
}

std::vector<std::string> OpalRenderDelegate::takeWarnings() {
    std::vector<std::string> warnings;
    warnings.swap(warnings_);
    return warnings;
}

std::vector<std::string> OpalRenderDelegate::takeErrors() {
    std::lock_guard lock(jobMutex_);
    std::vector<std::string> errors;
    errors.swap(renderErrors_);
    return errors;
}

std::shared_ptr<const Frame> OpalRenderDelegate::frame(hd::RenderIndex& index) {
    if (!frame_ || &index != index_ || settingsVersion_ != committedSettingsVersion_) commitResources(index);
    return frame_;
}

void OpalRenderDelegate::destroyPrim(std::unique_ptr<hd::Prim> prim) {
    if (const auto* buffer = dynamic_cast<const hd::RenderBuffer*>(prim.get())) {
        std::unique_lock lock(jobMutex_);
        if (job_ && std::find(job_->targets.begin(), job_->targets.end(), buffer) != job_->targets.end()) {
            lock.unlock();
            thread_.stopRender();
            lock.lock();
            job_.reset();
        }
    }
    prim.reset();
}

void OpalRenderDelegate::finalizeRenderIndex(hd::RenderIndex& index) {
    if (&index != index_) return;
    thread_.stopRender();
    {
        std::lock_guard lock(jobMutex_);
        job_.reset();
    }
    frame_.reset();
    committedMeshes_.clear();
    meshPaths_.clear();
    {
        std::lock_guard lock(statsMutex_);
        meshMemory_.clear();
    }
    index_ = nullptr;
}

bool OpalRenderDelegate::pause() {
    thread_.pauseRender();
    return true;
}

bool OpalRenderDelegate::resume() {
    thread_.resumeRender();
    return true;
}

bool OpalRenderDelegate::stop() {
    thread_.stopRender();
    std::lock_guard lock(jobMutex_);
    job_.reset();  // the next execute starts the frame again
    return true;
}

void OpalRenderDelegate::render(hd::RenderIndex& index, RenderJob job) {
    CameraView(job.camera, job.width, job.height, job.cameraPath);  // throws for a bad camera or size
    job.frame = frame(index);
    job.options = RenderOptions{settings_.specular, settings_.transparentBackground, settings_.tileSize,
                                settings_.samplesPerPixel, settings_.pixelFilter, settings_.draftBlock};
    {
        std::lock_guard lock(jobMutex_);
        if (job_ && job_->sameAs(job)) return;
    }
    restart(std::move(job));
}

void OpalRenderDelegate::restart(RenderJob job) {
    thread_.stopRender();  // waits for the running tile at most
    for (std::size_t a = 0; a < hd::kAovCount; ++a) {
        hd::RenderBuffer* buffer = job.targets[a];
        if (!buffer) continue;
        const hd::AovDescriptor& aov = hd::aovDescriptor(hd::AovId(a));
        if (buffer->width() != job.width || buffer->height() != job.height || buffer->channels() != aov.channelCount())
            buffer->allocate(job.width, job.height, aov.channelCount(), aov.clearValue);
        buffer->setConverged(false);
    }
    {
        std::lock_guard lock(jobMutex_);
        job_ = std::move(job);
        newJob();
    }
    thread_.startRender();
}

void OpalRenderDelegate::newJob() {
    ++jobGeneration_;
    passesDone_ = 0;
    converged_ = false;
}

// A new commit while a job renders: it restarts with the new frame at its next tile.
void OpalRenderDelegate::publish(std::shared_ptr<const Frame> frame) {
    frame_ = std::move(frame);
    std::lock_guard lock(jobMutex_);
    if (!job_) return;
    job_->frame = frame_;
    newJob();
    for (hd::RenderBuffer* buffer : job_->targets)
        if (buffer) buffer->setConverged(false);
    thread_.startRender();
}

void OpalRenderDelegate::renderJob() {
    RenderJob job;
    std::uint64_t generation = 0;
    {
        std::lock_guard lock(jobMutex_);
        if (!job_ || !job_->frame) return;
        job = *job_;
        generation = jobGeneration_;
        jobStart_ = std::chrono::steady_clock::now();
    }
    // The draft is pass -1: before the centre pass, which overwrites it.
    const int first = job.options.draftBlock > 1 ? -1 : 0, passes = passCount(job.options);
    passCount_ = passes - first;
    draftPasses_ = -first;
    try {
        const CameraView camera(job.camera, job.width, job.height, job.cameraPath);
        const auto stop = [this] { return thread_.checkpoint(); };
        for (int pass = first; pass < passes; ++pass) {
            if (thread_.checkpoint()) return;
            const auto start = std::chrono::steady_clock::now();
            const bool done = pass < 0 ? renderDraft(*job.frame, camera, job.options, job.targets, job.options.draftBlock, stop)
                                       : renderPass(*job.frame, camera, job.options, job.targets, pass, stop);
            if (!done) return;
            std::lock_guard lock(jobMutex_);
            if (generation != jobGeneration_) return;  // a pass of a job already replaced
            lastPassMs_ = millisecondsSince(start);
            ++passesDone_;
        }
    } catch (const std::exception& e) {
        std::lock_guard lock(jobMutex_);
        renderErrors_.push_back(std::string("Opal render thread: ") + e.what());
    }
    std::lock_guard lock(jobMutex_);
    if (generation != jobGeneration_ || thread_.stopRequested()) return;  // replaced meanwhile
    for (hd::RenderBuffer* buffer : job.targets)
        if (buffer) buffer->setConverged(true);
    convergedMs_ = millisecondsSince(jobStart_);
    converged_ = true;
}

void OpalRenderDelegate::commitResources(hd::RenderIndex& index) {
    // The frame this commit replaces renders no more meanwhile, so that the relighting has
    // every core (the render thread's passes would be thrown away by the restart anyway). The
    // commit's publish starts the new frame; a failed commit lets the old one start again.
    const bool rendering = thread_.isRendering();
    thread_.stopRender();
    try {
        commit(index);
    } catch (...) {
        std::lock_guard lock(jobMutex_);
        if (rendering && job_) {
            newJob();
            thread_.startRender();
        }
        throw;
    }
}

void OpalRenderDelegate::commit(hd::RenderIndex& index) {
    const auto start = std::chrono::steady_clock::now();
    CommitStats stats;
    if (&index != index_) {  // another index: nothing committed before applies
        index_ = &index;
        frame_.reset();
        committedMeshes_.clear();
    }
    if (settings_.ocioConfig != texturesConfig_) reloadDomeTextures(index);

    auto frame = std::make_shared<Frame>();
    const LightSources lights = collectLights(index, *frame);
    const MaterialPrims materials = collectMaterials(index);
    const std::vector<TranslucentMesh*> meshes = collectMeshes(index);
    const bool rebuild = !frame_ || geometryChanged(meshes, committedMeshes_);
    frame->rays = rebuild ? buildRayScene(meshes, stats) : frame_->rays;
    relightMeshes(meshes, lights, materials, {settings_.reference, rebuild}, *frame, stats, warnings_);

    for (TranslucentMesh* mesh : meshes) mesh->markCommitted();
    committedMeshes_.assign(meshes.begin(), meshes.end());
    meshPaths_.clear();
    std::vector<std::pair<hd::SdfPath, std::size_t>> memory;
    for (const TranslucentMesh* mesh : meshes) {
        meshPaths_.push_back(mesh->id());
        memory.emplace_back(mesh->id(), mesh->memoryBytes());
    }
    committedSettingsVersion_ = settingsVersion_;
    publish(std::move(frame));
    stats.totalMs = millisecondsSince(start);
    std::lock_guard lock(statsMutex_);  // renderStats() may be read from another thread
    meshMemory_ = std::move(memory);
    lastCommit_ = stats;
    totals_ += stats;
    ++commits_;
}

void OpalRenderDelegate::reloadDomeTextures(hd::RenderIndex& index) {
    textures_.reset(settings_.ocioConfig);
    texturesConfig_ = settings_.ocioConfig;
    for (OpalLight* light : collectLightPrims(index)) light->reloadTexture();
}

}  // namespace opal
