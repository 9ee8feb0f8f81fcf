// The lecture demos' labels (app/ui/LabelLayout.h): none covers another, each moves as little as it can.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "app/ui/LabelLayout.h"

using radiant::app::ui::LabelBox;
using radiant::app::ui::separateLabels;

namespace {

bool anyOverlap(const std::vector<LabelBox>& boxes, float gap) {
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            const LabelBox& a = boxes[i];
            const LabelBox& b = boxes[j];
            if (a.x < b.x + b.width + gap && b.x < a.x + a.width + gap && a.y < b.y + b.height + gap &&
                b.y < a.y + a.height + gap)
                return true;
        }
    return false;
}

} // namespace

TEST_SUITE("label layout") {

TEST_CASE("a readout over another moves just clear of it, the earlier one stays") {
    // The source's two-line label, then the cursor's readout asked for 10 units lower, overlapping it.
    std::vector<LabelBox> boxes{{100, 200, 300, 40}, {150, 210, 200, 40}};
    separateLabels(boxes, 0, 1000, 4);
    CHECK(boxes[0].y == 200);
    CHECK_FALSE(anyOverlap(boxes, 4));
    CHECK(boxes[1].y == 244);  // just below: 34 down rather than 54 up
}

TEST_CASE("pinned labels keep their places even when they touch, and others go around them") {
    // Tick labels a little closer than their height (a colour bar's), and a readout asked on top of them.
    std::vector<LabelBox> boxes{{10, 100, 20, 22, true}, {10, 120, 20, 22, true}, {10, 140, 20, 22, true},
                                {0, 125, 120, 30}};
    separateLabels(boxes, 0, 1000, 2);
    CHECK(boxes[0].y == 100);
    CHECK(boxes[1].y == 120);
    CHECK(boxes[2].y == 140);
    const LabelBox& readout = boxes[3];
    CHECK((readout.y + readout.height + 2 <= 100 || readout.y >= 162 + 2));
}

TEST_CASE("labels stay inside the view, and disjoint ones do not move") {
    std::vector<LabelBox> boxes{{0, 950, 100, 40}, {0, 960, 100, 40}, {500, 10, 100, 40}};
    separateLabels(boxes, 0, 1000, 4);
    CHECK(boxes[0].y == 950);
    CHECK(boxes[1].y == 950 - 40 - 4);  // below would leave the view: above instead
    CHECK(boxes[2].y == 10);
    CHECK_FALSE(anyOverlap(boxes, 4));
}

TEST_CASE("a crowd of equal labels at one spot ends up stacked, none covering another") {
    std::vector<LabelBox> boxes(6, LabelBox{200, 500, 150, 30});
    separateLabels(boxes, 0, 1000, 3);
    CHECK_FALSE(anyOverlap(boxes, 3));
    for (const LabelBox& b : boxes) CHECK(std::abs(b.y - 500) <= 3 * 33 + 1e-3f);  // three above, two below at most
}

} // TEST_SUITE
