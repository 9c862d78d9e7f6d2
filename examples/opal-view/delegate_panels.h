// What the render delegate describes of itself, as panels: its render stats (one row per
// entry of renderStats(), as it reports them), and its render settings, one control per
// setting descriptor (a checkbox, a slider within the descriptor's range, a choice or a
// text field). Changing a setting goes to the delegate at once (the next pass restarts
// the frame, as DELEGATE.md says); the saved scene authors those that differ from their
// defaults. opal:reference (the exact dipole gather) is one of them, also offered as a
// checkbox at the top of the settings.
#pragma once

#include "delegate/hd/render_delegate.h"

#include <string>

namespace opal::view {

void drawStatsPanel(const hd::RenderDelegate& delegate, bool& open);
// `problem`: the delegate's refusal of the last change, shown under the controls.
void drawRenderSettingsPanel(hd::RenderDelegate& delegate, bool& open, std::string& problem);

}  // namespace opal::view
