#include "examples/opal-view/core/light_shape.h"

#include "examples/scene/scene_lights.h"
#include "schema/error.h"

#include <limits>
#include <sstream>

namespace opal::view {
namespace {

using namespace std::string_view_literals;

constexpr std::string_view Parameters[] = {"radius"sv, "cone"sv, "softness"sv, "angle"sv};

struct Range {
    double low, high;
    const char* unit;
};

Range rangeOf(std::string_view parameter) {
    if (parameter == "radius") return {0.0, std::numeric_limits<double>::max(), ""};
    if (parameter == "softness") return {0.0, scene::MaxConeSoftness, ""};
    if (parameter == "cone") return {0.0, scene::MaxConeAngle, " degrees"};
    return {0.0, scene::MaxDistantAngle, " degrees"};
}

// Which lights have it, for the refusal.
const char* owners(std::string_view parameter) {
    if (parameter == "radius") return "only sphere and spot lights have a radius (not a point light: treatAsPoint)";
    if (parameter == "cone") return "only sphere, point and spot lights have a cone";
    if (parameter == "softness") return "only spot lights have a softness (set a cone first)";
    return "only distant lights have an angle";
}

void requireInRange(std::string_view parameter, double value) {
    const Range range = rangeOf(parameter);
    if (value >= range.low && value <= range.high) return;
    std::ostringstream message;
    message << parameter << " " << value << " is ";
    if (range.high == std::numeric_limits<double>::max()) message << "negative";
    else message << "outside " << range.low << " to " << range.high << range.unit;
    throw Error(message.str());
}

}  // namespace

std::span<const std::string_view> lightShapeParameters() { return Parameters; }

bool hasShapeParameter(const hd::LightDesc& light, std::string_view parameter) {
    const bool sphere = light.kind == hd::LightKind::Sphere;
    if (parameter == "radius") return sphere && !light.treatAsPoint;
    if (parameter == "cone") return sphere;
    if (parameter == "softness") return sphere && light.shapingConeAngle.has_value();
    if (parameter == "angle") return light.kind == hd::LightKind::Distant;
    return false;
}

void setShapeParameter(hd::LightDesc& light, std::string_view parameter, double value) {
    bool known = false;
    for (const std::string_view name : Parameters) known |= name == parameter;
    if (!known) throw Error("unknown light parameter '" + std::string(parameter) + "' (radius, cone, softness, angle)");
    if (!hasShapeParameter(light, parameter))
        throw Error(owners(parameter));
    requireInRange(parameter, value);
    if (parameter == "radius") light.radius = value;
    else if (parameter == "cone") light.shapingConeAngle = value;
    else if (parameter == "softness") light.shapingConeSoftness = value;
    else light.angle = value;
}

}  // namespace opal::view
