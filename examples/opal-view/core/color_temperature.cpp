#include "examples/opal-view/core/color_temperature.h"

#include "schema/error.h"

#include <sstream>

namespace opal::view {

void setColorTemperature(hd::LightDesc& light, double kelvin) {
    if (kelvin == 0.0) {
        light.enableColorTemperature = false;
        return;
    }
    if (!(kelvin >= kMinColorTemperature && kelvin <= kMaxColorTemperature)) {
        std::ostringstream message;
        message << "colour temperature " << kelvin << " K is outside " << kMinColorTemperature << " to "
                << kMaxColorTemperature << " K";
        throw Error(message.str());
    }
    light.enableColorTemperature = true;
    light.colorTemperature = kelvin;
}

}  // namespace opal::view
