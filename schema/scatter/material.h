// A translucent material: per-channel (sigma_s', sigma_a) in mm^-1 plus eta, the ten
// measured presets of Jensen et al. 2001, the artist parameterization (diffuse albedo +
// mean free path) and the editable range a baked asset supports.
#pragma once

#include "schema/scatter/dipole.h"
#include "schema/scatter/rgb.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

struct Material {
    Rgb sigmaSPrime{1.0, 1.0, 1.0};  // mm^-1
    Rgb sigmaA{0.01, 0.01, 0.01};    // mm^-1
    double eta = 1.3;

    DipoleCoefficients channel(int c) const { return {sigmaSPrime[c], sigmaA[c], eta}; }
};

struct NamedMaterial {
    std::string_view name;
    Material material;
};

// marble, skin1, skin2, ketchup, apple, chicken, cream, potato, skimmilk, wholemilk.
std::span<const NamedMaterial> jensenPresets();
std::optional<Material> findPreset(std::string_view name);

// What an artist edits: the total diffuse reflectance per channel (closed form of the
// dipole) and the diffuse mean free path l_d = 1/sigma_tr in mm (Jensen and Buhler 2002).
struct ArtistMaterial {
    Rgb albedo{0.8, 0.8, 0.8};
    Rgb meanFreePath{1.0, 1.0, 1.0};  // mm
    double eta = 1.3;
};

// Inverts the closed-form total reflectance numerically. Throws opal::Error naming the
// parameter and channel for albedo outside (0, 1), non-positive or non-finite input, and
// for eta outside the dipole's range (requireDipoleEta); toArtist as validateMaterial.
Material fromArtist(const ArtistMaterial& artist);
ArtistMaterial toArtist(const Material& material);

// The box of materials a baked asset (its PCA basis) is valid for.
struct EditableRange {
    double sigmaSPrimeMin = 0.0, sigmaSPrimeMax = 0.0;  // mm^-1
    double sigmaAMin = 0.0, sigmaAMax = 0.0;            // mm^-1
    double etaMin = 1.0, etaMax = 1.0;

    // The default: contains all ten presets with a margin.
    static EditableRange coveringPresets();

    // Throws opal::Error (prefixed with context) unless every interval is finite, positive
    // and ordered and both eta bounds lie in the dipole's range (requireDipoleEta).
    void validate(std::string_view context) const;
    bool contains(const Material& m) const;
    // Clamps every coefficient into the range; each clamped value adds a warning naming
    // the parameter, the channel, the value and the bound. Non-finite input, and an eta
    // outside the dipole's range (requireDipoleEta), throw.
    // warnings may be null.
    Material clamp(const Material& m, std::vector<std::string>* warnings) const;
};

// Throws opal::Error when a coefficient is non-finite or non-positive, or eta lies
// outside the dipole's range (requireDipoleEta).
void validateMaterial(const Material& m, std::string_view context);

}  // namespace opal
