// The patch renderer drawn offscreen on a hand-built field: one unit square cut into a row of
// patches whose radiosity rises left to right as B_k = c k^2 (grey). Expected pixels come from the
// documented formulas written out here (ACES fit, sRGB curve, viridis end colours, Gouraud: the
// display colours of the area-weighted vertex means interpolated linearly), never from the
// renderer's own helpers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

#include "app/window/Window.h"
#include "radiometry/common/Error.h"
#include "render/ColourScale.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"
#include "render/gl/Framebuffer.h"
#include "render/overlay/DepthVisibility.h"
#include "tests/gl/RequireDisplay.h"

using namespace radiant;
using render::ImageRgb8;
using radiant::test::requireDisplay;

namespace {

constexpr int kPatches = 5;
constexpr int kWidth = 480;
constexpr int kHeight = 360;
constexpr double kStep = 4.0;  // W/m^2: B_k = kStep k^2

double radiosityOf(int k) { return kStep * k * k; }

/// One grey surface, the unit square in z = 0 facing +z, cut into kPatches columns. As a grid face
/// it is drawn as one light-mapped quad; `asGrid` false gives the face a fifth corner, mid-way along
/// its bottom edge (the same square), which no grid has: its patches are drawn as triangles.
struct Field {
    Scene scene;
    PatchMesh mesh;
    std::vector<Rgb> radiosity;

    explicit Field(const Material& material = {"grey", Rgb(0.5), ExitanceRgb{}}, bool asGrid = true) {
        scene.name = "test field";
        scene.materials.push_back(material);
        Face face{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1}, 1.0};
        if (!asGrid) face.vertices.insert(face.vertices.begin() + 1, glm::dvec3{0.5, 0, 0});
        scene.surfaces.push_back({"square", 0, {face}, "test"});
        for (int i = 0; i <= kPatches; ++i) {
            mesh.vertices.emplace_back(static_cast<double>(i) / kPatches, 0.0, 0.0);
            mesh.vertices.emplace_back(static_cast<double>(i) / kPatches, 1.0, 0.0);
        }
        for (std::uint32_t k = 0; k < kPatches; ++k) {
            Patch patch;
            patch.corners = {2 * k, 2 * k + 2, 2 * k + 3, 2 * k + 1};
            patch.cornerCount = 4;
            patch.area = 1.0 / kPatches;
            patch.centroid = {(k + 0.5) / kPatches, 0.5, 0.0};
            mesh.patches.push_back(patch);
            radiosity.emplace_back(radiosityOf(static_cast<int>(k)));
        }
        mesh.surfaceFirstPatch = {0, kPatches};
    }
};

render::Camera frontCamera() {
    render::Camera camera;
    camera.eye = {0.5, 0.5, 1.5};
    camera.forward = {0, 0, -1};
    camera.up = {0, 1, 0};
    return camera;
}

/// Pixel position of a point of the square.
glm::dvec2 pixelOf(double x, double y) {
    const glm::dvec3 p = render::projectToPixel(frontCamera(), {0, 0, kWidth, kHeight}, {x, y, 0.0});
    return {p.x, p.y};
}

glm::dvec3 pixelAt(const ImageRgb8& image, double x, double y) {
    const glm::dvec2 p = pixelOf(x, y);
    const glm::u8vec3 c = image.at(static_cast<int>(p.x), static_cast<int>(p.y));
    return glm::dvec3(c);
}

// The documented display formulas, independently written.
double aces(double x) { return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }
double srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }
double toneMapped255(double radiosity, double exposureScale) { return 255.0 * srgb(aces(radiosity * exposureScale)); }

/// Exposure 0 puts the area-weighted mean luminance of the lit patches at tone-curve input 0.35.
double expectedExposureScale(double stops) {
    double sum = 0;
    int lit = 0;
    for (int k = 0; k < kPatches; ++k)
        if (radiosityOf(k) > 0) {
            sum += radiosityOf(k);
            ++lit;
        }
    return std::exp2(stops) * 0.35 / (sum / lit);
}

/// Gouraud oracle: vertex radiosity is the mean of the (equal-area) adjacent patches; each vertex's
/// display colour is interpolated linearly in x between the patch's left and right edges.
double smoothPixelAt(double x, double exposureScale) {
    const int k = std::min(static_cast<int>(x * kPatches), kPatches - 1);
    const double left = k == 0 ? radiosityOf(0) : (radiosityOf(k - 1) + radiosityOf(k)) / 2;
    const double right = k == kPatches - 1 ? radiosityOf(k) : (radiosityOf(k) + radiosityOf(k + 1)) / 2;
    const double f = x * kPatches - k;
    return toneMapped255(left, exposureScale) * (1 - f) + toneMapped255(right, exposureScale) * f;
}

struct Rig {
    app::Window window{{64, 64, "patch renderer test", false, false}};
    std::unique_ptr<render::PatchRenderer> renderer = std::make_unique<render::PatchRenderer>();
    Field field;

    explicit Rig(bool asGrid = true) : field({"grey", Rgb(0.5), ExitanceRgb{}}, asGrid) {
        renderer->setMesh(field.scene, field.mesh, 1);
        renderer->setRadiosity(field.radiosity, 1, -1);
    }
    ~Rig() { renderer.reset(); }  // GL objects die while the context lives

    ImageRgb8 draw(const render::DisplaySettings& settings) {
        renderer->setSettings(settings);
        renderer->prepare();
        return render::renderOffscreen(*renderer, frontCamera(), kWidth, kHeight, {0, 0, 0});
    }
};

render::DisplaySettings plain() {
    render::DisplaySettings settings;
    settings.highlightShooter = false;
    return settings;
}

} // namespace

TEST_SUITE("gl display") {

TEST_CASE("flat tone-mapped patches show the ACES-fitted, sRGB-encoded radiosity and rise left to right") {
    requireDisplay();
    Rig rig;
    for (const float stops : {0.0f, -1.5f, 2.0f}) {
        render::DisplaySettings settings = plain();
        settings.shading = render::Shading::Flat;
        settings.exposureStops = stops;
        const ImageRgb8 image = rig.draw(settings);
        const double scale = expectedExposureScale(stops);
        double previous = -1;
        for (int k = 0; k < kPatches; ++k) {
            const double x = (k + 0.5) / kPatches;
            const glm::dvec3 pixel = pixelAt(image, x, 0.5);
            const double expected = toneMapped255(radiosityOf(k), scale);
            INFO("stops ", stops, ", patch ", k, ": B = ", radiosityOf(k), " W/m^2, expected ", expected, ", got (",
                 pixel.x, ", ", pixel.y, ", ", pixel.z, ")");
            CHECK(std::abs(pixel.x - expected) <= 2.0);
            CHECK(std::abs(pixel.y - expected) <= 2.0);
            CHECK(std::abs(pixel.z - expected) <= 2.0);
            CHECK(pixel.y > previous);  // brighter where B is larger
            previous = pixel.y;
        }
    }
}

TEST_CASE("smooth shading interpolates the area-weighted vertex means, and flat shading jumps at patch edges") {
    requireDisplay();
    Rig rig;
    render::DisplaySettings settings = plain();
    settings.exposureStops = -2.0f;  // keep the brightest patch off the tone curve's shoulder
    const double scale = expectedExposureScale(-2.0);
    settings.shading = render::Shading::Smooth;
    const ImageRgb8 smooth = rig.draw(settings);
    settings.shading = render::Shading::Flat;
    const ImageRgb8 flat = rig.draw(settings);

    for (const double x : {0.1, 0.3, 0.45, 0.5, 0.7, 0.77, 0.9}) {
        const double expected = smoothPixelAt(x, scale);
        const double got = pixelAt(smooth, x, 0.37).y;
        INFO("x = ", x, ": expected ", expected, ", got ", got);
        CHECK(std::abs(got - expected) <= 3.0);
    }
    // Either side of the edge between patches 2 and 3 (x = 0.6): a step in flat, continuous in smooth.
    const double flatJump = pixelAt(flat, 0.61, 0.5).y - pixelAt(flat, 0.59, 0.5).y;
    const double smoothJump = pixelAt(smooth, 0.61, 0.5).y - pixelAt(smooth, 0.59, 0.5).y;
    const double expectedFlatJump = toneMapped255(radiosityOf(3), scale) - toneMapped255(radiosityOf(2), scale);
    CHECK(flatJump == doctest::Approx(expectedFlatJump).epsilon(0.1).scale(0));
    CHECK(std::abs(smoothJump) < 0.25 * flatJump);
}

TEST_CASE("patches drawn as triangles (no grid face) show each patch's own radiosity flat and the vertex means smooth") {
    requireDisplay();
    Rig rig(false);
    REQUIRE(rig.renderer->model().grids().grids.empty());  // else this draws the light map, not triangles
    render::DisplaySettings settings = plain();
    settings.exposureStops = -2.0f;
    const double scale = expectedExposureScale(-2.0);
    settings.shading = render::Shading::Flat;
    const ImageRgb8 flat = rig.draw(settings);
    for (int k = 0; k < kPatches; ++k)
        for (const double y : {0.2, 0.5, 0.8}) {  // both triangles of the patch's fan, and its diagonal
            const double x = (k + 0.5) / kPatches;
            const glm::dvec3 pixel = pixelAt(flat, x, y);
            const double expected = toneMapped255(radiosityOf(k), scale);
            INFO("patch ", k, " at y = ", y, ": expected ", expected, ", got (", pixel.x, ", ", pixel.y, ", ", pixel.z, ")");
            CHECK(std::abs(pixel.x - expected) <= 2.0);
            CHECK(std::abs(pixel.y - expected) <= 2.0);
            CHECK(std::abs(pixel.z - expected) <= 2.0);
        }
    settings.shading = render::Shading::Smooth;
    const ImageRgb8 smooth = rig.draw(settings);
    for (const double x : {0.1, 0.3, 0.45, 0.5, 0.7, 0.77, 0.9})
        for (const double y : {0.2, 0.8}) {
            const double expected = smoothPixelAt(x, scale);
            const double got = pixelAt(smooth, x, y).y;
            INFO("x = ", x, ", y = ", y, ": expected ", expected, ", got ", got);
            CHECK(std::abs(got - expected) <= 3.0);
        }
}

TEST_CASE("patches drawn as triangles keep their colours under the wireframe and the shooter's tint, as a grid face does") {
    requireDisplay();
    Rig triangles(false);
    // The grid face in the same context (GL objects belong to the context they were made in);
    // destroyed before the rig's window.
    Field gridField;
    render::PatchRenderer grid;
    grid.setMesh(gridField.scene, gridField.mesh, 1);
    REQUIRE(triangles.renderer->model().grids().grids.empty());
    REQUIRE(grid.model().grids().grids.size() == 1);
    render::DisplaySettings settings = plain();
    settings.shading = render::Shading::Flat;
    const ImageRgb8 bare = triangles.draw(settings);
    // The wireframe draws every patch with its edges (the unindexed triangles): inside the patches
    // (off the hidden diagonals) the colours are the indexed draw's.
    settings.wireframe = true;
    const ImageRgb8 wired = triangles.draw(settings);
    for (int k = 0; k < kPatches; ++k) CHECK(pixelAt(wired, (k + 0.3) / kPatches, 0.5) == pixelAt(bare, (k + 0.3) / kPatches, 0.5));
    // A new solution with a shooter: its tint and outline are redrawn over it from the unindexed
    // triangles, whose colours must be the new solution's.
    settings.wireframe = false;
    settings.highlightShooter = true;
    std::vector<Rgb> radiosity = triangles.field.radiosity;
    for (Rgb& b : radiosity) b = b * 0.5 + Rgb(3.0);
    triangles.renderer->setRadiosity(radiosity, 2, 2);
    grid.setRadiosity(radiosity, 2, 2);
    const ImageRgb8 fromTriangles = triangles.draw(settings);
    grid.setSettings(settings);
    grid.prepare();
    const ImageRgb8 fromGrid = render::renderOffscreen(grid, frontCamera(), kWidth, kHeight, {0, 0, 0});
    for (int k = 0; k < kPatches; ++k) {
        const glm::dvec3 a = pixelAt(fromTriangles, (k + 0.3) / kPatches, 0.5), b = pixelAt(fromGrid, (k + 0.3) / kPatches, 0.5);
        INFO("patch ", k, ": triangles (", a.x, ", ", a.y, ", ", a.z, "), grid (", b.x, ", ", b.y, ", ", b.z, ")");
        CHECK(glm::length(a - b) <= 2.0);
    }
    const glm::dvec3 shooter = pixelAt(fromTriangles, 0.5, 0.5);
    CHECK(shooter.x > shooter.z + 20);  // tinted orange
    const glm::dvec3 outlined = pixelAt(fromTriangles, 0.4 + 1.0 / kWidth, 0.5);
    CHECK(outlined.x > outlined.z + 100);
}

TEST_CASE("false colour maps zero to viridis' first colour and the range maximum to its last") {
    requireDisplay();
    Rig rig;
    render::DisplaySettings settings = plain();
    settings.shading = render::Shading::Flat;
    settings.colourMode = render::ColourMode::FalseColour;
    settings.falseColourMaxW_m2 = static_cast<float>(3 * radiosityOf(kPatches - 1));  // total over bands
    for (const bool log : {false, true}) {
        settings.logScale = log;
        const ImageRgb8 image = rig.draw(settings);
        const glm::dvec3 top = pixelAt(image, (kPatches - 0.5) / kPatches, 0.5);
        const glm::dvec3 bottom = pixelAt(image, 0.5 / kPatches, 0.5);
        INFO("log ", log, ": top (", top.x, ", ", top.y, ", ", top.z, "), bottom (", bottom.x, ", ", bottom.y, ", ",
             bottom.z, ")");
        CHECK(glm::all(glm::lessThanEqual(glm::abs(top - glm::dvec3(253, 231, 37)), glm::dvec3(2.0))));
        CHECK(glm::all(glm::lessThanEqual(glm::abs(bottom - glm::dvec3(68, 1, 84)), glm::dvec3(2.0))));
    }
    // Half the maximum on a linear scale: between viridis 4/8 (33, 145, 140) and 5/8 at t = 0.5 exactly 4/8.
    settings.logScale = false;
    settings.falseColourMaxW_m2 = static_cast<float>(2 * 3 * radiosityOf(2));
    const glm::dvec3 middle = pixelAt(rig.draw(settings), 2.5 / kPatches, 0.5);
    CHECK(glm::all(glm::lessThanEqual(glm::abs(middle - glm::dvec3(33, 145, 140)), glm::dvec3(2.0))));
}

TEST_CASE("radiosity is uploaded only when its generation changes, and a wrong size is refused") {
    requireDisplay();
    Rig rig;
    CHECK(rig.renderer->radiosityUploads() == 1);
    rig.renderer->setRadiosity(rig.field.radiosity, 1, -1);
    CHECK(rig.renderer->radiosityUploads() == 1);
    rig.renderer->setRadiosity(rig.field.radiosity, 2, 3);
    CHECK(rig.renderer->radiosityUploads() == 2);
    rig.renderer->setMesh(rig.field.scene, rig.field.mesh, 1);  // same mesh generation: kept
    CHECK(rig.renderer->hasRadiosity());
    const std::vector<Rgb> tooShort(kPatches - 1, Rgb(1.0));
    CHECK_THROWS_AS(rig.renderer->setRadiosity(tooShort, 3, -1), RadiantError);
}

TEST_CASE("the shooter's outline and the wireframe darken or colour patch edges only") {
    requireDisplay();
    Rig rig;
    rig.renderer->setRadiosity(rig.field.radiosity, 2, 2);
    render::DisplaySettings settings = plain();
    settings.shading = render::Shading::Flat;
    const ImageRgb8 bare = rig.draw(settings);
    settings.wireframe = true;
    const ImageRgb8 wired = rig.draw(settings);
    // On the edge x = 0.4 the wireframe darkens; inside the patch (and on the quad's hidden diagonal,
    // which passes through the centre) it does not.
    const glm::dvec2 edge = pixelOf(0.4, 0.5);
    const double edgeBare = glm::dvec3(bare.at(static_cast<int>(edge.x), static_cast<int>(edge.y))).y;
    const double edgeWired = glm::dvec3(wired.at(static_cast<int>(edge.x), static_cast<int>(edge.y))).y;
    CHECK(edgeWired < edgeBare - 10);
    CHECK(pixelAt(wired, 0.5, 0.5).y == doctest::Approx(pixelAt(bare, 0.5, 0.5).y).epsilon(0.02).scale(0));

    settings.wireframe = false;
    settings.highlightShooter = true;
    const ImageRgb8 highlighted = rig.draw(settings);
    const glm::dvec3 shooter = pixelAt(highlighted, 0.5, 0.5), plainShooter = pixelAt(bare, 0.5, 0.5);
    CHECK(shooter.x > shooter.z + 20);  // tinted orange
    CHECK(pixelAt(highlighted, 0.9, 0.5) == pixelAt(bare, 0.9, 0.5));  // unchanged patch, not the shooter
    CHECK(plainShooter.x == doctest::Approx(plainShooter.z).epsilon(0.02).scale(0));  // grey before
    // The outline runs along the shooter's own edges (x = 0.4 just inside), nowhere else.
    const glm::dvec3 outlined = pixelAt(highlighted, 0.4 + 1.0 / kWidth, 0.5);
    INFO("shooter's edge: (" << outlined.x << ", " << outlined.y << ", " << outlined.z << ")");
    CHECK(outlined.x > outlined.z + 100);
    CHECK(pixelAt(highlighted, 0.8 + 1.0 / kWidth, 0.5) == pixelAt(bare, 0.8 + 1.0 / kWidth, 0.5));
}

TEST_CASE("a point behind a nearer surface is hidden in the depth buffer, a point on the front surface is not") {
    requireDisplay();
    // The field at z = 0 and, in front of its left half, a blind at z = 0.3.
    Field field;
    field.scene.surfaces.push_back({"blind", 0, {Face{{{0, 0, 0.3}, {0.5, 0, 0.3}, {0.5, 1, 0.3}, {0, 1, 0.3}}, {0, 0, 1}, 0.5}}, "test"});
    const auto corner = static_cast<std::uint32_t>(field.mesh.vertices.size());
    for (const glm::dvec3& v : {glm::dvec3(0, 0, 0.3), glm::dvec3(0.5, 0, 0.3), glm::dvec3(0.5, 1, 0.3), glm::dvec3(0, 1, 0.3)})
        field.mesh.vertices.push_back(v);
    Patch blind;
    blind.surface = 1;
    blind.corners = {corner, corner + 1, corner + 2, corner + 3};
    blind.cornerCount = 4;
    blind.area = 0.5;
    blind.centroid = {0.25, 0.5, 0.3};
    field.mesh.patches.push_back(blind);
    field.mesh.surfaceFirstPatch = {0, kPatches, kPatches + 1};
    field.radiosity.emplace_back(1.0);

    app::Window window{{64, 64, "depth test", false, false}};
    render::PatchRenderer renderer;
    renderer.setMesh(field.scene, field.mesh, 1);
    renderer.setRadiosity(field.radiosity, 1);
    const render::gl::Framebuffer target(kWidth, kHeight);
    target.bindForDrawing();
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const render::Viewport viewport{0, 0, kWidth, kHeight};
    renderer.prepare();
    renderer.draw(frontCamera(), viewport.aspect());
    CHECK(render::visibleInDepthBuffer(frontCamera(), viewport, kHeight, {0.75, 0.5, 0.0}));       // open
    CHECK_FALSE(render::visibleInDepthBuffer(frontCamera(), viewport, kHeight, {0.25, 0.5, 0.0}));  // behind
    CHECK(render::visibleInDepthBuffer(frontCamera(), viewport, kHeight, {0.25, 0.5, 0.3}));        // on the blind
    CHECK_FALSE(render::visibleInDepthBuffer(frontCamera(), viewport, kHeight, {0.75, 0.5, 3.0}));  // behind the eye
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // TEST_SUITE
