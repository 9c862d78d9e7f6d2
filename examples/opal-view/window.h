// The viewer's window: GLFW with an OpenGL 3.3 core context (forward compatible), its
// functions loaded with glad, swap interval 1. HiDPI: the framebuffer size, not the window
// size, is what the picture is rendered at.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace opal::view {

class Window {
public:
    // Throws opal::Error with GLFW's description when there is no display (DISPLAY unset:
    // run under xvfb-run on a machine without one), no OpenGL 3.3 core, or no loader.
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool closeRequested() const;
    void requestClose();
    void setTitle(const std::string& title);
    std::pair<int, int> framebufferSize() const;
    // Shows the frame drawn, then waits out the rest of `interval` since the last one (a
    // display without vertical sync, such as Xvfb, would not wait), or until wakeEarly(),
    // asked every millisecond, says there is something to show sooner. Returns how long it
    // waited after the swap.
    std::chrono::steady_clock::duration swapBuffers(std::chrono::microseconds interval,
                                                    const std::function<bool()>& wakeEarly = {});
    void pollEvents();
    // Files dropped on the window since the last call, in the order dropped.
    std::vector<std::filesystem::path> takeDroppedFiles();

private:
    static void onDrop(GLFWwindow* window, int count, const char** paths);

    GLFWwindow* window_ = nullptr;
    std::vector<std::filesystem::path> dropped_;
    std::chrono::steady_clock::time_point lastSwap_;
};

}  // namespace opal::view
