// Dear ImGui on the viewer's window (Debian's 1.86 with its GLFW and OpenGL 3 backends):
// the context, and the frame bracket the interface is drawn in.
#pragma once

#include "examples/opal-view/window.h"

namespace opal::view {

class ImGuiLayer {
public:
    explicit ImGuiLayer(const Window& window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    // Draws what the frame built into the current framebuffer.
    void render();
};

}  // namespace opal::view
