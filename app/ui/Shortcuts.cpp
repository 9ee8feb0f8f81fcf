#include "app/ui/Shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace radiant::app {
namespace {

constexpr Shortcut kShortcuts[] = {
    {LabAction::RunPause, GLFW_KEY_SPACE, 0, "Space", "run / pause the solve", false},
    {LabAction::Step, GLFW_KEY_N, GLFW_KEY_RIGHT, "N or Right", "one step (hold: repeat)", true},
    {LabAction::Reset, GLFW_KEY_R, 0, "R", "reset the solve", false},
    {LabAction::Rekey, GLFW_KEY_K, 0, "K", "re-key the exposure on the solution shown", false},
    {LabAction::FalseColour, GLFW_KEY_F, 0, "F", "false colour on / off", false},
    {LabAction::Wireframe, GLFW_KEY_W, 0, "W", "wireframe on / off", false},
    {LabAction::HomeView, GLFW_KEY_C, 0, "C", "back to the scene's home camera", false},
    {LabAction::TogglePanels, GLFW_KEY_H, 0, "H", "hide / show the panels", false},
    {LabAction::Dome, GLFW_KEY_S, 0, "S", "the dome over the probe point (the sky it sees) on / off", false},
    {LabAction::NextLessonStep, GLFW_KEY_PAGE_DOWN, 0, "Page Down", "next step of the open lesson", false},
    {LabAction::PreviousLessonStep, GLFW_KEY_PAGE_UP, 0, "Page Up", "previous step of the open lesson", false},
    {LabAction::Compare, GLFW_KEY_V, 0, "V", "compare two methods: side by side, then their difference, then off (Solver panel: which two)", false},
    {LabAction::SaveSession, GLFW_KEY_S, 0, "Ctrl+S", "save the session (scene, materials, method, camera, probe, display with its units, the comparison of two methods) as `radiant-session-YYYYMMDD-HHMMSS.json`", false, true},
    {LabAction::OpenFile, GLFW_KEY_O, 0, "Ctrl+O", "open a lesson or session file (the Lessons panel's path field)", false, true},
    {LabAction::UndoMaterial, GLFW_KEY_Z, 0, "Ctrl+Z", "undo the last material edit (a whole drag, or Reset materials)", false, true},
    {LabAction::RedoMaterial, GLFW_KEY_Y, 0, "Ctrl+Y", "redo the material edit undone", false, true},
    {LabAction::Screenshot, GLFW_KEY_F12, 0, "F12", "save a screenshot (`radiant-YYYYMMDD-HHMMSS.png`)", false},
    {LabAction::Quit, GLFW_KEY_ESCAPE, 0, "Esc", "quit", false},
};

constexpr MouseControl kMouse[] = {
    {"Left drag", "orbit"},
    {"Right/middle drag", "pan"},
    {"Wheel", "zoom"},
    {"Left click", "probe a point"},
};

} // namespace

std::span<const Shortcut> labShortcuts() { return kShortcuts; }
std::span<const MouseControl> labMouseControls() { return kMouse; }

std::optional<Shortcut> shortcutForKey(int glfwKey, bool control) {
    for (const Shortcut& shortcut : kShortcuts)
        if (shortcut.control == control &&
            (shortcut.key == glfwKey || (shortcut.alternateKey != 0 && shortcut.alternateKey == glfwKey)))
            return shortcut;
    return std::nullopt;
}

} // namespace radiant::app
