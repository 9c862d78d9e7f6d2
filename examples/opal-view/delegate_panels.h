// What the render delegate describes of itself, as panels: its render stats (one row per
// entry of renderStats(), as it reports them), and its render settings, one control per
// setting descriptor (a checkbox, a slider within the descriptor's range, a choice or a
// text field). A change goes to the delegate before the next sync (which restarts the
// frame, as DELEGATE.md says); the saved scene authors those that differ from their
// defaults. opal:reference (the exact dipole gather) is one of them, also offered as a
// checkbox at the top of the settings.
#pragma once

#include "delegate/hd/render_delegate.h"
#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

void drawStatsPanel(const hd::RenderDelegate& delegate, bool& open);
// Changes go through the model (checked, then set on the session's worker). `problem`: the
// refusal of the last change, shown under the controls.
void drawRenderSettingsPanel(ViewerModel& model, const hd::RenderDelegate& delegate, bool& open, std::string& problem);

}  // namespace opal::view
