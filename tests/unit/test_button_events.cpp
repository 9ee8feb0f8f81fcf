// Issue #16: a click in the 3D view is taken where the button went down (ButtonRecorder, fed in
// event order by the window's callbacks), not where the pointer is when a slow frame reads it.
// CameraController runs in its own ImGui context with ImGui's pointer and button set by hand, as
// ImGui 1.86's GLFW backend sets them: the pointer at frame time, a press seen as down for one frame
// even when released before it.
#include <doctest/doctest.h>

#include <optional>

#include <imgui.h>

#include "app/window/ButtonEvents.h"
#include "app/window/CameraController.h"
#include "render/camera/OrbitCamera.h"
#include "tests/support/HeadlessImGui.h"

using namespace radiant;
using radiant::app::ButtonEvents;
using radiant::app::ButtonRecorder;
using radiant::app::CameraController;

namespace {

const render::Viewport kView{200, 0, 600, 600};  // right of a 200-wide sidebar

struct Gestures {
    test::HeadlessImGui imgui;

    /// One frame: ImGui's pointer and left button as the frame reads them, the events since the last.
    std::optional<glm::dvec2> frame(float x, float y, bool leftDown, const ButtonEvents& events = {}) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = {x, y};
        io.MouseDown[0] = leftDown;
        io.DeltaTime = 1.0f / 60;
        ImGui::NewFrame();
        controller.update(orbit, kView, events);
        ImGui::EndFrame();
        return controller.click();
    }

    /// A left click between two frames, as the window's events record it: pressed at `press`,
    /// released at `release`, the pointer then moved on to `after`.
    void clickBetweenFrames(const glm::dvec2& press, const glm::dvec2& release, const glm::dvec2& after) {
        recorder.moved(press);
        recorder.button(0, true);
        if (release != press) recorder.moved(release);
        recorder.button(0, false);
        recorder.moved(after);
    }

    /// The slow frame that sees the button down with the pointer already moved on to (x, y), then the frame after
    /// the release: no click in the first; the second's click, if any.
    std::optional<glm::dvec2> slowFrames(float x, float y) {
        CHECK_FALSE(frame(x, y, true, recorder.take()));
        return frame(x, y, false, recorder.take());
    }

    render::OrbitCamera orbit{render::Camera{}, glm::dvec3(0, 0, 1)};
    CameraController controller;
    ButtonRecorder recorder;
};

} // namespace

TEST_CASE("a click that a slow frame finds the pointer moved on from is taken where the button went down") {
    Gestures g;
    g.clickBetweenFrames({300, 200}, {300, 200}, {700, 500});
    const std::optional<glm::dvec2> click = g.slowFrames(700, 500);
    REQUIRE(click);
    CHECK(*click == glm::dvec2(300, 200));
}

TEST_CASE("with no events recorded (a test's overridden mouse) the click is where ImGui saw the pointer at the press") {
    Gestures g;
    CHECK_FALSE(g.frame(350, 250, true));
    const std::optional<glm::dvec2> click = g.frame(351, 251, false);
    REQUIRE(click);
    CHECK(*click == glm::dvec2(350, 250));  // the press frame's pointer
}

TEST_CASE("pressed, moved beyond the slop and released within one frame is a drag, not a click") {
    Gestures g;
    g.clickBetweenFrames({300, 200}, {310, 200}, {700, 500});  // 10 pixels: over the 4-pixel slop
    CHECK_FALSE(g.slowFrames(700, 500));

    // Within the slop, a hand's wobble, it stays a click.
    g.clickBetweenFrames({300, 200}, {302, 201}, {700, 500});
    const std::optional<glm::dvec2> click = g.slowFrames(700, 500);
    REQUIRE(click);
    CHECK(*click == glm::dvec2(300, 200));
}

TEST_CASE("a press on the sidebar is no click in the view, wherever the pointer went before the frame") {
    Gestures g;
    g.clickBetweenFrames({100, 200}, {100, 200}, {400, 300});  // on the sidebar, then over the view
    CHECK_FALSE(g.slowFrames(400, 300));
}

TEST_CASE("a press held over frames and released later is measured to where its release event was") {
    Gestures g;
    g.recorder.moved({300, 200});
    g.recorder.button(0, true);
    CHECK_FALSE(g.frame(300, 200, true, g.recorder.take()));
    CHECK_FALSE(g.frame(301, 200, true, g.recorder.take()));
    g.recorder.moved({302, 201});
    g.recorder.button(0, false);
    g.recorder.moved({600, 400});
    const std::optional<glm::dvec2> click = g.frame(600, 400, false, g.recorder.take());
    REQUIRE(click);
    CHECK(*click == glm::dvec2(300, 200));

    // take() hands each event over once.
    const ButtonEvents none = g.recorder.take();
    CHECK_FALSE(none[0].pressedAt);
    CHECK_FALSE(none[0].releasedAt);
}
