// The panels' label-value rows with ImGui alone (no GL: the font atlas is built on the CPU and the
// frame is laid out, never drawn): a value never starts inside its label ("Unshot power0.1578 W").
#include <doctest/doctest.h>

#include <imgui.h>

#include "app/ui/SidebarLayout.h"
#include "tests/support/HeadlessImGui.h"

namespace {

/// One ImGui context laying out a 300 x 400 window for the duration of a test.
struct LayoutFrame {
    radiant::test::HeadlessImGui imgui;
    LayoutFrame() {
        ImGui::NewFrame();
        ImGui::SetNextWindowPos({0, 0});
        ImGui::SetNextWindowSize({300, 400});
        ImGui::Begin("layout", nullptr, ImGuiWindowFlags_NoSavedSettings);
    }
    ~LayoutFrame() {
        ImGui::End();
        ImGui::EndFrame();
    }
    LayoutFrame(const LayoutFrame&) = delete;
    LayoutFrame& operator=(const LayoutFrame&) = delete;
};

} // namespace

TEST_CASE("labelValueRow: a value at its column when the label fits, on the next line when it does not") {
    const LayoutFrame frame;
    const float em = ImGui::GetFontSize();
    const float left = ImGui::GetWindowPos().x;

    const float shortTop = ImGui::GetCursorScreenPos().y;
    radiant::app::ui::labelValueRow("B", 7.0f, "%.4g W", 0.1578);
    CHECK(ImGui::GetItemRectMin().x == doctest::Approx(left + 7.0f * em));
    CHECK(ImGui::GetItemRectMin().y == doctest::Approx(shortTop));

    // A column narrower than its label: the old rows drew the value from the column on, over the label.
    const float labelWidth = ImGui::CalcTextSize("Unshot power").x;
    const float column = 0.5f * labelWidth / em;
    const float longTop = ImGui::GetCursorScreenPos().y;
    radiant::app::ui::labelValueRow("Unshot power", column, "%.4g W", 0.1578);
    CHECK(ImGui::GetItemRectMin().y >= longTop + ImGui::GetTextLineHeight());
}

TEST_CASE("sameLineIfFits keeps a unit beside its value only when the line has room for it") {
    const LayoutFrame frame;
    ImGui::TextUnformatted("0.123");
    const float firstTop = ImGui::GetItemRectMin().y;
    radiant::app::ui::sameLineIfFits(ImGui::CalcTextSize("W/m^2").x);
    ImGui::TextUnformatted("W/m^2");
    CHECK(ImGui::GetItemRectMin().y == doctest::Approx(firstTop));

    ImGui::TextUnformatted("0.123");
    const float secondTop = ImGui::GetItemRectMin().y;
    radiant::app::ui::sameLineIfFits(1000.0f);  // wider than the 300-unit window
    ImGui::TextUnformatted("W/m^2");
    CHECK(ImGui::GetItemRectMin().y > secondTop);
}
