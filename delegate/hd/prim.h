// Prims as Hydra has them: Rprims are renderable (translucent meshes), Sprims are state
// (camera, lights, materials), Bprims are buffers. A prim pulls its data from the scene
// delegate in sync() for the dirty bits it is given, and clears them.
#pragma once

#include "delegate/hd/change_tracker.h"
#include "delegate/hd/scene_delegate.h"

namespace opal::hd {

class Prim {
public:
    explicit Prim(SdfPath id) : id_(std::move(id)) {}
    virtual ~Prim() = default;
    Prim(const Prim&) = delete;
    Prim& operator=(const Prim&) = delete;

    const SdfPath& id() const { return id_; }
    // Pull what `*dirtyBits` says changed; leave *dirtyBits == Dirty::Clean.
    virtual void sync(const SceneDelegate& scene, DirtyBits* dirtyBits) = 0;
    // What the first sync pulls (Hydra's GetInitialDirtyBitsMask): the render index marks a
    // new prim with these.
    virtual DirtyBits initialDirtyBits() const = 0;

private:
    SdfPath id_;
};

class Rprim : public Prim {
    using Prim::Prim;
};
class Sprim : public Prim {
    using Prim::Prim;
};
class Bprim : public Prim {
    using Prim::Prim;
};

}  // namespace opal::hd
