// A render setting's value written as text (the script's `setting KEY VALUE`), read as the
// type of the setting's default in the delegate's descriptor: bool (true, false, 1, 0),
// int, double, or string; and checked against the descriptor before it goes to the
// delegate's thread (where a refusal could only be reported later).
#pragma once

#include "delegate/hd/render_setting_descriptor.h"

#include <string_view>
#include <vector>

namespace opal::view {

// Throws opal::Error naming the setting and the expected type for text that is not one.
hd::Value parseSettingValue(const hd::RenderSettingDescriptor& setting, std::string_view text);

// Throws opal::Error naming the setting unless `value` has the type of its default, lies
// within its min and max, and is one of its choices when it lists some.
void checkSettingValue(const hd::RenderSettingDescriptor& setting, const hd::Value& value);

// The descriptor of `key`; throws opal::Error listing the known keys when there is none.
const hd::RenderSettingDescriptor& findSetting(const std::vector<hd::RenderSettingDescriptor>& settings,
                                               std::string_view key);

}  // namespace opal::view
