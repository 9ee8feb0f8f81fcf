// The false-colour legend, GL-free: ticks at 1-2-5 steps (linear) and 1, 2, 5 per decade (log), their
// labels, the isoline coordinate the shader mirrors (an integer exactly at each tick), and the legend
// painted into `radiant render --false-colour` pictures (bar ends in viridis' end colours, in the corner).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "render/ColourScale.h"
#include "render/display/LegendImage.h"
#include "tests/support/Relative.h"

using namespace radiant;
using test::relativeTo;

namespace {

/// The mantissa of a positive value in [1, 10).
double mantissa(double value) { return value / std::pow(10.0, std::floor(std::log10(value) + 1e-12)); }

bool isOneTwoFive(double value) {
    const double m = mantissa(value);
    return std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9 || std::abs(m - 10) < 1e-9;
}

} // namespace

TEST_CASE("legend: linear ticks step by 1, 2 or 5 x 10^k from 0, four to ten of them inside the range") {
    for (const double top : {0.37, 1.0, 3.0, 7.5, 37.0, 120.0, 999.0, 2.5e4}) {
        const render::ColourLegend legend = render::makeLegend(top, false, 3);
        INFO("max " << top);
        REQUIRE(legend.ticksW_m2.size() >= 4);
        CHECK(legend.ticksW_m2.size() <= 10);
        const double step = legend.linearStepW_m2();
        CHECK(isOneTwoFive(step));
        for (std::size_t i = 0; i < legend.ticksW_m2.size(); ++i) {
            if (i == 0) CHECK(legend.ticksW_m2[i] == 0.0);
            else CHECK(legend.ticksW_m2[i] == relativeTo(static_cast<double>(i) * step, 1e-12));
            CHECK(legend.ticksW_m2[i] <= top * (1 + 1e-12));
            // The isoline coordinate is an integer exactly at each tick.
            const double u = legend.isolineCoordinate(legend.position(legend.ticksW_m2[i]));
            CHECK(std::abs(u - std::round(u)) < 1e-9);
        }
    }
}

TEST_CASE("legend: log ticks are 1, 2 and 5 of every decade in the range, and isolines fall on each") {
    const render::ColourLegend legend = render::makeLegend(250.0, true, 3);  // 0.25 .. 250
    const std::vector<double> expected{0.5, 1, 2, 5, 10, 20, 50, 100, 200};
    REQUIRE(legend.ticksW_m2.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) CHECK(legend.ticksW_m2[i] == relativeTo(expected[i], 1e-12));

    // Ends that land on a tick are kept: 1 .. 1000 has 1, 2, 5, ..., 500, 1000.
    const render::ColourLegend decades = render::makeLegend(1000.0, true, 3);
    REQUIRE(decades.ticksW_m2.size() == 10);
    CHECK(decades.ticksW_m2.front() == relativeTo(1.0, 1e-12));
    CHECK(decades.ticksW_m2.back() == relativeTo(1000.0, 1e-12));

    // Integer at every tick, consecutive ticks one apart, and rising in between.
    double previous = -1e9;
    for (std::size_t i = 0; i < legend.ticksW_m2.size(); ++i) {
        const double u = legend.isolineCoordinate(legend.position(legend.ticksW_m2[i]));
        INFO("tick " << legend.ticksW_m2[i] << ": u " << u);
        CHECK(std::abs(u - std::round(u)) < 1e-9);
        if (i > 0) CHECK(u - previous == relativeTo(1.0, 1e-9));
        previous = u;
    }
    double last = legend.isolineCoordinate(0.0);
    for (int k = 1; k <= 200; ++k) {
        const double u = legend.isolineCoordinate(k / 200.0);
        CHECK(u > last);
        last = u;
    }
    // 3 (W/m^2) lies a third of the way from 2 to 5: u(3) - u(2) = 1/3.
    const double u2 = legend.isolineCoordinate(legend.position(2.0)), u3 = legend.isolineCoordinate(legend.position(3.0));
    CHECK(u3 - u2 == relativeTo(1.0 / 3.0, 1e-9));
}

TEST_CASE("legend: tick labels are short and exact, the title names the quantity and unit") {
    CHECK(render::formatLegendTick(0) == "0");
    CHECK(render::formatLegendTick(0.02) == "0.02");
    CHECK(render::formatLegendTick(500) == "500");
    CHECK(render::formatLegendTick(2e4) == "20k");
    CHECK(render::formatLegendTick(1e-5) == "1e-05");
    CHECK(render::legendTitle(render::makeLegend(10, false, 3)) == "radiosity, sum of R+G+B, W/m^2");
    CHECK(render::legendTitle(render::makeLegend(10, true, 3)) == "radiosity, sum of R+G+B, W/m^2, log");
}

TEST_CASE("legend in a picture: a bar from viridis' top colour to its bottom one in the top-right corner, with text") {
    render::ImageRgb8 image;
    image.width = 800;
    image.height = 500;
    image.pixels.assign(static_cast<std::size_t>(image.width * image.height * 3), 128);
    const render::ColourLegend legend = render::makeLegend(40.0, false, 3);
    render::paintLegend(image, legend);
    const render::LegendLayout l = render::layoutLegend(legend, image.width, image.height);

    REQUIRE(l.plateLeft > image.width / 2);
    REQUIRE(l.plateRight <= image.width);
    REQUIRE(l.barBottom - l.barTop >= image.height / 3);
    const auto near = [](glm::u8vec3 pixel, glm::dvec3 srgb) {
        const glm::dvec3 expected = srgb * 255.0;
        return std::abs(pixel.x - expected.x) <= 2 && std::abs(pixel.y - expected.y) <= 2 && std::abs(pixel.z - expected.z) <= 2;
    };
    const int x = (l.barLeft + l.barRight) / 2;
    CHECK(near(image.at(x, l.barTop), render::viridis(1.0)));
    CHECK(near(image.at(x, l.barBottom - 1), render::viridis(0.0)));
    CHECK(near(image.at(x, (l.barTop + l.barBottom - 1) / 2), render::viridis(0.5)));
    // Outside the plate the picture is untouched; on the plate, labels and title are light text.
    CHECK(image.at(l.plateLeft - 2, l.barTop) == glm::u8vec3(128));
    CHECK(image.at(10, 10) == glm::u8vec3(128));
    int light = 0;
    for (int y = l.plateTop; y < l.plateBottom; ++y)
        for (int xx = l.barRight; xx < l.plateRight; ++xx)
            if (image.at(xx, y).x > 200 && image.at(xx, y).z > 200) ++light;
    CHECK(light > 200);

    // A picture too small for it is left alone rather than half-painted.
    render::ImageRgb8 tiny;
    tiny.width = 40;
    tiny.height = 30;
    tiny.pixels.assign(40 * 30 * 3, 7);
    render::paintLegend(tiny, legend);
    for (const std::uint8_t v : tiny.pixels) REQUIRE(v == 7);
}
