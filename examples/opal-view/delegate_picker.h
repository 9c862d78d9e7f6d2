// The delegate picker: a panel listing every renderer plugin the registry found (display
// name, type and priority, in priority order, the one in use selected) and the manifests
// or declarations it skipped with the reason. Choosing another returns its type; the
// viewer then renders the open scene with it (Viewer::useDelegate).
#pragma once

#include "examples/opal-view/core/delegate_choices.h"

#include <optional>
#include <string>
#include <vector>

namespace opal::view {

std::optional<std::string> drawDelegatePicker(const std::vector<DelegateChoice>& choices,
                                              const std::vector<std::string>& skipped, bool& open);

}  // namespace opal::view
