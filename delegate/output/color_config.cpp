#include "delegate/output/color_config.h"

#include "schema/error.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>
#include <utility>

namespace opal {
namespace {

std::string quotedList(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
    return out.empty() ? "(none)" : out;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::filesystem::path thisExecutable() {
    std::error_code error;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : exe;
}

}  // namespace

ColorConfig::ColorConfig(std::filesystem::path file, OCIO::ConstConfigRcPtr config)
    : file_(std::move(file)), config_(std::move(config)) {
    const OCIO::ConstColorSpaceRcPtr linear = config_->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    if (!linear) throw Error(context() + ": has no scene_linear role (Opal's working space)");
    workingSpace_ = linear->getName();
}

ColorConfig ColorConfig::fromFile(const std::filesystem::path& file) {
    const std::string where = "OCIO config '" + file.string() + "'";
    if (!std::filesystem::is_regular_file(file)) throw Error(where + ": no such file");
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(file.c_str());
        config->validate();
        return ColorConfig(file, std::move(config));
    } catch (const OCIO::Exception& e) {
        throw Error(where + ": " + e.what());
    }
}

ColorConfig ColorConfig::fromEnvironment(const EnvironmentLookup& lookup,
                                         const std::filesystem::path& executable) {
    if (const std::optional<std::string> ocio = lookup("OCIO"); ocio && !ocio->empty()) {
        try {
            return fromFile(*ocio);
        } catch (const Error& e) {
            throw Error(std::string("$OCIO: ") + e.what());
        }
    }
    const std::vector<std::filesystem::path> candidates = shippedConfigCandidates(executable);
    for (const std::filesystem::path& candidate : candidates) {
        if (std::filesystem::is_regular_file(candidate)) return fromFile(candidate);
    }
    std::vector<std::string> searched;
    for (const std::filesystem::path& c : candidates) searched.push_back(c.string());
    throw Error("no OCIO config: $OCIO is not set and Opal's config is not at " +
                quotedList(searched));
}

ColorConfig ColorConfig::fromEnvironment() {
    const EnvironmentLookup processEnvironment =
        [](const char* name) -> std::optional<std::string> {
        const char* value = std::getenv(name);
        return value ? std::optional<std::string>(value) : std::nullopt;
    };
    return fromEnvironment(processEnvironment, thisExecutable());
}

std::vector<std::filesystem::path> ColorConfig::shippedConfigCandidates(
    const std::filesystem::path& executable) {
    std::vector<std::filesystem::path> candidates;
    if (!executable.empty()) {
        candidates.push_back(
            (executable.parent_path() / OPAL_INSTALLED_OCIO_CONFIG).lexically_normal());
    }
    candidates.emplace_back(OPAL_SOURCE_OCIO_CONFIG);
    return candidates;
}

ColorSpaceIdentity ColorConfig::workingSpaceIdentity(std::vector<std::string>* warnings) const {
    std::vector<std::string> found;
    ColorSpaceIdentity identity = identifyColorSpace(*config_, workingSpace_, &found);
    if (warnings) {
        for (const std::string& w : found) warnings->push_back(context() + ": " + w);
    }
    return identity;
}

std::vector<std::string> ColorConfig::displays() const {
    std::vector<std::string> names;
    for (int i = 0; i < config_->getNumDisplays(); ++i) names.emplace_back(config_->getDisplay(i));
    return names;
}

std::vector<std::string> ColorConfig::views(const std::string& display) const {
    if (!contains(displays(), display)) {
        throw Error(context() + ": no display '" + display +
                    "'; available displays: " + quotedList(displays()));
    }
    std::vector<std::string> names;
    for (int i = 0; i < config_->getNumViews(display.c_str()); ++i) {
        names.emplace_back(config_->getView(display.c_str(), i));
    }
    return names;
}

std::string ColorConfig::defaultDisplay() const { return config_->getDefaultDisplay(); }

std::string ColorConfig::defaultView(const std::string& display) const {
    views(display);  // validates the display name
    return config_->getDefaultView(display.c_str());
}

void ColorConfig::requireDisplayView(const std::string& display, const std::string& view) const {
    const std::vector<std::string> available = views(display);
    if (!contains(available, view)) {
        throw Error(context() + ": display '" + display + "' has no view '" + view +
                    "'; available views: " + quotedList(available));
    }
}

OCIO::ConstProcessorRcPtr ColorConfig::workingToDisplay(const std::string& display,
                                                        const std::string& view) const {
    requireDisplayView(display, view);
    OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(workingSpace_.c_str());
    transform->setDisplay(display.c_str());
    transform->setView(view.c_str());
    try {
        return config_->getProcessor(transform);
    } catch (const OCIO::Exception& e) {
        throw Error(context() + ": " + workingSpace_ + " -> '" + display + "' / '" + view +
                    "': " + e.what());
    }
}

OCIO::ConstProcessorRcPtr ColorConfig::toWorking(const std::string& colorSpace) const {
    if (!config_->getColorSpace(colorSpace.c_str())) {
        throw Error(context() + ": no color space, alias or role '" + colorSpace + "'");
    }
    try {
        return config_->getProcessor(colorSpace.c_str(), workingSpace_.c_str());
    } catch (const OCIO::Exception& e) {
        throw Error(context() + ": '" + colorSpace + "' -> " + workingSpace_ + ": " + e.what());
    }
}

std::string ColorConfig::context() const { return "OCIO config '" + file_.string() + "'"; }

}  // namespace opal
