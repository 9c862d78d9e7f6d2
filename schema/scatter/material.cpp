#include "schema/scatter/material.h"

#include "schema/error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <sstream>

namespace opal {

namespace {

constexpr std::array<char, 3> kChannelNames = {'r', 'g', 'b'};

// Jensen, Marschner, Levoy, Hanrahan 2001, "A Practical Model for Subsurface Light
// Transport", Figure 5: measured sigma_s' and sigma_a in mm^-1, eta = 1.3 for all.
// "chicken" is the table's Chicken1.
const std::array<NamedMaterial, 10> kJensenPresets = {{
    {"marble", {{2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}, 1.3}},
    {"skin1", {{0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3}},
    {"skin2", {{1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}, 1.3}},
    {"ketchup", {{0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}, 1.3}},
    {"apple", {{2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}, 1.3}},
    {"chicken", {{0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}, 1.3}},
    {"cream", {{7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}, 1.3}},
    {"potato", {{0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}, 1.3}},
    {"skimmilk", {{0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}, 1.3}},
    {"wholemilk", {{2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}, 1.3}},
}};

// The default editable range reaches this factor beyond the presets' extremes (on a log
// scale) so that sliders can move past every measured material. A wider box costs PCA
// accuracy: see kDefaultScaleRatio in profile_basis.cpp.
constexpr double kPresetMargin = 1.25;
constexpr double kDefaultEtaMin = 1.2;
constexpr double kDefaultEtaMax = 1.6;

std::string describe(std::string_view context, std::string_view parameter, int channel, double value) {
    std::ostringstream out;
    out << context << ": " << parameter;
    if (channel >= 0) out << '.' << kChannelNames[channel];
    out << " = " << value;
    return out.str();
}

void requirePositiveFinite(std::string_view context, std::string_view parameter, int channel, double value) {
    if (!std::isfinite(value) || !(value > 0.0))
        throw Error(describe(context, parameter, channel, value) + " must be positive and finite");
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    });
}

// Solves dipoleTotalReflectance(alpha', eta) = albedo for s = sqrt(3 (1 - alpha')) in
// [0, sqrt(3)] by bisection: the total reflectance falls monotonically from 1 (s = 0) to 0
// (s = sqrt(3)). Working in s keeps sigma_a = sigma_tr s / 3 accurate as alpha' -> 1.
double solveDiffusionExponent(double albedo, double eta) {
    double lo = 0.0, hi = std::sqrt(3.0);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        if (dipoleTotalReflectance(1.0 - mid * mid / 3.0, eta) > albedo)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

// sigma_tr = 1 / l_d; sigma_t' = sigma_tr / s; sigma_a = sigma_t' (1 - alpha') = sigma_tr s / 3.
void channelFromArtist(const ArtistMaterial& artist, int c, Material& out) {
    constexpr std::string_view context = "fromArtist";
    const double albedo = artist.albedo[c];
    if (!(albedo > 0.0 && albedo < 1.0))
        throw Error(describe(context, "albedo", c, albedo) + " must lie in the open interval (0, 1)");
    requirePositiveFinite(context, "meanFreePath", c, artist.meanFreePath[c]);
    const double s = solveDiffusionExponent(albedo, artist.eta);
    const double sigmaTr = 1.0 / artist.meanFreePath[c];
    const double sigmaTPrime = sigmaTr / s;
    out.sigmaA[c] = sigmaTr * s / 3.0;
    out.sigmaSPrime[c] = sigmaTPrime - out.sigmaA[c];
    if (!std::isfinite(sigmaTPrime) || !(out.sigmaA[c] > 0.0) || !(out.sigmaSPrime[c] > 0.0))
        throw Error(describe(context, "albedo", c, albedo) + " with meanFreePath." + kChannelNames[c] + " = " +
                    std::to_string(artist.meanFreePath[c]) + " mm has no finite positive sigma_s', sigma_a");
}

double clampValue(double value, double lo, double hi, std::string_view parameter, int channel,
                  std::vector<std::string>* warnings) {
    if (!std::isfinite(value))
        throw Error(describe("EditableRange::clamp", parameter, channel, value) + " is not finite");
    const double clamped = std::clamp(value, lo, hi);
    if (clamped != value && warnings) {
        std::ostringstream out;
        out << describe("EditableRange::clamp", parameter, channel, value) << " lies outside the editable range ["
            << lo << ", " << hi << "]; clamped to " << clamped;
        warnings->push_back(out.str());
    }
    return clamped;
}

}  // namespace

std::span<const NamedMaterial> jensenPresets() { return kJensenPresets; }

std::optional<Material> findPreset(std::string_view name) {
    for (const NamedMaterial& preset : kJensenPresets)
        if (equalsIgnoringCase(preset.name, name)) return preset.material;
    if (equalsIgnoringCase(name, "chicken1")) return findPreset("chicken");
    return std::nullopt;
}

void validateMaterial(const Material& m, std::string_view context) {
    for (int c = 0; c < 3; ++c) {
        requirePositiveFinite(context, "sigmaSPrime", c, m.sigmaSPrime[c]);
        requirePositiveFinite(context, "sigmaA", c, m.sigmaA[c]);
    }
    requireDipoleEta(m.eta, context);
}

Material fromArtist(const ArtistMaterial& artist) {
    requireDipoleEta(artist.eta, "fromArtist");
    Material material;
    material.eta = artist.eta;
    for (int c = 0; c < 3; ++c) channelFromArtist(artist, c, material);
    return material;
}

ArtistMaterial toArtist(const Material& material) {
    validateMaterial(material, "toArtist");
    ArtistMaterial artist;
    artist.eta = material.eta;
    for (int c = 0; c < 3; ++c) {
        const double sigmaTPrime = material.sigmaSPrime[c] + material.sigmaA[c];
        artist.albedo[c] = dipoleTotalReflectance(material.sigmaSPrime[c] / sigmaTPrime, material.eta);
        artist.meanFreePath[c] = 1.0 / std::sqrt(3.0 * material.sigmaA[c] * sigmaTPrime);
    }
    return artist;
}

EditableRange EditableRange::coveringPresets() {
    EditableRange range{1e300, 0.0, 1e300, 0.0, kDefaultEtaMin, kDefaultEtaMax};
    for (const NamedMaterial& preset : kJensenPresets) {
        for (int c = 0; c < 3; ++c) {
            range.sigmaSPrimeMin = std::min(range.sigmaSPrimeMin, preset.material.sigmaSPrime[c] / kPresetMargin);
            range.sigmaSPrimeMax = std::max(range.sigmaSPrimeMax, preset.material.sigmaSPrime[c] * kPresetMargin);
            range.sigmaAMin = std::min(range.sigmaAMin, preset.material.sigmaA[c] / kPresetMargin);
            range.sigmaAMax = std::max(range.sigmaAMax, preset.material.sigmaA[c] * kPresetMargin);
        }
    }
    return range;
}

void EditableRange::validate(std::string_view context) const {
    const auto requireInterval = [&](std::string_view name, double lo, double hi) {
        if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo > 0.0) || !(lo <= hi)) {
            std::ostringstream out;
            out << context << ": editable range " << name << " [" << lo << ", " << hi
                << "] must be finite, positive and ordered";
            throw Error(out.str());
        }
    };
    requireInterval("sigmaSPrime", sigmaSPrimeMin, sigmaSPrimeMax);
    requireInterval("sigmaA", sigmaAMin, sigmaAMax);
    requireDipoleEta(etaMin, std::string(context) + " (editable range eta minimum)");
    requireDipoleEta(etaMax, std::string(context) + " (editable range eta maximum)");
    requireInterval("eta", etaMin, etaMax);
}

bool EditableRange::contains(const Material& m) const {
    const auto inside = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
    for (int c = 0; c < 3; ++c)
        if (!inside(m.sigmaSPrime[c], sigmaSPrimeMin, sigmaSPrimeMax) || !inside(m.sigmaA[c], sigmaAMin, sigmaAMax))
            return false;
    return inside(m.eta, etaMin, etaMax);
}

Material EditableRange::clamp(const Material& m, std::vector<std::string>* warnings) const {
    validate("EditableRange::clamp");
    Material out;
    for (int c = 0; c < 3; ++c) {
        out.sigmaSPrime[c] = clampValue(m.sigmaSPrime[c], sigmaSPrimeMin, sigmaSPrimeMax, "sigmaSPrime", c, warnings);
        out.sigmaA[c] = clampValue(m.sigmaA[c], sigmaAMin, sigmaAMax, "sigmaA", c, warnings);
    }
    // Inside the dipole's valid eta range a value outside the editable one is clamped
    // with a warning; outside the valid range it is an error.
    requireDipoleEta(m.eta, "EditableRange::clamp");
    out.eta = clampValue(m.eta, etaMin, etaMax, "eta", -1, warnings);
    return out;
}

}  // namespace opal
