#pragma once
// The open lesson step's title and caption, drawn in a band under the 3D view's picture (ImGui).
#include "app/lessons/LessonPlayer.h"
#include "render/camera/Camera.h"

namespace radiant::app {

/// Across the bottom of `view` (ImGui units), during an ImGui frame. Returns the band's height
/// (the caption and a gap either side of it, ImGui units), which the caller keeps the picture out of; 0
/// when no lesson is open or it is a session.
float drawLessonCaption(const LessonPlayer& lessons, const render::Viewport& view);

} // namespace radiant::app
