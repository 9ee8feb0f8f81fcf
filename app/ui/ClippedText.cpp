#include "app/ui/ClippedText.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

namespace radiant::app::ui {
namespace {

// Sub-pixel rounding of item positions is not clipping.
constexpr float kTolerance = 0.5f;

void checkWindows(const ImGuiContext& g, std::vector<ClippedText>& found) {
    for (const ImGuiWindow* window : g.Windows) {
        // A window that scrolls sideways cuts nothing off; tooltips and popups size to their content.
        if (!window->Active || window->Hidden || window->ScrollbarX) continue;
        const float overflow = window->DC.CursorMaxPos.x - window->WorkRect.Max.x;
        if (overflow > kTolerance) found.push_back({std::string("window ") + window->Name, overflow});
    }
}

void checkTables(ImGuiContext& g, std::vector<ClippedText>& found) {
    for (int n = 0; n < g.Tables.GetMapSize(); ++n) {
        const ImGuiTable* table = g.Tables.TryGetMapData(n);
        if (table == nullptr || table->LastFrameActive != g.FrameCount) continue;
        for (int c = 0; c < table->ColumnsCount; ++c) {
            const ImGuiTableColumn& column = table->Columns[c];
            if (!column.IsEnabled) continue;
            const float contentRight = std::max({column.ContentMaxXFrozen, column.ContentMaxXUnfrozen,
                                                 column.ContentMaxXHeadersIdeal});
            const float overflow = contentRight - column.ClipRect.Max.x;
            if (overflow <= kTolerance) continue;
            const char* name = ImGui::TableGetColumnName(table, c);
            found.push_back({std::string("window ") + table->OuterWindow->Name + ", table column " +
                                 std::to_string(c) + (name && *name ? std::string(" '") + name + "'" : std::string()),
                             overflow});
        }
    }
}

} // namespace

std::vector<ClippedText> findClippedText() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    std::vector<ClippedText> found;
    checkWindows(g, found);
    checkTables(g, found);
    return found;
}

} // namespace radiant::app::ui
