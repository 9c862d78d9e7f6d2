// Versions of synced prim state: every sync that changes a light or a material takes a new
// number from the delegate's counter, and each mesh remembers the numbers it last used, so
// commitResources redoes exactly what changed (a light's E, a material's s_k) for exactly
// the meshes that depend on it, even when a prim is removed and another one added at the
// same path. Numbers are never reused within one delegate; 0 means "nothing".
#pragma once

#include <cstdint>

namespace opal {

class PrimVersions {
public:
    std::uint64_t next() { return ++last_; }

private:
    std::uint64_t last_ = 0;
};

}  // namespace opal
