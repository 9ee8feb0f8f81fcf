#include "app/ui/LabelLayout.h"

#include <cmath>
#include <limits>

namespace radiant::app::ui {
namespace {

bool overlap(const LabelBox& a, const LabelBox& b, float gap) {
    return a.x < b.x + b.width + gap && b.x < a.x + a.width + gap && a.y < b.y + b.height + gap &&
           b.y < a.y + a.height + gap;
}

bool clearOf(const LabelBox& box, const std::vector<const LabelBox*>& placed, float gap) {
    for (const LabelBox* other : placed)
        if (overlap(box, *other, gap)) return false;
    return true;
}

} // namespace

void separateLabels(std::vector<LabelBox>& boxes, float top, float bottom, float gap) {
    std::vector<const LabelBox*> placed;
    for (const LabelBox& box : boxes)
        if (box.pinned) placed.push_back(&box);
    for (LabelBox& box : boxes) {
        if (box.pinned) continue;
        // The free places nearest the asked one lie where the box is, or just above or just below
        // some box already placed: try those, keep the nearest free one.
        std::vector<float> candidates{box.y};
        for (const LabelBox* other : placed) {
            candidates.push_back(other->y + other->height + gap);
            candidates.push_back(other->y - box.height - gap);
        }
        float best = box.y, bestDistance = std::numeric_limits<float>::infinity();
        for (const float y : candidates) {
            if (y < top || y + box.height > bottom) continue;
            LabelBox moved = box;
            moved.y = y;
            const float distance = std::abs(y - box.y);
            if (distance < bestDistance && clearOf(moved, placed, gap)) {
                best = y;
                bestDistance = distance;
            }
        }
        box.y = best;
        placed.push_back(&box);
    }
}

} // namespace radiant::app::ui
