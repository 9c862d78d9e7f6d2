// Dirty bits per prim, as Hydra's HdChangeTracker: the scene source marks what changed,
// Sync pulls only that, and clears the bits.
#pragma once

#include "delegate/hd/types.h"

#include <map>

namespace opal::hd {

using DirtyBits = std::uint32_t;

namespace Dirty {
inline constexpr DirtyBits Clean = 0;
inline constexpr DirtyBits Transform = 1u << 0;  // the prim's xform
inline constexpr DirtyBits Params = 1u << 1;     // light/camera parameters, render settings
inline constexpr DirtyBits Visibility = 1u << 2;
inline constexpr DirtyBits Topology = 1u << 3;   // a mesh's asset (points, samples, transfer)
inline constexpr DirtyBits Material = 1u << 4;   // a mesh's material binding or a material's values
inline constexpr DirtyBits AllDirty = ~0u;
}  // namespace Dirty

class ChangeTracker {
public:
    void markDirty(const SdfPath& id, DirtyBits bits) { bits_[id] |= bits; }
    DirtyBits dirtyBits(const SdfPath& id) const {
        auto it = bits_.find(id);
        return it == bits_.end() ? Dirty::Clean : it->second;
    }
    void markClean(const SdfPath& id) { bits_.erase(id); }
    void remove(const SdfPath& id) { bits_.erase(id); }
    bool anyDirty() const { return !bits_.empty(); }
private:
    std::map<SdfPath, DirtyBits> bits_;
};

}  // namespace opal::hd
