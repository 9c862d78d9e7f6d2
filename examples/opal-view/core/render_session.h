// One open scene on a render delegate, driven as DELEGATE.md says a host that must never
// wait does it: a worker thread owns the render index and runs sync, commit and execute;
// the delegate's render thread draws passes into the AOV buffers; the interface thread
// only submits edits (returning at once), maps buffers and reads stats. Edits submitted
// while a sync runs are merged: the next sync takes the latest scene and every prim dirtied
// since.
#pragma once

#include "delegate/hd/render_delegate.h"
#include "delegate/hd/render_index.h"
#include "examples/opal-render/aov_buffers.h"
#include "examples/opal-view/core/edited_scene.h"
#include "examples/scene/usda_scene_source.h"

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace opal::view {

// What the render pass is asked for: the camera, the size, and the AOVs it renders (a
// pass writes only these, so the viewer binds what it shows; empty: every AOV).
struct Viewport {
    hd::SdfPath camera;
    int width = 640, height = 480;
    std::vector<std::string> aovs;
    friend bool operator==(const Viewport&, const Viewport&) = default;
};

// Render settings for the delegate, set on the worker (the thread that syncs and executes,
// so a setting never changes under a sync) before the next sync.
using RenderSettingChanges = std::vector<std::pair<hd::Token, hd::Value>>;

struct SessionStatus {
    double lastSyncMs = 0.0;  // the last sync (relighting included), wall clock
    int syncs = 0;            // syncs done, the first (every prim) included
    int applied = 0;          // the newest submission (submit's number) the last sync took in
    bool busy = false;        // a sync is pending or running
};

class RenderSession {
public:
    // Populates a render index on `delegate` with `scene` (throws opal::Error naming the
    // prim it refuses) and starts the first sync on the worker. `delegate` must outlive it.
    RenderSession(hd::RenderDelegate& delegate, scene::Scene scene, Viewport viewport);
    ~RenderSession();  // waits for the running sync, then stops rendering
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    // The interface's scene after its edits, the prims they dirtied, and the viewport.
    // Lights may come and go (the index follows); other prims keep their paths.
    // Returns the submission's number (1, 2, ...; the first sync's is 0): once
    // status().applied reaches it, the delegate's frame shows it.
    int submit(const scene::Scene& scene, const DirtyPrims& changes, const Viewport& viewport,
               const RenderSettingChanges& settings = {});
    // Nothing pending or running on the worker, and every bound buffer holds its final values.
    bool settled() const;
    // The newest submission is synced and its frame has finished a pass. A host that submits
    // only then never restarts a frame before its first pass, so a dragged control keeps
    // producing pictures (every submission would otherwise restart the frame before any
    // pass of it is done).
    bool firstPassDone() const;
    SessionStatus status() const;
    // Errors of syncs and of the render thread, and the delegate's warnings, since the last
    // call, each prefixed "error: " or "warning: ".
    std::vector<std::string> takeMessages();

    // The delegate's AOVs (those of hd/aov.h it has a descriptor for): the session binds
    // only these, so a pass never gets an AOV its delegate does not render.
    const render::AovBuffers& buffers() const { return buffers_; }
    // Throws opal::Error naming the AOVs there are for one the delegate does not render.
    const hd::RenderBuffer& buffer(const std::string& aov) const;
    std::vector<std::string> aovs() const;  // the bound ones, in binding order
    bool renders(const std::string& aov) const;
    // "color, normal, ..." for messages.
    std::string aovList() const;
    hd::RenderDelegate& delegate() const { return delegate_; }

private:
    struct Update {
        scene::Scene scene;
        DirtyPrims dirty;
        Viewport viewport;
        int number = 0;
        RenderSettingChanges settings;
    };
    void work();
    void syncAndExecute(Update update);
    // Inserts the scene's lights the index lacks and removes those the scene lost.
    void syncLightSet(const scene::Scene& scene);
    std::vector<hd::AovBinding> bindings(const std::vector<std::string>& aovs) const;

    hd::RenderDelegate& delegate_;
    scene::UsdaSceneSource source_;
    render::AovBuffers buffers_;
    hd::RenderIndex index_;
    std::unique_ptr<hd::RenderPass> pass_;
    std::set<hd::SdfPath> lights_;  // the lights in the index (the worker's)

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Update> pending_;
    bool running_ = false, quit_ = false;
    int submissions_ = 0;
    SessionStatus status_;
    std::vector<std::string> messages_;
    std::thread worker_;  // last: starts once everything it uses exists
};

}  // namespace opal::view
