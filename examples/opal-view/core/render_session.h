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
#include <string>
#include <thread>
#include <vector>

namespace opal::view {

struct Viewport {
    hd::SdfPath camera;
    int width = 640, height = 480;
    friend bool operator==(const Viewport&, const Viewport&) = default;
};

struct SessionStatus {
    double lastSyncMs = 0.0;  // the last sync (relighting included), wall clock
    int syncs = 0;            // syncs done, the first (every prim) included
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
    void submit(const scene::Scene& scene, const DirtyPrims& changes, const Viewport& viewport);
    // Nothing pending or running on the worker, and every bound buffer holds its final values.
    bool settled() const;
    SessionStatus status() const;
    // Errors of syncs and of the render thread, and the delegate's warnings, since the last
    // call, each prefixed "error: " or "warning: ".
    std::vector<std::string> takeMessages();

    const render::AovBuffers& buffers() const { return buffers_; }
    const hd::RenderBuffer& buffer(const std::string& aov) const;
    hd::RenderDelegate& delegate() const { return delegate_; }

private:
    struct Update {
        scene::Scene scene;
        DirtyPrims dirty;
        Viewport viewport;
    };
    void work();
    void syncAndExecute(Update update);

    hd::RenderDelegate& delegate_;
    scene::UsdaSceneSource source_;
    render::AovBuffers buffers_;
    hd::RenderIndex index_;
    std::unique_ptr<hd::RenderPass> pass_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Update> pending_;
    bool running_ = false, quit_ = false;
    SessionStatus status_;
    std::vector<std::string> messages_;
    std::thread worker_;  // last: starts once everything it uses exists
};

}  // namespace opal::view
