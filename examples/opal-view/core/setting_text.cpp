#include "examples/opal-view/core/setting_text.h"

#include "schema/error.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <variant>

namespace opal::view {
namespace {

template <class T>
bool parse(std::string_view text, T& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

hd::Value parseSettingValue(const hd::RenderSettingDescriptor& setting, std::string_view text) {
    const auto refuse = [&](const char* type) -> hd::Value {
        throw Error("setting " + setting.key + ": '" + std::string(text) + "' is not " + type);
    };
    if (std::holds_alternative<bool>(setting.defaultValue)) {
        if (text == "true" || text == "1") return true;
        if (text == "false" || text == "0") return false;
        return refuse("a bool (true, false, 1 or 0)");
    }
    if (std::holds_alternative<int>(setting.defaultValue)) {
        int value = 0;
        return parse(text, value) ? hd::Value(value) : refuse("an integer");
    }
    if (std::holds_alternative<double>(setting.defaultValue)) {
        double value = 0.0;
        return parse(text, value) && std::isfinite(value) ? hd::Value(value) : refuse("a finite number");
    }
    if (std::holds_alternative<std::string>(setting.defaultValue)) return std::string(text);
    return refuse("of a type a script can set");
}

void checkSettingValue(const hd::RenderSettingDescriptor& setting, const hd::Value& value) {
    if (value.index() != setting.defaultValue.index())
        throw Error("setting " + setting.key + ": a value of another type than its default's");
    double number = 0.0;
    if (const int* i = std::get_if<int>(&value)) number = *i;
    if (const double* d = std::get_if<double>(&value)) number = *d;
    if ((setting.min && number < *setting.min) || (setting.max && number > *setting.max)) {
        std::ostringstream message;
        message << "setting " << setting.key << ": " << number << " is outside [" << setting.min.value_or(number) << ", "
                << setting.max.value_or(number) << "]";
        throw Error(message.str());
    }
    const std::string* text = std::get_if<std::string>(&value);
    if (!text || setting.choices.empty()) return;
    std::string choices;
    for (const std::string& choice : setting.choices) {
        if (choice == *text) return;
        choices += (choices.empty() ? "" : ", ") + choice;
    }
    throw Error("setting " + setting.key + ": '" + *text + "' is not one of " + choices);
}

const hd::RenderSettingDescriptor& findSetting(const std::vector<hd::RenderSettingDescriptor>& settings,
                                               std::string_view key) {
    std::string known;
    for (const hd::RenderSettingDescriptor& setting : settings) {
        if (setting.key == key) return setting;
        known += (known.empty() ? "" : ", ") + setting.key;
    }
    throw Error("the renderer has no setting '" + std::string(key) + "' (settings: " + known + ")");
}

}  // namespace opal::view
