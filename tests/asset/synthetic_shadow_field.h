// Test support: shadow fields made in code (no bake), small enough for exhaustive checks.
#pragma once

#include "schema/asset/array_codec.h"
#include "schema/asset/shadow_field.h"

#include <cmath>
#include <functional>

namespace opal::test {

// Every map uniform: map m of shell j at sample direction w has radiance value(j, w) in
// all three channels (R, 2R, 3R... scaled per channel by channelScale). A uniform face of
// size s has one nonzero Haar coefficient, its average times s, at the face's first cell.
inline ShadowField uniformShadowField(std::function<double(std::uint32_t shell, std::uint64_t map)> value,
                                      std::uint32_t shells = 4, std::uint32_t directionFaceSize = 4,
                                      std::uint32_t mapFaceSize = 8) {
    ShadowField f;
    f.name = "synthetic";
    f.centre = {1.0, -2.0, 0.5};
    f.emitterRadius = 2.0;
    for (std::uint32_t j = 0; j < shells; ++j) f.radii.push_back(2.5 * std::pow(2.0, double(j)));
    f.directionFaceSize = directionFaceSize;
    f.mapFaceSize = mapFaceSize;
    f.keptEnergy = 0.999;
    f.offsets.push_back(0);
    const std::uint32_t faceCells = mapFaceSize * mapFaceSize;
    for (std::uint64_t m = 0; m < f.maps(); ++m) {
        const double v = value(std::uint32_t(m / f.directionsPerShell()), m);
        for (std::uint32_t face = 0; face < 6; ++face) {
            f.indices.push_back(face * faceCells);
            for (int c = 1; c <= 3; ++c) f.values.push_back(float(v * c * mapFaceSize));
        }
        f.offsets.push_back(f.indices.size());
    }
    return f;
}

// Arbitrary sparse maps with values of many magnitudes, rounded as the file stores them.
inline ShadowField irregularShadowField() {
    ShadowField f = uniformShadowField([](std::uint32_t, std::uint64_t) { return 0.0; }, 3, 2, 4);
    f.bakeId = 0x0123456789abcdefull;
    f.indices.clear();
    f.values.clear();
    f.offsets.assign(1, 0);
    for (std::uint64_t m = 0; m < f.maps(); ++m) {
        for (std::uint32_t i = std::uint32_t(m % 5); i < f.mapTexels(); i += 7 + std::uint32_t(m % 3)) {
            f.indices.push_back(i);
            for (int c = 0; c < 3; ++c) f.values.push_back(float(std::sin(double(m * 31 + i * 7 + c)) * std::pow(10.0, double(int(i % 9) - 4))));
        }
        f.offsets.push_back(f.indices.size());
    }
    roundToHalfPlanes(f.values);
    // Views: 6 x 1 x 1 directions of 4 x 4 pixels, values of many magnitudes.
    f.views.directionFaceSize = 1;
    f.views.imageSize = 4;
    for (std::uint64_t k = 0; k < f.views.values(); ++k)
        f.views.radiance.push_back(float(std::abs(std::sin(double(k) * 1.7)) * std::pow(10.0, double(int(k % 7) - 3))));
    roundToHalfPlanes(f.views.radiance);
    return f;
}

}  // namespace opal::test
