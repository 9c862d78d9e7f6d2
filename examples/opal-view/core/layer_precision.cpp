#include "examples/opal-view/core/layer_precision.h"

namespace opal::view {
namespace {

// Through a volatile float: GCC 12.2's SLP vectoriser at -O2 turns the double -> float ->
// double round trips of two colours in a row into code that skips the second colour's last
// two channels (tests/view viewer_model_test catches it).
double rounded(double value) {
    const volatile float narrowed = float(value);
    return double(narrowed);
}

void roundChannels(Rgb& c) {
    c.x = rounded(c.x);
    c.y = rounded(c.y);
    c.z = rounded(c.z);
}

}  // namespace

double storable(double value) { return rounded(value); }

hd::MaterialDesc storable(hd::MaterialDesc desc) {
    roundChannels(desc.subsurface.sigmaSPrime);
    roundChannels(desc.subsurface.sigmaA);
    desc.subsurface.eta = storable(desc.subsurface.eta);
    desc.specularRoughness = storable(desc.specularRoughness);
    return desc;
}

hd::LightDesc storable(hd::LightDesc desc) {
    roundChannels(desc.color);
    desc.intensity = storable(desc.intensity);
    desc.exposure = storable(desc.exposure);
    desc.radius = storable(desc.radius);
    if (desc.shapingConeAngle) desc.shapingConeAngle = storable(*desc.shapingConeAngle);
    desc.shapingConeSoftness = storable(desc.shapingConeSoftness);
    desc.angle = storable(desc.angle);
    desc.flicker.amplitude = storable(desc.flicker.amplitude);
    desc.flicker.frequency = storable(desc.flicker.frequency);
    desc.colorTemperature = storable(desc.colorTemperature);
    return desc;
}

hd::CameraDesc storable(hd::CameraDesc desc) {
    desc.focalLength = storable(desc.focalLength);
    desc.horizontalAperture = storable(desc.horizontalAperture);
    desc.verticalAperture = storable(desc.verticalAperture);
    desc.nearClip = storable(desc.nearClip);
    desc.farClip = storable(desc.farClip);
    return desc;
}

}  // namespace opal::view
