// A key pressed and released between two frames (xdotool, a presenter remote, a quick tap while
// software GL draws a slow frame) still reaches the UI: Return in the Lessons panel's path field
// opens the lesson. Dear ImGui 1.86 reads keys as held-down states once per frame, so without the
// lab's one-frame hold (ImGuiLayer::notePress) the press was lost.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/Lab.h"
#include "radiometry/scene/AssetDirectory.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;

TEST_CASE("Return pressed and released between two frames opens the lesson typed in the path field") {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) FAIL("no X display: run the GL tests under Xvfb");
    LabOptions options;
    options.width = 1280;
    options.height = 800;
    options.vsync = false;
    options.maxPatchArea = 0.05;
    options.runOnStart = false;
    Lab lab(options);
    lab.frame();
    GLFWwindow* window = glfwGetCurrentContext();
    REQUIRE(window != nullptr);
    // The key callback GLFW calls: ImGui's backend's, which chains to the lab's.
    const GLFWkeyfun keyCallback = glfwSetKeyCallback(window, nullptr);
    glfwSetKeyCallback(window, keyCallback);
    REQUIRE(static_cast<bool>(keyCallback));
    // Keys reach the lab through that callback, not through the X server; a window another test opens
    // meanwhile on the same virtual display (ctest runs two at once) takes the X focus, and the focus
    // event would clear ImGui's keys between the press and the frame that reads it.
    glfwSetWindowFocusCallback(window, nullptr);

    lab.pressKey(GLFW_KEY_O, /*control=*/true);  // Ctrl+O: the path field takes the keyboard
    for (int i = 0; i < 3; ++i) lab.frame();
    const std::string file = (std::filesystem::path(assetDirectory()) / "lessons" / "01-radiometric-quantities.json").string();
    ImGui::GetIO().AddInputCharactersUTF8(file.c_str());
    for (int i = 0; i < 3; ++i) lab.frame();
    REQUIRE_FALSE(lab.lessons().isOpen());

    // Both events before the next frame, as xdotool sends them.
    keyCallback(window, GLFW_KEY_ENTER, glfwGetKeyScancode(GLFW_KEY_ENTER), GLFW_PRESS, 0);
    keyCallback(window, GLFW_KEY_ENTER, glfwGetKeyScancode(GLFW_KEY_ENTER), GLFW_RELEASE, 0);
    for (int i = 0; i < 3; ++i) lab.frame();
    REQUIRE(lab.lessons().isOpen());
    CHECK(lab.lessons().lesson().file == std::filesystem::path(file));
}
