#include "delegate/hd/render_index.h"

#include "schema/error.h"

namespace opal::hd {

RenderIndex::~RenderIndex() {
    // Rprims refer to Sprims (materials) and Sprims to nothing: destroy in reverse order.
    for (int order = 2; order >= 0; --order)
        for (auto& [id, entry] : prims_)
            if (entry.order == order) delegate_.destroyPrim(std::move(entry.prim));
    delegate_.finalizeRenderIndex(*this);
}

void RenderIndex::insert(const Token& type, const SceneDelegate& scene, const SdfPath& id,
                         std::unique_ptr<Prim> prim, int order) {
    if (!prim) throw Error("render index: the render delegate does not support prim type '" + type + "' (" + id + ")");
    if (prims_.count(id)) throw Error("render index: a prim '" + id + "' exists already");
    const DirtyBits initial = prim->initialDirtyBits();
    prims_.emplace(id, Entry{type, &scene, std::move(prim), order});
    if (initial != Dirty::Clean) tracker_.markDirty(id, initial);
}

void RenderIndex::insertRprim(const Token& type, const SceneDelegate& scene, const SdfPath& id) {
    insert(type, scene, id, delegate_.createRprim(type, id), 2);
}

void RenderIndex::insertSprim(const Token& type, const SceneDelegate& scene, const SdfPath& id) {
    insert(type, scene, id, delegate_.createSprim(type, id), 1);
}

void RenderIndex::insertBprim(const Token& type, const SceneDelegate& scene, const SdfPath& id) {
    insert(type, scene, id, delegate_.createBprim(type, id), 0);
}

void RenderIndex::removePrim(const SdfPath& id) {
    const auto it = prims_.find(id);
    if (it == prims_.end()) return;
    std::unique_ptr<Prim> prim = std::move(it->second.prim);
    prims_.erase(it);
    tracker_.remove(id);
    delegate_.destroyPrim(std::move(prim));
}

void RenderIndex::sync() {
    for (int order = 0; order <= 2; ++order)
        for (auto& [id, entry] : prims_) {
            if (entry.order != order) continue;
            DirtyBits bits = tracker_.dirtyBits(id);
            if (bits == Dirty::Clean) continue;
            entry.prim->sync(*entry.scene, &bits);
            tracker_.markClean(id);
        }
    delegate_.commitResources(*this);
}

const RenderIndex::Entry* RenderIndex::find(const SdfPath& id) const {
    auto it = prims_.find(id);
    return it == prims_.end() ? nullptr : &it->second;
}

Rprim* RenderIndex::rprim(const SdfPath& id) const {
    const Entry* e = find(id);
    return e && e->order == 2 ? static_cast<Rprim*>(e->prim.get()) : nullptr;
}

Sprim* RenderIndex::sprim(const SdfPath& id) const {
    const Entry* e = find(id);
    return e && e->order == 1 ? static_cast<Sprim*>(e->prim.get()) : nullptr;
}

Bprim* RenderIndex::bprim(const SdfPath& id) const {
    const Entry* e = find(id);
    return e && e->order == 0 ? static_cast<Bprim*>(e->prim.get()) : nullptr;
}

const Token& RenderIndex::typeOf(const SdfPath& id) const {
    const Entry* e = find(id);
    if (!e) throw Error("render index: no prim '" + id + "'");
    return e->type;
}

void RenderIndex::forEachSprim(const Token& type, const std::function<void(Sprim&)>& visit) const {
    for (const auto& [id, entry] : prims_)
        if (entry.order == 1 && entry.type == type) visit(static_cast<Sprim&>(*entry.prim));
}

void RenderIndex::forEachRprim(const std::function<void(Rprim&)>& visit) const {
    for (const auto& [id, entry] : prims_)
        if (entry.order == 2) visit(static_cast<Rprim&>(*entry.prim));
}

}  // namespace opal::hd
