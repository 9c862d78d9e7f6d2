#include "bake/light/field_bake.h"

#include "bake/light/cube_map_compression.h"
#include "bake/light/emitter_scene.h"
#include "bake/light/emitter_view_render.h"
#include "bake/light/incident_radiance.h"
#include "schema/asset/array_codec.h"
#include "schema/asset/shadow_field_checks.h"
#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>

namespace opal {
namespace {

void checkSettings(const FieldSettings& s) {
    if (s.shells < shadow_field::kMinShells || s.shells > shadow_field::kMaxShells)
        throw Error("light bake: shells must be 2 to 256, got " + std::to_string(s.shells));
    if (!(s.innerScale > 1.0 && s.outerScale > s.innerScale && std::isfinite(s.outerScale)))
        throw Error("light bake: shell radii need 1 < inner scale < outer scale");
    if (!(s.keptEnergy > 0.0 && s.keptEnergy <= 1.0)) throw Error("light bake: kept energy must be in (0, 1]");
    EmitterViews views;
    views.directionFaceSize = s.viewFaceSize;
    views.imageSize = s.viewImageSize;
    shadow_field::checkViewSizes(views, "light bake");
}

struct MapError {
    double energy = 0.0, error = 0.0;
};

// Rounds every value as the sidecar stores it and adds each map's rounding error energy.
void roundValues(ShadowField& field, std::vector<MapError>& errors) {
    const std::vector<float> exact = field.values;
    roundToHalfPlanes(field.values);
    for (std::uint64_t m = 0; m < field.maps(); ++m)
        for (std::uint64_t k = 3 * field.offsets[m]; k < 3 * field.offsets[m + 1]; ++k) {
            const double d = double(exact[k]) - field.values[k];
            errors[m].error += d * d;
        }
}

void summarize(const std::vector<MapError>& errors, FieldBakeStats& stats) {
    double sumSquares = 0.0, energy = 0.0, error = 0.0;
    std::uint64_t lit = 0;
    for (const MapError& e : errors) {
        if (e.energy == 0.0) continue;
        const double relative = std::sqrt(e.error / e.energy);
        stats.worstMapError = std::max(stats.worstMapError, relative);
        sumSquares += relative * relative;
        energy += e.energy;
        error += e.error;
        ++lit;
    }
    stats.rmsMapError = lit ? std::sqrt(sumSquares / double(lit)) : 0.0;
    stats.fieldError = energy > 0.0 ? std::sqrt(error / energy) : 0.0;
}

}  // namespace

std::vector<double> shellRadii(double emitterRadius, const FieldSettings& s) {
    std::vector<double> radii(s.shells);
    const double inner = s.innerScale * emitterRadius, ratio = s.outerScale / s.innerScale;
    for (std::uint32_t j = 0; j < s.shells; ++j) radii[j] = inner * std::pow(ratio, double(j) / (s.shells - 1));
    return radii;
}

ShadowField bakeShadowField(const Emitter& emitter, const FieldSettings& s, ProgressSink* progress,
                            const CancelToken& cancel, FieldBakeStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    checkSettings(s);
    const EmitterScene scene(emitter);
    const IncidentRadianceRenderer renderer(scene, s.mapFaceSize, s.raysPerTexelSide);
    ShadowField field;
    field.name = emitter.kind;
    field.centre = scene.bounds().centre;
    field.emitterRadius = scene.bounds().radius;
    field.radii = shellRadii(field.emitterRadius, s);
    field.directionFaceSize = s.directionFaceSize;
    field.mapFaceSize = s.mapFaceSize;
    field.keptEnergy = s.keptEnergy;
    shadow_field::checkHeader(field, "light bake");
    const CubeMapLayout directions(s.directionFaceSize);

    std::vector<CompressedCubeMap> maps(field.maps());
    std::atomic<std::uint64_t> rays{0};
    {
        const StageScope stage(progress, "light field", field.maps());
        tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, field.maps(), 8), [&](const auto& range) {
            std::uint64_t traced = 0;
            for (std::uint64_t m = range.begin(); m != range.end(); ++m) {
                if (cancel.requested()) return;
                const std::uint32_t shell = std::uint32_t(m / field.directionsPerShell());
                const Imath::V3d point = field.centre + Imath::V3d(directions.direction(
                                                            std::uint32_t(m % field.directionsPerShell()))) *
                                                            field.radii[shell];
                Random random(s.seed, m);
                std::vector<float> rgb = renderer.render(Imath::V3f(point), random, &traced);
                maps[m] = compressCubeMap(rgb, renderer.layout(), s.keptEnergy);
            }
            rays += traced;
            stage.advance(range.size());
        });
    }
    cancel.throwIfRequested();

    std::vector<MapError> errors(maps.size());
    field.offsets.push_back(0);
    for (std::size_t m = 0; m < maps.size(); ++m) {
        field.indices.insert(field.indices.end(), maps[m].indices.begin(), maps[m].indices.end());
        field.values.insert(field.values.end(), maps[m].values.begin(), maps[m].values.end());
        field.offsets.push_back(field.indices.size());
        errors[m] = {maps[m].energy, maps[m].droppedEnergy};
        maps[m] = {};
    }
    roundValues(field, errors);
    {
        const StageScope stage(progress, "emitter views", 1);
        field.views = renderEmitterViews(scene, s.viewFaceSize, s.viewImageSize);
        stage.advance(1);
    }
    shadow_field::checkViews(field, "light bake");
    if (stats) {
        stats->maps = field.maps();
        stats->coefficients = field.indices.size();
        stats->rays = rays.load();
        summarize(errors, *stats);
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return field;
}

}  // namespace opal
