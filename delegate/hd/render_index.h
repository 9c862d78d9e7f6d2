// The host-side registry of prims (Hydra's HdRenderIndex): a scene source inserts prims by
// type and id, marks them dirty through the change tracker, and sync() brings the
// delegate's prims up to date (pull, only what is dirty), then commits resources.
#pragma once

#include "delegate/hd/render_delegate.h"

#include <functional>
#include <map>
#include <memory>

namespace opal::hd {

class RenderIndex {
public:
    explicit RenderIndex(RenderDelegate& delegate) : delegate_(delegate) {}
    ~RenderIndex();
    RenderIndex(const RenderIndex&) = delete;
    RenderIndex& operator=(const RenderIndex&) = delete;

    RenderDelegate& renderDelegate() { return delegate_; }
    ChangeTracker& changeTracker() { return tracker_; }

    // Each throws opal::Error for a type the delegate does not support or a duplicate id.
    void insertRprim(const Token& type, const SceneDelegate& scene, const SdfPath& id);
    void insertSprim(const Token& type, const SceneDelegate& scene, const SdfPath& id);
    void insertBprim(const Token& type, const SceneDelegate& scene, const SdfPath& id);
    void removePrim(const SdfPath& id);

    // Syncs every dirty prim (Bprims, then Sprims, then Rprims, as Hydra), then calls
    // the delegate's commitResources.
    void sync();

    Rprim* rprim(const SdfPath& id) const;
    Sprim* sprim(const SdfPath& id) const;
    Bprim* bprim(const SdfPath& id) const;
    const Token& typeOf(const SdfPath& id) const;
    // Every prim of one type, in path order.
    void forEachSprim(const Token& type, const std::function<void(Sprim&)>& visit) const;
    void forEachRprim(const std::function<void(Rprim&)>& visit) const;

private:
    struct Entry {
        Token type;
        const SceneDelegate* scene = nullptr;
        std::unique_ptr<Prim> prim;
        int order = 0;  // 0 Bprim, 1 Sprim, 2 Rprim
    };
    void insert(const Token& type, const SceneDelegate& scene, const SdfPath& id, std::unique_ptr<Prim> prim, int order);
    const Entry* find(const SdfPath& id) const;

    RenderDelegate& delegate_;
    ChangeTracker tracker_;
    std::map<SdfPath, Entry> prims_;
};

}  // namespace opal::hd
