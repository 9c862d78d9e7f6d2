// The A/B wipe over the picture: left of a vertical line the engine's picture, right of
// it the exact reference's (opal:reference); the user drags the line.
#pragma once

namespace opal::view {

struct WipeState {
    bool on = false;
    double split = 0.5;  // the line's position, a fraction of the picture's width
};

// Draws the line and lets a left drag on it move it; returns the line's framebuffer
// column. Over the line, the mouse is the interface's (not the viewport's).
int drawWipeLine(WipeState& wipe);

}  // namespace opal::view
