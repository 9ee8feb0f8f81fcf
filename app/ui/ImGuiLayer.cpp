#include "app/ui/ImGuiLayer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/ui/Theme.h"
#include "radiometry/common/Error.h"

namespace radiant::app {
namespace {

constexpr float kBaseFontPixels = 17.0f;

/// A humanist sans reads better on a projector than ImGui's built-in bitmap font; it is used when
/// the system has one (Debian's fonts-dejavu-core is nearly always there), else the built-in one.
const char* findUiFont() {
    static const char* const candidates[] = {
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
        "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf",
    };
    for (const char* path : candidates)
        if (std::filesystem::exists(path)) return path;
    return nullptr;
}

} // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, float uiScale) : scale_(std::clamp(uiScale, 0.5f, 3.0f)) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is the program's, not a file's beside the working directory
    // No keyboard navigation of the panels: with it, a focused panel claims every key
    // (WantCaptureKeyboard), so a click on a slider killed the lecturer's Space, N and R, and Space
    // would also press whichever button the navigation cursor rested on.
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true) || !ImGui_ImplOpenGL3_Init("#version 330 core")) {
        ImGui::DestroyContext();
        throw RadiantError({"window", "Dear ImGui"}, "cannot initialise the GLFW/OpenGL 3 backends");
    }
    applyScale();
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::setUiScale(float scale) { scale_ = std::clamp(scale, 0.5f, 3.0f); }

void ImGuiLayer::applyScale() {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig config;
    config.OversampleH = 2;
    config.OversampleV = 2;
    const float pixels = std::round(kBaseFontPixels * scale_);
    if (const char* path = findUiFont()) {
        io.Fonts->AddFontFromFileTTF(path, pixels, &config);
    } else {
        config.SizePixels = pixels;
        io.Fonts->AddFontDefault(&config);
    }
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    applyTheme(ImGui::GetStyle(), scale_);
    appliedScale_ = scale_;
}

void ImGuiLayer::newFrame() {
    if (scale_ != appliedScale_) applyScale();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGuiIO& keys = ImGui::GetIO();
    // Let go of last frame's one-frame presses (unless pressed again), then show this frame's
    // presses that were already released; index = GLFW key code, as 1.86's GLFW backend maps them.
    const auto inRange = [&](int key) { return key >= 0 && key < static_cast<int>(IM_ARRAYSIZE(keys.KeysDown)); };
    for (const int key : heldForOneFrame_)
        if (inRange(key) && std::find(pressedSinceFrame_.begin(), pressedSinceFrame_.end(), key) == pressedSinceFrame_.end())
            keys.KeysDown[key] = false;
    heldForOneFrame_.clear();
    for (const int key : pressedSinceFrame_)
        if (inRange(key) && !keys.KeysDown[key]) {
            keys.KeysDown[key] = true;
            heldForOneFrame_.push_back(key);
        }
    pressedSinceFrame_.clear();
    if (mouseOverride_) {  // after the backend, which writes the real pointer's state
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = {mouseOverride_->x, mouseOverride_->y};
        io.MouseDown[0] = mouseOverride_->leftDown;
    }
    ImGui::NewFrame();
}

void ImGuiLayer::notePress(int glfwKey) { pressedSinceFrame_.push_back(glfwKey); }

bool ImGuiLayer::keyboardClaimed() {
    if (!ImGui::GetCurrentContext()) return false;
    return ImGui::GetIO().WantTextInput || ImGui::IsAnyItemActive();
}

void ImGuiLayer::overrideMouse(std::optional<MouseOverride> mouse) { mouseOverride_ = mouse; }

void ImGuiLayer::render() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace radiant::app
