#include "bake/light/light_bake.h"

#include "schema/asset/asset_layer.h"
#include "schema/asset/bake_id.h"
#include "schema/asset/shadow_field_file.h"
#include "schema/asset/shadow_field_layer.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"
#include "schema/usd/crash_point.h"
#include "schema/usd/usda_writer.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <sstream>

#ifndef OPAL_VERSION
#error "bake/light/CMakeLists.txt defines OPAL_VERSION for this file"
#endif

namespace opal {

std::string lightBakeIdentity(const Emitter& emitter, const FieldSettings& s) {
    std::ostringstream text;
    text.precision(17);
    text << "tool opal-bake light " << OPAL_VERSION << '\n'
         << "format " << kShadowFieldKind.tag.str() << ' ' << kShadowFieldKind.version.str() << '\n'
         << "emitter " << emitter.description << '\n'
         << "shells " << s.shells << " inner " << s.innerScale << " outer " << s.outerScale << '\n'
         << "directions " << s.directionFaceSize << " map " << s.mapFaceSize << " rays " << s.raysPerTexelSide << '\n'
         << "kept energy " << s.keptEnergy << " seed " << s.seed << '\n'
         << "views " << s.viewFaceSize << " image " << s.viewImageSize << '\n';
    return text.str();
}

std::uint64_t lightBakeIdentifier(const Emitter& emitter, const FieldSettings& settings) {
    const std::string identity = lightBakeIdentity(emitter, settings);
    return xxh64(std::as_bytes(std::span(identity.data(), identity.size())));
}

void writeLightAsset(const StemLock& lock, const ShadowField& field, LightBakeReport& report) {
    if (!field.bakeId) throw Error(lock.stem().layer().string() + ": the light field has no bake identifier");
    const auto start = std::chrono::steady_clock::now();
    const AssetStem& stem = lock.stem();
    const std::filesystem::path sidecar = stem.sidecar(*field.bakeId);
    const std::string primName = assetNameFrom(stem.stem().filename().string());
    // Formed (and the name checked) before anything is written.
    const usda::Layer layer = shadowFieldLayer(primName, "./" + sidecar.filename().string(), field.bakeId);
    crashPoint("bake:writing");
    stem.removeStaleTemporaries(&report.warnings);
    crashPoint("bake:cleaned");
    writeShadowFieldFile(sidecar, field);
    usda::writeUsdaFile(stem.layer(), layer);  // the commit
    crashPoint("bake:committed");
    stem.removeSidecarsExcept(*field.bakeId, &report.warnings);
    crashPoint("bake:pruned");
    report.layerFile = stem.layer();
    report.sidecarFile = sidecar;
    report.layerBytes = std::filesystem::file_size(stem.layer());
    report.sidecarBytes = std::filesystem::file_size(sidecar);
    report.writeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

LightBakeReport bakeLightAsset(const std::string& spec, const Emitter& emitter, const FieldSettings& settings,
                               const std::filesystem::path& stem, ProgressSink* progress, const CancelToken& cancel) {
    const auto start = std::chrono::steady_clock::now();
    const StemLock lock{AssetStem(stem)};
    LightBakeReport report;
    report.spec = spec;
    report.kind = emitter.kind;
    report.settings = settings;
    ShadowField field = bakeShadowField(emitter, settings, progress, cancel, &report.stats);
    cancel.throwIfRequested();
    field.bakeId = report.bakeId = lightBakeIdentifier(emitter, settings);
    report.emitterRadius = field.emitterRadius;
    report.innerRadius = field.radii.front();
    report.outerRadius = field.radii.back();
    writeLightAsset(lock, field, report);
    report.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

void writeLightBakeReport(const std::filesystem::path& path, const LightBakeReport& r) {
    const FieldSettings& s = r.settings;
    nlohmann::ordered_json j;
    j["light"] = {{"spec", r.spec}, {"kind", r.kind}, {"bakeId", formatBakeId(r.bakeId)},
                  {"layer", r.layerFile.string()}, {"sidecar", r.sidecarFile.string()}};
    j["settings"] = {{"shells", s.shells},         {"directionFaceSize", s.directionFaceSize},
                     {"mapFaceSize", s.mapFaceSize}, {"raysPerTexelSide", s.raysPerTexelSide},
                     {"innerScale", s.innerScale}, {"outerScale", s.outerScale},
                     {"keptEnergy", s.keptEnergy}, {"seed", s.seed},
                     {"viewFaceSize", s.viewFaceSize}, {"viewImageSize", s.viewImageSize}};
    j["field"] = {{"emitterRadiusMm", r.emitterRadius}, {"innerRadiusMm", r.innerRadius},
                  {"outerRadiusMm", r.outerRadius},     {"maps", r.stats.maps},
                  {"coefficients", r.stats.coefficients}, {"rays", r.stats.rays}};
    j["sizes"] = {{"sidecarBytes", r.sidecarBytes}, {"layerBytes", r.layerBytes}};
    j["time"] = {{"bakeSeconds", r.stats.seconds}, {"writeSeconds", r.writeSeconds}, {"totalSeconds", r.totalSeconds}};
    j["compression"] = {{"keptEnergy", s.keptEnergy},
                        {"worstMapRelativeError", r.stats.worstMapError},
                        {"rmsMapRelativeError", r.stats.rmsMapError},
                        {"fieldRelativeError", r.stats.fieldError}};
    j["warnings"] = r.warnings;
    writeFileAtomically(path, j.dump(2) + "\n");
}

std::string formatLightBakeSummary(const LightBakeReport& r) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "opal-bake light: %s -> %s (%.1f MB sidecar, %llu maps, %llu coefficients); %.1f s; "
                  "compression error: worst map %.2f%%, RMS %.2f%%\n",
                  r.spec.c_str(), r.layerFile.string().c_str(), double(r.sidecarBytes) / 1e6,
                  (unsigned long long)r.stats.maps, (unsigned long long)r.stats.coefficients, r.totalSeconds,
                  100.0 * r.stats.worstMapError, 100.0 * r.stats.rmsMapError);
    return text;
}

}  // namespace opal
