#include "examples/opal-view/core/material_edit.h"

#include "schema/error.h"

#include <sstream>

namespace opal::view {
namespace {

constexpr const char* ChannelNames[] = {"red", "green", "blue"};

void requireWithin(double value, double lo, double hi, std::string_view what) {
    if (value >= lo && value <= hi) return;
    std::ostringstream message;
    message << what << " " << value << " is outside the asset's editable range [" << lo << ", " << hi << "]";
    throw Error(message.str());
}

void requireCount(std::span<const double> values, std::size_t count, std::string_view parameter) {
    if (values.size() != count)
        throw Error(std::string(parameter) + " takes " + std::to_string(count) + " value(s), got " +
                    std::to_string(values.size()));
}

void setChannels(Rgb& target, std::span<const double> values, double lo, double hi, std::string_view parameter) {
    requireCount(values, 3, parameter);
    for (int c = 0; c < 3; ++c) {
        requireWithin(values[c], lo, hi, std::string(parameter) + " (" + ChannelNames[c] + ", mm^-1)");
        target[c] = values[c];
    }
}

}  // namespace

hd::MaterialDesc bakedDefault(const TranslucentAsset& asset) {
    hd::MaterialDesc desc;
    desc.subsurface = asset.defaultMaterial;
    return desc;
}

hd::MaterialDesc withParameter(hd::MaterialDesc desc, std::string_view parameter, std::span<const double> values,
                               const TranslucentAsset& asset) {
    const EditableRange& range = asset.range;
    if (parameter == "sigma_s") {
        setChannels(desc.subsurface.sigmaSPrime, values, range.sigmaSPrimeMin, range.sigmaSPrimeMax, "sigma_s'");
    } else if (parameter == "sigma_a") {
        setChannels(desc.subsurface.sigmaA, values, range.sigmaAMin, range.sigmaAMax, "sigma_a");
    } else if (parameter == "eta") {
        requireCount(values, 1, parameter);
        requireWithin(values[0], range.etaMin, range.etaMax, "eta");
        desc.subsurface.eta = values[0];
    } else if (parameter == "roughness") {
        requireCount(values, 1, parameter);
        requireWithin(values[0], 0.0, 1.0, "specular roughness");
        desc.specularRoughness = values[0];
    } else {
        throw Error("unknown material parameter '" + std::string(parameter) + "' (sigma_s, sigma_a, eta, roughness)");
    }
    return desc;
}

}  // namespace opal::view
