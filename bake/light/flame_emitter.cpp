#include "bake/light/flame_emitter.h"

#include "schema/scatter/blackbody.h"
#include "bake/light/emitter_shapes.h"
#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>

namespace opal {
namespace {

constexpr int kProfilePoints = 160;
constexpr int kSegments = 192;
constexpr double kWidest = 0.32476;  // max of sqrt(t) (1 - t)^1.5, at t = 1/4
constexpr int kTemperatureSteps = 256;

RenderMesh teardrop(const FlameShape& s) {
    std::vector<Imath::V2f> profile;
    for (int i = 0; i <= kProfilePoints; ++i) {
        const double t = 0.5 * (1.0 - std::cos(std::numbers::pi * i / kProfilePoints));  // dense at both ends
        const double r = i == 0 || i == kProfilePoints ? 0.0 : s.radius / kWidest * std::sqrt(t) * std::pow(1.0 - t, 1.5);
        profile.emplace_back(float(r), float(t * s.height));
    }
    return revolvedMesh(profile, kSegments, "flame");
}

// rgb(T) tabulated between the rim and core temperatures (it is smooth in T).
struct TemperatureTable {
    double rim, core;
    std::vector<Imath::V3f> rgb;

    TemperatureTable(double rimKelvin, double coreKelvin) : rim(rimKelvin), core(coreKelvin) {
        for (int i = 0; i <= kTemperatureSteps; ++i)
            rgb.emplace_back(blackbodyAcescg(rim + (core - rim) * i / kTemperatureSteps));
    }
    // f in [0, 1]: from rim to core.
    Imath::V3f at(float f) const {
        const float x = std::clamp(f, 0.0f, 1.0f) * kTemperatureSteps;
        const int i = std::min(int(x), kTemperatureSteps - 1);
        return rgb[i] + (rgb[i + 1] - rgb[i]) * (x - i);
    }
};

std::string describe(const FlameShape& s) {
    std::ostringstream text;
    text.precision(17);
    text << "flame:height=" << s.height << ",radius=" << s.radius << ",core_k=" << s.coreKelvin
         << ",rim_k=" << s.rimKelvin << ",luminance=" << s.luminance;
    return text.str();
}

}  // namespace

Emitter flameEmitter(const FlameShape& s) {
    for (double v : {s.height, s.radius, s.luminance})
        if (!(v > 0.0) || !std::isfinite(v)) throw Error("flame: height, radius and luminance must be positive and finite");
    auto table = std::make_shared<const TemperatureTable>(s.rimKelvin, s.coreKelvin);
    const float height = float(s.height), luminance = float(s.luminance);
    EmissionProfile emission = [table, height, luminance](const EmitterHit& hit) {
        const float mu = std::min(1.0f, std::abs(hit.direction.dot(hit.normal)));
        const float t = std::clamp(hit.point.y / height, 0.0f, 1.0f);
        return table->at(mu * (1.0f - t * t)) * (luminance * (0.25f + 0.75f * mu));
    };
    Emitter e{"flame", describe(s), {}};
    e.parts.push_back({"flame", teardrop(s), std::move(emission)});
    return e;
}

}  // namespace opal
