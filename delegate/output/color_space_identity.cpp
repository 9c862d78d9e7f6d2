#include "delegate/output/color_space_identity.h"

#include "schema/error.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

namespace opal {
namespace {

constexpr Chromaticities::Xy kAcesWhite{0.32168, 0.33767};
constexpr Chromaticities::Xy kD65{0.3127, 0.3290};

// Primaries from ITU-R BT.709, SMPTE EG 432-1 (P3), ITU-R BT.2020, and SMPTE ST 2065-1 /
// Academy S-2014-004 (AP0, AP1).
const std::vector<KnownLinearSpace>& table() {
    static const std::vector<KnownLinearSpace> spaces = {
        {"ACEScg",
         "lin_ap1_scene",
         {"lin_ap1", "ACES - ACEScg"},
         {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}, kAcesWhite}},
        {"ACES2065-1",
         "lin_ap0_scene",
         {"lin_ap0", "aces2065_1", "ACES - ACES2065-1"},
         {{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}, kAcesWhite}},
        {"Linear Rec.709 (sRGB)",
         "lin_rec709_scene",
         {"lin_rec709_srgb", "lin_rec709", "lin_srgb", "Utility - Linear - sRGB",
          "Utility - Linear - Rec.709"},
         {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, kD65}},
        {"Linear P3-D65",
         "lin_p3d65_scene",
         {"lin_p3d65", "Utility - Linear - P3-D65"},
         {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}, kD65}},
        {"Linear Rec.2020",
         "lin_rec2020_scene",
         {"lin_rec2020", "Utility - Linear - Rec.2020"},
         {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, kD65}},
    };
    return spaces;
}

bool sameName(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](unsigned char x, unsigned char y) {
        return std::tolower(x) == std::tolower(y);
    });
}

bool knownAs(const KnownLinearSpace& space, std::string_view name) {
    if (sameName(space.name, name) || sameName(space.interopId, name)) return true;
    return std::any_of(space.aliases.begin(), space.aliases.end(),
                       [&](std::string_view alias) { return sameName(alias, name); });
}

std::vector<std::string> namesOf(const OCIO::ColorSpace& cs) {
    std::vector<std::string> names{cs.getName()};
    for (size_t i = 0; i < cs.getNumAliases(); ++i) names.emplace_back(cs.getAlias(i));
    return names;
}

const KnownLinearSpace* findByName(const OCIO::ColorSpace& cs) {
    for (const std::string& name : namesOf(cs)) {
        for (const KnownLinearSpace& space : table()) {
            if (knownAs(space, name)) return &space;
        }
    }
    return nullptr;
}

// Matrices act on column vectors here: y = m * v.
Imath::V3d times(const Imath::M33d& m, const Imath::V3d& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Imath::V3d xyToXyz(Chromaticities::Xy c) { return {c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y}; }

Imath::M33d columns(const Imath::V3d& a, const Imath::V3d& b, const Imath::V3d& c) {
    return Imath::M33d(a.x, b.x, c.x, a.y, b.y, c.y, a.z, b.z, c.z);
}

Imath::M33d diagonal(const Imath::V3d& d) { return Imath::M33d(d.x, 0, 0, 0, d.y, 0, 0, 0, d.z); }

// RGB -> XYZ: each primary's XYZ scaled so that RGB (1, 1, 1) is the white with Y = 1.
Imath::M33d rgbToXyz(const Chromaticities& c) {
    const Imath::M33d primaries = columns(xyToXyz(c.red), xyToXyz(c.green), xyToXyz(c.blue));
    const Imath::V3d scale = times(primaries.gjInverse(), xyToXyz(c.white));
    return primaries * diagonal(scale);
}

// Von Kries adaptation in the Bradford cone space.
Imath::M33d bradford(Chromaticities::Xy from, Chromaticities::Xy to) {
    const Imath::M33d cone(0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685,
                           1.0296);
    const Imath::V3d src = times(cone, xyToXyz(from));
    const Imath::V3d dst = times(cone, xyToXyz(to));
    return cone.gjInverse() * diagonal({dst.x / src.x, dst.y / src.y, dst.z / src.z}) * cone;
}

Imath::M33d toAp0(const Chromaticities& c) {
    const Chromaticities& ap0 = table()[1].chromaticities;
    return rgbToXyz(ap0).gjInverse() * bradford(c.white, ap0.white) * rgbToXyz(c);
}

Imath::V3d apply(const OCIO::CPUProcessor& cpu, const Imath::V3d& v) {
    std::array<float, 3> rgb{float(v.x), float(v.y), float(v.z)};
    cpu.applyRGB(rgb.data());
    return {rgb[0], rgb[1], rgb[2]};
}

// The matrix of a linear processor, or nullopt when the processor is not linear.
std::optional<Imath::M33d> linearMatrix(const OCIO::CPUProcessor& cpu) {
    const Imath::M33d m =
        columns(apply(cpu, {1, 0, 0}), apply(cpu, {0, 1, 0}), apply(cpu, {0, 0, 1}));
    const Imath::V3d probe{0.3, 2.5, 0.04};
    const Imath::V3d expected = times(m, probe);
    if ((apply(cpu, probe) - expected).length() > 1e-4 * expected.length()) return std::nullopt;
    if (apply(cpu, {0, 0, 0}).length() > 1e-6) return std::nullopt;
    return m;
}

bool nearlyEqual(const Imath::M33d& a, const Imath::M33d& b) {
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (std::abs(a[i][j] - b[i][j]) > 2e-4) return false;
        }
    }
    return true;
}

const KnownLinearSpace* findByMatrix(const OCIO::Config& config, const char* colorSpace) {
    if (!config.hasRole(OCIO::ROLE_INTERCHANGE_SCENE)) return nullptr;
    const OCIO::ConstCPUProcessorRcPtr cpu =
        config.getProcessor(colorSpace, OCIO::ROLE_INTERCHANGE_SCENE)->getDefaultCPUProcessor();
    const std::optional<Imath::M33d> m = linearMatrix(*cpu);
    if (!m) return nullptr;
    for (const KnownLinearSpace& space : table()) {
        if (nearlyEqual(*m, toAp0(space.chromaticities))) return &space;
    }
    return nullptr;
}

}  // namespace

std::span<const KnownLinearSpace> knownLinearSpaces() { return table(); }

ColorSpaceIdentity identifyColorSpace(const OCIO::Config& config, std::string_view colorSpace,
                                      std::vector<std::string>* warnings) {
    const std::string requested(colorSpace);
    const OCIO::ConstColorSpaceRcPtr cs = config.getColorSpace(requested.c_str());
    if (!cs) {
        throw Error("OCIO config '" + std::string(config.getName()) + "': no color space '" +
                    requested + "'");
    }
    ColorSpaceIdentity identity{cs->getName(), std::nullopt, std::nullopt};
    const KnownLinearSpace* known = findByName(*cs);
    if (!known) {
        try {
            known = findByMatrix(config, cs->getName());
        } catch (const OCIO::Exception&) {
            known = nullptr;  // no processor to aces_interchange: nothing to compare
        }
    }
    if (known) {
        identity.interopId = std::string(known->interopId);
        identity.chromaticities = known->chromaticities;
    } else if (warnings) {
        warnings->push_back("color space '" + identity.name +
                            "' is not a linear space Opal knows (ACEScg, ACES2065-1, Linear "
                            "Rec.709, P3-D65, Rec.2020) by name or by its matrix to "
                            "aces_interchange: headers carry its name only, no chromaticities");
    }
    return identity;
}

}  // namespace opal
