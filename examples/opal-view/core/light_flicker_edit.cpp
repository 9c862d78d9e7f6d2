#include "examples/opal-view/core/light_flicker_edit.h"

#include "schema/error.h"

#include <cmath>
#include <sstream>

namespace opal::view {
namespace {

constexpr double MaxFrequency = 1000.0;
constexpr double MaxSeed = 4294967295.0;

void requireWithin(double value, double lo, double hi, const char* what) {
    if (value >= lo && value <= hi) return;
    std::ostringstream message;
    message << "flicker " << what << " " << value << " is outside [" << lo << ", " << hi << "]";
    throw Error(message.str());
}

}  // namespace

void setFlicker(hd::LightDesc& light, double amplitude, double frequency, double seed) {
    if (light.kind != hd::LightKind::ShadowField) throw Error("only a shadow-field light flickers");
    requireWithin(amplitude, 0.0, 1.0, "amplitude");
    requireWithin(frequency, 0.0, MaxFrequency, "frequency (Hz)");
    requireWithin(seed, 0.0, MaxSeed, "seed");
    if (seed != std::floor(seed)) throw Error("flicker seed " + std::to_string(seed) + " is not a whole number");
    light.flicker = {amplitude, frequency, std::uint64_t(seed)};
}

}  // namespace opal::view
