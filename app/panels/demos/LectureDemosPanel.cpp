#include "app/panels/demos/LectureDemosPanel.h"

#include <imgui.h>

#include <cstring>

#include "app/panels/demos/DemoView.h"
#include "app/panels/demos/LectureDemos.h"

namespace radiant::app {

LectureDemosPanel::LectureDemosPanel(DemoView& view) : view_(view) {
    demos_.push_back(std::make_unique<PointSourceDemo>());
    demos_.push_back(std::make_unique<DiffuseEmitterDemo>());
    demos_.push_back(std::make_unique<SunDemo>());
    demos_.push_back(std::make_unique<SquareSolidAngleDemo>());
    demos_.push_back(std::make_unique<DodecahedronDemo>());
    demos_.push_back(std::make_unique<RadianceIrradianceDemo>());
}

void LectureDemosPanel::focus(const char* demoTitle) {
    for (const auto& demo : demos_)
        if (std::strcmp(demoTitle, demo->title()) == 0) {
            focused_ = demoTitle;
            focusPending_ = true;
            view_.open(*demo);
        }
}

void LectureDemosPanel::closeDemo() {
    view_.close();
    focused_.clear();  // every section closes at the next draw
    focusPending_ = true;
}

void LectureDemosPanel::draw() {
    drawn_ = true;
    // A section toggled during this draw asks for the next one (focus() and closeDemo() set these again).
    const bool expandAll = expandAll_, applyFocus = focusPending_;
    const std::string focused = focused_;
    expandAll_ = focusPending_ = false;
    for (const auto& demo : demos_) {
        // "Demo: point source over a plane" -> "point source over a plane" under this header.
        const char* name = demo->title();
        if (std::strncmp(name, "Demo: ", 6) == 0) name += 6;
        const bool shown = view_.active() == demo.get();
        // A demo opened wins over the sidebar's "expand all" that focusing this header also sends.
        if (applyFocus) ImGui::SetNextItemOpen(focused == demo->title());
        else if (expandAll) ImGui::SetNextItemOpen(true);
        const bool open = ImGui::TreeNodeEx(name, ImGuiTreeNodeFlags_SpanAvailWidth);
        if (ImGui::IsItemToggledOpen()) {
            if (open) {
                focus(demo->title());
            } else if (shown) {
                closeDemo();
            }
        }
        if (open) {
            ImGui::PushID(demo.get());
            demo->draw();
            if (view_.active() == demo.get() && ImGui::Button("Back to the scene")) closeDemo();
            ImGui::PopID();
            ImGui::TreePop();
        }
    }
}

} // namespace radiant::app
