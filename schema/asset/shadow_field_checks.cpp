#include "schema/asset/shadow_field_checks.h"

#include "schema/asset/sidecar_checks.h"
#include "schema/error.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace opal::shadow_field {
namespace {

[[noreturn]] void fail(std::string_view context, const std::string& problem) {
    throw Error(std::string(context) + ": " + problem);
}

std::string str(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

bool powerOfTwo(std::uint32_t v) { return v != 0 && (v & (v - 1)) == 0; }

void checkFaceSize(std::uint32_t size, std::uint32_t max, std::string_view context, const char* what) {
    if (!powerOfTwo(size) || size > max)
        fail(context, std::string(what) + " face size " + std::to_string(size) + " is not a power of two up to " +
                          std::to_string(max));
}

}  // namespace

void checkHeader(const ShadowField& f, std::string_view context) {
    sidecar::checkName(f.name, context);
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(f.centre[i]) <= kMaxLength))
            fail(context, "centre coordinate " + str(f.centre[i]) + " is not finite or beyond 1e9 mm");
    if (!(f.emitterRadius > 0.0) || !(f.emitterRadius <= kMaxLength))
        fail(context, "emitter radius " + str(f.emitterRadius) + " mm is not in (0, 1e9]");
    if (f.shells() < kMinShells || f.shells() > kMaxShells)
        fail(context, std::to_string(f.shells()) + " shells, expected " + std::to_string(kMinShells) + " to " +
                          std::to_string(kMaxShells));
    checkFaceSize(f.directionFaceSize, kMaxDirectionFaceSize, context, "sample-direction");
    checkFaceSize(f.mapFaceSize, kMaxMapFaceSize, context, "cube-map");
    if (!(f.keptEnergy > 0.0 && f.keptEnergy <= 1.0))
        fail(context, "kept energy fraction " + str(f.keptEnergy) + " is not in (0, 1]");
}

void checkRadii(const ShadowField& f, std::string_view context) {
    for (std::size_t j = 0; j < f.radii.size(); ++j) {
        const double r = f.radii[j];
        if (!(r > f.emitterRadius) || !(r <= kMaxLength))
            fail(context, "shell " + std::to_string(j) + " radius " + str(r) + " mm is not in (emitter radius " +
                              str(f.emitterRadius) + ", 1e9]");
        if (j > 0 && !(r > f.radii[j - 1]))
            fail(context, "shell " + std::to_string(j) + " radius " + str(r) + " mm is not above shell " +
                              std::to_string(j - 1) + "'s " + str(f.radii[j - 1]));
    }
}


void checkMaps(const ShadowField& f, std::string_view context) {
    const std::uint64_t maps = f.maps(), entries = f.indices.size();
    if (f.offsets.size() != maps + 1)
        fail(context, std::to_string(f.offsets.size()) + " map offsets, expected maps + 1 = " +
                          std::to_string(maps + 1));
    sidecar::checkOffsets<std::uint64_t>(f.offsets, maps, entries, context, "map offsets");
    sidecar::checkIndices<std::uint64_t>(f.offsets, f.indices, f.mapTexels(), true, context, "coefficient indices");
    if (f.values.size() != 3 * entries)
        fail(context, std::to_string(f.values.size()) + " values for " + std::to_string(entries) +
                          " coefficients, expected 3 each");
    sidecar::checkFinite(f.values, context, "coefficient values");
    const double bound = kMaxRadiance * std::sqrt(double(f.mapTexels()));
    for (std::size_t k = 0; k < f.values.size(); ++k)
        if (std::abs(double(f.values[k])) > bound)
            fail(context, "coefficient value " + str(f.values[k]) + " at " + std::to_string(k) +
                              " exceeds the largest a map of radiance <= 1e20 has (" + str(bound) + ")");
}

void checkViewSizes(const EmitterViews& v, std::string_view context) {
    checkFaceSize(v.directionFaceSize, kMaxViewFaceSize, context, "view direction");
    checkFaceSize(v.imageSize, kMaxViewImageSize, context, "view image");
}

void checkViews(const ShadowField& f, std::string_view context) {
    const EmitterViews& v = f.views;
    checkViewSizes(v, context);
    if (v.radiance.size() != v.values())
        fail(context, std::to_string(v.radiance.size()) + " values, expected 3 x views x image size^2 = " +
                          std::to_string(v.values()));
    sidecar::checkFinite(v.radiance, context, "view radiance");
    for (std::size_t k = 0; k < v.radiance.size(); ++k)
        if (v.radiance[k] < 0.0f || double(v.radiance[k]) > kMaxRadiance)
            fail(context, "view radiance " + str(v.radiance[k]) + " at " + std::to_string(k) +
                              " is outside [0, 1e20]");
}

}  // namespace opal::shadow_field
