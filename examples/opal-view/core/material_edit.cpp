#include "examples/opal-view/core/material_edit.h"

#include "schema/error.h"
#include "schema/scatter/material.h"

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

// Albedo or mean free path replaced in the artist's terms (toArtist of the material),
// the rest kept, and back to coefficients within the asset's range.
void setArtistChannels(Material& material, std::span<const double> values, std::string_view parameter,
                       const EditableRange& range) {
    requireCount(values, 3, parameter);
    ArtistMaterial artist = toArtist(material);
    Rgb& target = parameter == "albedo" ? artist.albedo : artist.meanFreePath;
    for (int c = 0; c < 3; ++c) target[c] = values[c];
    const Material converted = fromArtist(artist);
    const double sigmaS[] = {converted.sigmaSPrime[0], converted.sigmaSPrime[1], converted.sigmaSPrime[2]};
    const double sigmaA[] = {converted.sigmaA[0], converted.sigmaA[1], converted.sigmaA[2]};
    const std::string via = " (from " + std::string(parameter) + ")";
    setChannels(material.sigmaSPrime, sigmaS, range.sigmaSPrimeMin, range.sigmaSPrimeMax, "sigma_s'" + via);
    setChannels(material.sigmaA, sigmaA, range.sigmaAMin, range.sigmaAMax, "sigma_a" + via);
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
    } else if (parameter == "albedo" || parameter == "mfp") {
        setArtistChannels(desc.subsurface, values, parameter, range);
    } else if (parameter == "eta") {
        requireCount(values, 1, parameter);
        requireWithin(values[0], range.etaMin, range.etaMax, "eta");
        desc.subsurface.eta = values[0];
    } else if (parameter == "roughness") {
        requireCount(values, 1, parameter);
        requireWithin(values[0], 0.0, 1.0, "specular roughness");
        desc.specularRoughness = values[0];
    } else {
        throw Error("unknown material parameter '" + std::string(parameter) + "' (sigma_s, sigma_a, albedo, mfp, eta, roughness)");
    }
    return desc;
}

}  // namespace opal::view
