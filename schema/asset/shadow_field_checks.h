// The consistency rules of a shadow field (LIGHTFIELD.md, "Validation"). The reader applies
// them to what it decoded, the writer to what it is asked to write, so a light sidecar Opal
// writes is always one it reads. `context` names the file and chunk ("a.field: chunk
// 'HEAD'"); each check throws opal::Error with it.
#pragma once

#include "schema/asset/shadow_field.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace opal::shadow_field {

inline constexpr std::uint32_t kMinShells = 2;  // radial interpolation needs two
inline constexpr std::uint32_t kMaxShells = 256;
inline constexpr std::uint32_t kMaxDirectionFaceSize = 64;
inline constexpr std::uint32_t kMaxMapFaceSize = 256;
// Positions and radii within 1e9 mm of the origin, as every other point Opal reads.
inline constexpr double kMaxLength = 1e9;
// Emitted radiance at most 1e20 (docs/ARCHITECTURE.md#units); an orthonormal Haar
// coefficient of a map is at most sqrt(texels) times the map's largest value.
inline constexpr double kMaxRadiance = 1e20;
inline constexpr std::uint32_t kMaxViewFaceSize = 16;   // 1,536 views
inline constexpr std::uint32_t kMaxViewImageSize = 256;

// HEAD: name, centre, emitter radius, face sizes, kept energy, shell count.
void checkHeader(const ShadowField& field, std::string_view context);
// RADI: count == shells, finite, strictly ascending, all > emitter radius and <= kMaxLength.
void checkRadii(const ShadowField& field, std::string_view context);
// MAPS: offsets, indices, values (sizes, ranges, finiteness, magnitude).
void checkMaps(const ShadowField& field, std::string_view context);
// VIEW's face sizes: powers of two up to the limits (before anything is allocated).
void checkViewSizes(const EmitterViews& views, std::string_view context);
// VIEW (when present): face sizes powers of two up to the limits, value count, every value
// finite and in [0, kMaxRadiance].
void checkViews(const ShadowField& field, std::string_view context);

}  // namespace opal::shadow_field
