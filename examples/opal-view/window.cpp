#include "examples/opal-view/window.h"

#include "schema/error.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <thread>

namespace opal::view {
namespace {

std::string glfwProblem() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no description";
}

}  // namespace

Window::Window(int width, int height, const std::string& title) {
    if (!glfwInit()) throw Error("cannot open a window: " + glfwProblem() + " (without a display, run under xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string problem = glfwProblem();
        glfwTerminate();
        throw Error("cannot create an OpenGL 3.3 core window: " + problem);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, &Window::onDrop);
    if (!gladLoadGL(glfwGetProcAddress)) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw Error("cannot load the OpenGL 3.3 core functions");
    }
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_); }

void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

std::pair<int, int> Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {width, height};
}

std::chrono::steady_clock::duration Window::swapBuffers(std::chrono::microseconds interval,
                                                        const std::function<bool()>& wakeEarly) {
    using Clock = std::chrono::steady_clock;
    constexpr std::chrono::milliseconds Poll{1};
    glfwSwapBuffers(window_);
    const auto swapped = Clock::now(), next = lastSwap_ + interval;
    for (auto now = swapped; now < next; now = Clock::now()) {
        if (wakeEarly && wakeEarly()) break;
        std::this_thread::sleep_for(std::min<Clock::duration>(Poll, next - now));
    }
    lastSwap_ = Clock::now();
    return lastSwap_ - swapped;
}

void Window::pollEvents() { glfwPollEvents(); }

void Window::onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
}

std::vector<std::filesystem::path> Window::takeDroppedFiles() {
    std::vector<std::filesystem::path> dropped;
    dropped.swap(dropped_);
    return dropped;
}

}  // namespace opal::view
