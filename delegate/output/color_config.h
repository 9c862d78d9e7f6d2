// The OpenColorIO configuration a delegate renders with: the working (scene_linear)
// space, the displays and views an artist may pick, and the processors between them.
// It holds its own OCIO config object and never touches OCIO's process-wide "current"
// config, so two delegates in one host may use different configs.
#pragma once

#include "delegate/output/color_space_identity.h"

#include <OpenColorIO/OpenColorIO.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

// Opal's convention for lat-long HDR environment maps, which carry no trustworthy color
// metadata (.hdr PRIMARIES lines are often zero): scene-linear Rec.709 primaries, D65.
inline constexpr std::string_view kEnvironmentMapColorSpace = "Linear Rec.709 (sRGB)";

class ColorConfig {
public:
    // Reads a variable of the process environment; nullopt when it is unset.
    using EnvironmentLookup = std::function<std::optional<std::string>(const char* name)>;

    // Loads and validates the config at `file`. Throws opal::Error naming the file.
    static ColorConfig fromFile(const std::filesystem::path& file);

    // The config named by $OCIO (as `lookup` reports it) when set and non-empty, else
    // the config Opal ships (shippedConfigCandidates). An $OCIO that does not load is an
    // error, never a silent fallback: a studio that sets it expects its colors.
    static ColorConfig fromEnvironment(const EnvironmentLookup& lookup,
                                       const std::filesystem::path& executable);
    // Same, with the real environment and this process's executable.
    static ColorConfig fromEnvironment();

    // Where the shipped config is looked for, in order: <exe dir>/../share/opal/ocio/
    // config.ocio (the install layout), then the source tree's delegate/output/ocio/config.ocio.
    static std::vector<std::filesystem::path> shippedConfigCandidates(
        const std::filesystem::path& executable);

    const std::filesystem::path& file() const { return file_; }
    const OCIO::ConstConfigRcPtr& ocio() const { return config_; }

    // The color space of the scene_linear role: what Opal renders and writes EXRs in.
    const std::string& workingSpace() const { return workingSpace_; }
    // The working space's chromaticities and interop ID for file headers; an unknown
    // working space yields the name only, plus a warning (warnings may be null).
    ColorSpaceIdentity workingSpaceIdentity(std::vector<std::string>* warnings) const;

    std::vector<std::string> displays() const;
    // Throws opal::Error, listing the displays, when `display` is not one.
    std::vector<std::string> views(const std::string& display) const;
    std::string defaultDisplay() const;
    std::string defaultView(const std::string& display) const;

    // working space -> display/view (a DisplayViewTransform). Throws opal::Error naming
    // the config file and listing the available displays or views when one is unknown.
    OCIO::ConstProcessorRcPtr workingToDisplay(const std::string& display,
                                               const std::string& view) const;
    // `colorSpace` (a name, alias or role) -> working space, e.g. for environment maps.
    OCIO::ConstProcessorRcPtr toWorking(const std::string& colorSpace) const;

private:
    ColorConfig(std::filesystem::path file, OCIO::ConstConfigRcPtr config);

    std::string context() const;  // "OCIO config '<file>'"
    void requireDisplayView(const std::string& display, const std::string& view) const;

    std::filesystem::path file_;
    OCIO::ConstConfigRcPtr config_;
    std::string workingSpace_;
};

}  // namespace opal
