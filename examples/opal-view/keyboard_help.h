// The keyboard and mouse help (H): every shortcut and gesture the viewer answers, centred
// over the picture until H is pressed again or it is closed.
#pragma once

namespace opal::view {

void drawKeyboardHelp(bool& open);

}  // namespace opal::view
