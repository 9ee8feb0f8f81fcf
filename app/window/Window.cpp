#include "app/window/Window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include "radiometry/common/Error.h"

namespace radiant::app {
namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no description";
}

struct ContextRequest {
    int major, minor, samples;
};

GLFWwindow* tryCreate(const WindowOptions& options, const ContextRequest& request) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, request.major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, request.minor);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, request.samples);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    return glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
}

} // namespace

Window::Window(const WindowOptions& options) {
    if (glfwInit() != GLFW_TRUE) {
        const char* display = std::getenv("DISPLAY");
        throw RadiantError({"window", ""}, "cannot start GLFW (" + lastGlfwError() + "); DISPLAY is " +
                                               (display ? "'" + std::string(display) + "'" : "not set") +
                                               " - the lab needs a display (use xvfb-run without one)");
    }
    // Multisampling first when asked for; without it if the visual does not exist.
    std::vector<ContextRequest> requests;
    for (const auto& [major, minor] : {std::pair{4, 5}, std::pair{3, 3}}) {
        if (options.msaaSamples > 0) requests.push_back({major, minor, options.msaaSamples});
        requests.push_back({major, minor, 0});
    }
    std::string firstError;
    for (const ContextRequest& request : requests) {
        window_ = tryCreate(options, request);
        if (window_) {
            multisampled_ = request.samples > 0;
            if (request.major == 3)
                fallbackNote_ = "OpenGL 4.5 core is unavailable (" + firstError + "); running on 3.3 core";
            break;
        }
        if (firstError.empty()) firstError = lastGlfwError();
    }
    if (!window_) {
        glfwTerminate();
        throw RadiantError({"window", ""}, "no OpenGL 3.3+ core context: " + firstError);
    }
    if (!fallbackNote_.empty()) std::fprintf(stderr, "radiant: %s\n", fallbackNote_.c_str());
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(options.vsync ? 1 : 0);
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::swapBuffers() { glfwSwapBuffers(window_); }
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

float Window::pixelRatio() const {
    int windowWidth = 0, windowHeight = 0, pixelWidth = 0, pixelHeight = 0;
    glfwGetWindowSize(window_, &windowWidth, &windowHeight);
    glfwGetFramebufferSize(window_, &pixelWidth, &pixelHeight);
    return windowWidth > 0 ? static_cast<float>(pixelWidth) / static_cast<float>(windowWidth) : 1.0f;
}

} // namespace radiant::app
