// Every sample point's map of a shadow field, averaged to the decode face size and kept as
// its nonzero texels (before the clamp to 0). Interpolation is linear in the maps
// (shadow_field_lookup.h), so the field at a point is the stencil's weighted sum of these
// lists, then clamped: what ShadowFieldLookup::incidentRadiance gives, up to float
// rounding, without a Haar synthesis per query. A compact emitter lights a few dozen of a
// map's texels, so a query adds a few hundred terms instead of forming 6 faces.
#pragma once

#include "delegate/relight/float4.h"
#include "schema/asset/shadow_field_lookup.h"

#include <Imath/ImathVec.h>

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class SparseFieldMaps {
public:
    // Decodes every map of `lookup`'s field at `faceSize` (in parallel). Throws what
    // ShadowFieldLookup::mapTerms throws for a bad face size.
    SparseFieldMaps(const ShadowFieldLookup& lookup, std::uint32_t faceSize);

    // Map `index`'s nonzero texels (indices into a CubeMapLayout of faceSize) and their
    // radiance terms (RGB and a zero, one SSE register each: a sample adds about a
    // thousand), in increasing texel order.
    std::span<const std::uint32_t> texels(std::uint64_t index) const;
    std::span<const Float4> terms(std::uint64_t index) const;

    std::size_t entries() const { return texels_.size(); }

private:
    std::vector<std::uint64_t> offsets_;  // per map, into texels_ and terms_; one past the last
    std::vector<std::uint32_t> texels_;
    std::vector<Float4> terms_;
};

}  // namespace opal
