// Which of the viewer's optional panels are open (the View menu and the H, P and G keys).
#pragma once

namespace opal::view {

struct PanelVisibility {
    bool help = false;      // the keyboard help overlay (H)
    bool stats = false;     // the delegate's render stats
    bool settings = false;  // the render settings, from the delegate's descriptors
    bool delegates = false; // the delegate picker: the renderer plugins the registry found
    bool probe = false;     // the pixel probe under the cursor (P)
    bool gizmos = true;     // the light gizmos over the picture (G)
};

}  // namespace opal::view
