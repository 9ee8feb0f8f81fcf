#include "app/panels/demos/LectureDemosPanel.h"

#include <imgui.h>

#include <cstring>

#include "app/panels/demos/LectureDemos.h"

namespace radiant::app {

LectureDemosPanel::LectureDemosPanel() {
    demos_.push_back(std::make_unique<PointSourceDemo>());
    demos_.push_back(std::make_unique<DiffuseEmitterDemo>());
    demos_.push_back(std::make_unique<SunDemo>());
    demos_.push_back(std::make_unique<SquareSolidAngleDemo>());
    demos_.push_back(std::make_unique<DodecahedronDemo>());
    demos_.push_back(std::make_unique<RadianceIrradianceDemo>());
}

void LectureDemosPanel::focus(const char* demoTitle) { focused_ = demoTitle; }

void LectureDemosPanel::draw() {
    for (const auto& demo : demos_) {
        // "Demo: point source over a plane" -> "point source over a plane" under this header.
        const char* name = demo->title();
        if (std::strncmp(name, "Demo: ", 6) == 0) name += 6;
        if (expandAll_) ImGui::SetNextItemOpen(true);
        else if (focused_) ImGui::SetNextItemOpen(std::strcmp(focused_, demo->title()) == 0 || std::strcmp(focused_, name) == 0);
        if (ImGui::TreeNodeEx(name, ImGuiTreeNodeFlags_SpanAvailWidth)) {
            ImGui::PushID(demo.get());
            demo->draw();
            ImGui::PopID();
            ImGui::TreePop();
        }
    }
    focused_ = nullptr;
    expandAll_ = false;
}

} // namespace radiant::app
