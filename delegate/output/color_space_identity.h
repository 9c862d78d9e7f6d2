// What a file header says about the color space of its pixels, beyond an OCIO name that
// only means something inside one config: the CIE xy chromaticities of the primaries and
// white point (EXR's standard `chromaticities` attribute) and the ASWF Color Interop
// Forum ID ("lin_ap1_scene" for ACEScg), which names the space independently of configs.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

namespace OCIO = OCIO_NAMESPACE;

struct Chromaticities {
    struct Xy {
        double x = 0.0, y = 0.0;
    };
    Xy red, green, blue, white;
};

// A scene-linear RGB space Opal can describe in file headers.
struct KnownLinearSpace {
    std::string_view name;       // as in the ACES CG config: "ACEScg"
    std::string_view interopId;  // Color Interop Forum ID: "lin_ap1_scene"
    std::vector<std::string_view> aliases;
    Chromaticities chromaticities;
};

// ACEScg (AP1), ACES2065-1 (AP0), Linear Rec.709 (sRGB), Linear P3-D65, Linear Rec.2020.
std::span<const KnownLinearSpace> knownLinearSpaces();

struct ColorSpaceIdentity {
    std::string name;  // the config's name for it, written as the EXR color space name
    std::optional<std::string> interopId;
    std::optional<Chromaticities> chromaticities;
};

// Identifies `colorSpace` of `config` (a name or alias) as one of knownLinearSpaces():
// first by its name and aliases, then numerically, by comparing its conversion to the
// config's aces_interchange space with each known space's RGB -> AP0 matrix (Bradford
// adaptation, as the ACES configs use). When neither matches, the identity carries only
// the name and a warning says why (warnings may be null). Throws opal::Error when the
// config has no such color space.
ColorSpaceIdentity identifyColorSpace(const OCIO::Config& config, std::string_view colorSpace,
                                      std::vector<std::string>* warnings);

}  // namespace opal
