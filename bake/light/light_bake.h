// `opal-bake light SPEC -o STEM`: an emitter's field baked and written as a light asset,
//   STEM.usda              a layer with one OpalShadowFieldLight prim naming the sidecar,
//   STEM.<bake id>.opal    the light sidecar (schema/asset/LIGHTFIELD.md),
// under the asset bake's stem rules (bake/asset_stem.h): the stem's lock is held, the
// sidecar is written atomically under a name no other bake's has, then the layer (the
// commit), then the stem's other sidecars are removed. The bake identifier is XXH64 of
// a text listing the tool's version, the light sidecar's format, the emitter's canonical
// description (a mesh file's XXH64 included) and every field setting, so identical bakes
// are byte-identical.
#pragma once

#include "bake/light/emitter.h"
#include "bake/light/field_bake.h"
#include "bake/progress.h"
#include "bake/stem_lock.h"

#include <filesystem>
#include <string>
#include <vector>

namespace opal {

struct LightBakeReport {
    std::string spec, kind;
    FieldSettings settings;
    FieldBakeStats stats;
    std::uint64_t bakeId = 0;
    double emitterRadius = 0.0, innerRadius = 0.0, outerRadius = 0.0;
    std::filesystem::path layerFile, sidecarFile;
    std::uint64_t layerBytes = 0, sidecarBytes = 0;
    double writeSeconds = 0.0, totalSeconds = 0.0;
    std::vector<std::string> warnings;
};

std::string lightBakeIdentity(const Emitter& emitter, const FieldSettings& settings);
std::uint64_t lightBakeIdentifier(const Emitter& emitter, const FieldSettings& settings);

// Writes the field's sidecar and layer for the stem `lock` holds (the field's bakeId set).
void writeLightAsset(const StemLock& lock, const ShadowField& field, LightBakeReport& report);

// The whole bake of `opal-bake light`: takes the stem's lock (before the work, so a second
// bake of the stem fails at once), bakes the emitter's field, writes the asset and returns
// the report (spec, times, sizes, errors). Throws what the steps throw, Cancelled when
// cancelled (nothing written).
LightBakeReport bakeLightAsset(const std::string& spec, const Emitter& emitter, const FieldSettings& settings,
                               const std::filesystem::path& stem, ProgressSink* progress, const CancelToken& cancel);

// The report as JSON (sizes, times, compression error), written atomically.
void writeLightBakeReport(const std::filesystem::path& path, const LightBakeReport& report);
std::string formatLightBakeSummary(const LightBakeReport& report);

}  // namespace opal
