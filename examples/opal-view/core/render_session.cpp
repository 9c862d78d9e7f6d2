#include "examples/opal-view/core/render_session.h"

#include "delegate/hd/aov.h"
#include "schema/error.h"

#include <algorithm>
#include <chrono>
#include <variant>

namespace opal::view {
namespace {

void markAll(const scene::Scene& scene, DirtyPrims& dirty) {
    const auto mark = [&](const auto& prims) {
        for (const auto& entry : prims) dirty[entry.first] |= hd::Dirty::AllDirty;
    };
    mark(scene.materials);
    mark(scene.cameras);
    mark(scene.lights);
    mark(scene.meshes);
}

// A prim the session's index holds (a light removed since its edit is not).
bool inScene(const scene::Scene& scene, const hd::SdfPath& path) {
    return scene.lights.count(path) || scene.materials.count(path) || scene.meshes.count(path) || scene.cameras.count(path);
}

// The AOVs of Opal's table the delegate renders, in the table's order (Hydra hosts bind
// only those a delegate has a default descriptor for).
std::vector<std::string> renderedAovs(const hd::RenderDelegate& delegate) {
    std::vector<std::string> names;
    for (const hd::AovDescriptor& aov : hd::aovTable())
        if (delegate.defaultAovDescriptor(aov.name)) names.push_back(aov.name);
    return names;
}

}  // namespace

RenderSession::RenderSession(hd::RenderDelegate& delegate, scene::Scene scene, Viewport viewport)
    : delegate_(delegate), source_(scene), buffers_(renderedAovs(delegate), true), index_(delegate) {
    source_.populate(index_);
    for (const auto& entry : scene.lights) lights_.insert(entry.first);
    pass_ = delegate_.createRenderPass(index_);
    Update first{std::move(scene), {}, std::move(viewport), 0, {}};
    markAll(first.scene, first.dirty);
    pending_ = std::move(first);
    worker_ = std::thread([this] { work(); });
}

RenderSession::~RenderSession() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

int RenderSession::submit(const scene::Scene& scene, const DirtyPrims& changes, const Viewport& viewport,
                          const RenderSettingChanges& settings) {
    int number = 0;
    {
        std::lock_guard lock(mutex_);
        if (!pending_) pending_ = Update{};
        pending_->scene = scene;
        pending_->viewport = viewport;
        pending_->number = number = ++submissions_;
        for (const auto& [path, bits] : changes) pending_->dirty[path] |= bits;
        pending_->settings.insert(pending_->settings.end(), settings.begin(), settings.end());
    }
    wake_.notify_all();
    return number;
}

bool RenderSession::settled() const {
    {
        std::lock_guard lock(mutex_);
        if (pending_ || running_) return false;
    }
    return pass_->isConverged();
}

bool RenderSession::firstPassDone() const {
    {
        std::lock_guard lock(mutex_);
        if (pending_ || running_ || status_.applied != submissions_) return false;
    }
    // A frame that failed on the render thread counts converged; a delegate that does not
    // count passes cannot be waited for.
    if (pass_->isConverged()) return true;
    const auto stats = delegate_.renderStats();
    const auto passes = stats.find("passes");
    const int* done = passes == stats.end() ? nullptr : std::get_if<int>(&passes->second);
    return !done || *done >= 1;
}

SessionStatus RenderSession::status() const {
    std::lock_guard lock(mutex_);
    SessionStatus status = status_;
    status.busy = pending_.has_value() || running_;
    return status;
}

std::vector<std::string> RenderSession::takeMessages() {
    std::vector<std::string> messages;
    {
        std::lock_guard lock(mutex_);
        messages.swap(messages_);
    }
    for (const std::string& error : delegate_.takeErrors()) messages.push_back("error: " + error);
    return messages;
}

const hd::RenderBuffer& RenderSession::buffer(const std::string& aov) const {
    for (const hd::AovBinding& binding : buffers_.bindings())
        if (binding.aov == aov) return *binding.buffer;
    throw Error("the renderer renders no AOV '" + aov + "' (it renders " + aovList() + ")");
}

std::vector<std::string> RenderSession::aovs() const {
    std::vector<std::string> names;
    for (const hd::AovBinding& binding : buffers_.bindings()) names.push_back(binding.aov);
    return names;
}

bool RenderSession::renders(const std::string& aov) const {
    const std::vector<std::string> names = aovs();
    return std::find(names.begin(), names.end(), aov) != names.end();
}

std::string RenderSession::aovList() const {
    std::string list;
    for (const std::string& name : aovs()) list += (list.empty() ? "" : ", ") + name;
    return list;
}

std::vector<hd::AovBinding> RenderSession::bindings(const std::vector<std::string>& aovs) const {
    std::vector<hd::AovBinding> bound;
    for (const hd::AovBinding& binding : buffers_.bindings())
        if (aovs.empty() || std::find(aovs.begin(), aovs.end(), binding.aov) != aovs.end()) bound.push_back(binding);
    return bound;
}

void RenderSession::work() {
    for (;;) {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return quit_ || pending_; });
        if (quit_) return;
        Update update = std::move(*pending_);
        pending_.reset();
        running_ = true;
        lock.unlock();
        syncAndExecute(std::move(update));
        lock.lock();
        running_ = false;
    }
}

void RenderSession::syncLightSet(const scene::Scene& scene) {
    for (auto it = lights_.begin(); it != lights_.end();) {
        if (scene.lights.count(*it)) {
            ++it;
            continue;
        }
        index_.removePrim(*it);
        it = lights_.erase(it);
    }
    for (const auto& [path, light] : scene.lights) {
        if (lights_.count(path)) continue;
        index_.insertSprim(light.primType, source_, path);
        lights_.insert(path);
    }
}

void RenderSession::syncAndExecute(Update update) {
    const int number = update.number;
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::string> messages;
    try {
        for (const auto& [key, value] : update.settings) delegate_.setRenderSetting(key, value);
        syncLightSet(update.scene);
        source_.setScene(std::move(update.scene));
        const scene::Scene& scene = source_.scene();
        for (const auto& [path, bits] : update.dirty)
            if (inScene(scene, path)) index_.changeTracker().markDirty(path, bits);
        index_.sync();
        hd::RenderPassState state{update.viewport.camera, update.viewport.width, update.viewport.height};
        pass_->execute(state, bindings(update.viewport.aovs));
    } catch (const std::exception& e) {
        messages.push_back("error: " + std::string(e.what()));
    }
    for (const std::string& warning : delegate_.takeWarnings()) messages.push_back("warning: " + warning);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::lock_guard lock(mutex_);
    status_.lastSyncMs = ms;
    status_.applied = number;
    ++status_.syncs;
    messages_.insert(messages_.end(), messages.begin(), messages.end());
}

}  // namespace opal::view
