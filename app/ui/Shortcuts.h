#pragma once
// The lab's keyboard shortcuts, written once: the key handler dispatches on this table, the Info
// panel lists it, and a test checks the README's key table against it.
#include <optional>
#include <span>

namespace radiant::app {

enum class LabAction {
    RunPause, Step, Reset, Rekey, FalseColour, Wireframe, HomeView, TogglePanels, Dome, NextLessonStep,
    PreviousLessonStep, Compare, SaveSession, OpenFile, UndoMaterial, RedoMaterial, Screenshot, Quit
};

struct Shortcut {
    LabAction action;
    int key;             ///< GLFW key code
    int alternateKey;    ///< another GLFW key code doing the same, or 0
    const char* keys;    ///< as the README and the Info panel name them: "N or Right"
    const char* does;    ///< what it does, in the README's words
    bool repeats;        ///< a held key repeats it (stepping)
    bool control = false;  ///< only with Ctrl held (Ctrl+S saves; S alone is another action)
};

/// Every shortcut, in the order the README lists them.
std::span<const Shortcut> labShortcuts();
/// The shortcut a key press triggers, if any; `control`: Ctrl was held.
std::optional<Shortcut> shortcutForKey(int glfwKey, bool control = false);

/// The mouse, for the Info panel's list (not dispatched by the table).
struct MouseControl {
    const char* input;
    const char* does;
};
std::span<const MouseControl> labMouseControls();

} // namespace radiant::app
