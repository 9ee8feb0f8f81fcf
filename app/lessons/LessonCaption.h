#pragma once
// The open lesson step's title and caption, drawn in the 3D view (ImGui).
#include "app/lessons/LessonPlayer.h"
#include "render/camera/Camera.h"

namespace radiant::app {

/// In `view` (ImGui units), during an ImGui frame; nothing when no lesson is open or it is a session.
void drawLessonCaption(const LessonPlayer& lessons, const render::Viewport& view);

} // namespace radiant::app
