// The rule by which a mesh vertex averages the patches meeting at it (OpenFirstMean.h): covered
// patches count only where no open one meets. Checked on the accumulator itself and on a hand-made
// 2 x 2 grid of unit squares through all three users (the probe's vertexRadiosity and
// interpolateRadiosity, the display's smoothRadiosity), against means worked out by hand.
#include <doctest/doctest.h>

#include <vector>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/OpenFirstMean.h"
#include "radiometry/probe/RadiosityInterpolation.h"
#include "render/display/SmoothingGroups.h"
#include "tests/support/Relative.h"

using namespace radiant;
using radiant::test::relativeTo;

TEST_CASE("a vertex takes the area-weighted mean of the open patches meeting there, the covered ones only where no open one does") {
    OpenFirstMean openAndCovered;
    openAndCovered.add(Rgb(2.0), 0.5, false);
    openAndCovered.add(Rgb(2.0), 1.5, false);
    openAndCovered.add(Rgb(0.0), 4.0, true);
    CHECK(openAndCovered.mean().x == relativeTo(2.0, 1e-15));

    // Open values 1 and 4 with weights 3 and 1: (3 + 4) / 4, whatever the covered patch holds.
    OpenFirstMean weighted;
    weighted.add(Rgb(1.0, 10.0, 100.0), 3.0, false);
    weighted.add(Rgb(4.0, 40.0, 400.0), 1.0, false);
    weighted.add(Rgb(1000.0), 100.0, true);
    CHECK(weighted.mean().x == relativeTo(1.75, 1e-15));
    CHECK(weighted.mean().y == relativeTo(17.5, 1e-15));
    CHECK(weighted.mean().z == relativeTo(175.0, 1e-15));

    // Only covered patches (a vertex inside a block's footprint): their own weighted mean, (1 + 12) / 4.
    OpenFirstMean onlyCovered;
    onlyCovered.add(Rgb(1.0), 1.0, true);
    onlyCovered.add(Rgb(4.0), 3.0, true);
    CHECK(onlyCovered.mean().x == relativeTo(3.25, 1e-15));

    CHECK(OpenFirstMean{}.mean() == Rgb(0.0));  // a vertex no patch uses
}

TEST_CASE("the probe's vertex values and interpolation and the display's smoothing share the open-first rule") {
    // Vertices (i, j) at index 3 j + i, i, j in 0..2; four unit squares, the upper right one covered.
    PatchMesh mesh;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) mesh.vertices.emplace_back(i, j, 0);
    const auto square = [&](std::uint32_t lowerLeft, bool covered) {
        Patch patch;
        patch.corners = {lowerLeft, lowerLeft + 1, lowerLeft + 4, lowerLeft + 3};
        patch.cornerCount = 4;
        patch.centroid = mesh.vertices[lowerLeft] + glm::dvec3(0.5, 0.5, 0);
        patch.area = 1;
        patch.covered = covered;
        mesh.patches.push_back(patch);
    };
    square(0, false);
    square(1, false);
    square(3, false);
    square(4, true);
    mesh.surfaceFirstPatch = {0, 4};
    const std::vector<Rgb> b{Rgb(1.0), Rgb(2.0), Rgb(3.0), Rgb(0.6)};

    // Centre (1, 1): the three open squares, (1 + 2 + 3) / 3 (all four would give 1.65). (2, 1) and
    // (1, 2): the open neighbour alone. (2, 2): the covered square alone.
    const std::vector<Rgb> atVertex = vertexRadiosity(mesh, b);
    CHECK(atVertex[4].x == relativeTo(2.0, 1e-15));
    CHECK(atVertex[5].x == relativeTo(2.0, 1e-15));
    CHECK(atVertex[7].x == relativeTo(3.0, 1e-15));
    CHECK(atVertex[8].x == relativeTo(0.6, 1e-15));
    CHECK(atVertex[0].x == relativeTo(1.0, 1e-15));

    // The covered square's centre: bilinear, a quarter of each corner, (2 + 2 + 3 + 0.6) / 4.
    CHECK(interpolateRadiosity(mesh, b, 3, glm::dvec3(1.5, 1.5, 0)).x == relativeTo(1.9, 1e-14));
    CHECK(interpolateRadiosity(mesh, 3, glm::dvec3(1.5, 1.5, 0), atVertex).x == relativeTo(1.9, 1e-14));

    const render::SmoothingGroups groups = render::findSmoothingGroups(mesh);
    std::vector<Rgb> smoothed;
    render::smoothRadiosity(groups, std::vector<double>(4, 1.0), b, smoothed);
    for (std::size_t p = 0; p < mesh.patches.size(); ++p)
        for (std::size_t c = 0; c < 4; ++c)
            CHECK(smoothed[groups.cornerVertex[p][c]].x == relativeTo(atVertex[mesh.patches[p].corners[c]].x, 1e-15));
}
