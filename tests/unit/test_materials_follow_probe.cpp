// ctest-labels: threads
// The Materials panel follows the probe: a new pick selects the picked surface (ImGui alone, no GL:
// the font atlas is built on the CPU and the frame is laid out, never drawn).
#include <doctest/doctest.h>

#include <imgui.h>

#include <memory>
#include <optional>

#include "app/panels/MaterialsPanel.h"
#include "app/solver/LiveSolve.h"
#include "app/solver/SolverThread.h"
#include "tests/support/HeadlessImGui.h"

using namespace radiant;
using namespace radiant::app;

namespace {

/// Two unit squares, "floor" (z = 0, up) and "lid" (z = 1, down), the lid emitting.
std::shared_ptr<const Scene> twoPlates() {
    auto scene = std::make_shared<Scene>();
    scene->name = "plates";
    scene->materials.push_back({"grey", Rgb(0.5), ExitanceRgb(Rgb(0.0))});
    scene->materials.push_back({"lamp", Rgb(0.0), ExitanceRgb(Rgb(1.0))});
    Face floor;
    floor.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    floor.updateGeometry();
    Face lid;
    lid.vertices = {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};
    lid.updateGeometry();
    scene->surfaces.push_back({"floor", 0, {floor}, "test"});
    scene->surfaces.push_back({"lid", 1, {lid}, "test"});
    return scene;
}

/// Lays out one frame of the panel in its own ImGui context.
void drawOnce(MaterialsPanel& panel) {
    const radiant::test::HeadlessImGui imgui;
    ImGui::NewFrame();
    ImGui::SetNextWindowSize({400, 600});
    ImGui::Begin("materials", nullptr, ImGuiWindowFlags_NoSavedSettings);
    panel.draw();
    ImGui::End();
    ImGui::EndFrame();
}

} // namespace

TEST_CASE("the Materials panel selects the surface a probe pick lands on, once per pick") {
    SolverThread thread;
    thread.send(command::LoadScene{twoPlates(), MeshingOptions{1.0}});
    thread.waitUntilIdle();
    LiveSolve live(thread);
    live.refresh();
    REQUIRE(live.snapshot().scene);

    std::optional<ProbePick> pick;
    MaterialsPanel panel(live, [&] { return pick; });
    drawOnce(panel);
    CHECK(panel.selected() == 0);  // nothing picked: the first surface

    pick = ProbePick{{0.5, 0.5, 1.0}, {0, 0, -1}, 1, 0, live.snapshot().meshGeneration};
    drawOnce(panel);
    CHECK(panel.selected() == 1);

    pick = ProbePick{{0.2, 0.3, 0.0}, {0, 0, 1}, 0, 0, live.snapshot().meshGeneration};
    drawOnce(panel);
    CHECK(panel.selected() == 0);

    // A pick on a mesh no longer shown is not followed.
    pick = ProbePick{{0.5, 0.5, 1.0}, {0, 0, -1}, 1, 0, live.snapshot().meshGeneration + 1};
    drawOnce(panel);
    CHECK(panel.selected() == 0);
}
