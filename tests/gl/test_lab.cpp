// The real lab under Xvfb: the solve streams into the 3D view while frames keep coming, a click
// probes the scene like `radiant probe` does, and a materials edit recolours a wall without new
// form factors.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/Lab.h"
#include "app/solver/SolverThread.h"
#include "radiometry/units/Quantity.h"
#include "render/Screenshot.h"
#include "render/camera/Camera.h"
#include "tests/gl/FrameUntil.h"
#include "tests/gl/RequireDisplay.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;
namespace command = radiant::app::command;

using radiant::test::frameUntil;
using radiant::test::requireDisplay;

namespace {

constexpr double kCoarsePatchArea = 0.05;  // m^2: about a hundred patches, form factors in well under a second

LabOptions coarseCornell() {
    LabOptions options;
    options.scene = "cornell-box";
    options.width = 640;
    options.height = 480;
    options.showPanels = false;  // the 3D view fills the window
    options.vsync = false;
    options.maxPatchArea = kCoarsePatchArea;
    options.runOnStart = false;
    return options;
}

void waitForSolver(Lab& lab) {
    frameUntil(lab, [](const app::Snapshot& s) { return s.mesh && s.solverBuilds >= 1 && !s.running; });
}

double meanBrightness(const render::ImageRgb8& image) {
    double sum = 0;
    for (const std::uint8_t v : image.pixels) sum += v;
    return sum / static_cast<double>(image.pixels.size());
}

/// Mean colour (0..255 per channel) of a (2r+1)^2 block of pixels around `centre`.
glm::dvec3 meanColour(const render::ImageRgb8& image, const glm::dvec3& centre, int r = 4) {
    glm::dvec3 sum(0.0);
    int count = 0;
    const int cx = static_cast<int>(centre.x), cy = static_cast<int>(centre.y);
    for (int y = cy - r; y <= cy + r; ++y)
        for (int x = cx - r; x <= cx + r; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                   static_cast<std::size_t>(x)) * 3;
            sum += glm::dvec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
            ++count;
        }
    return sum / static_cast<double>(count);
}

std::string runCommand(const std::string& commandLine) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(commandLine.c_str(), "r"), pclose);
    REQUIRE(pipe);
    std::string out;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe.get())) out.append(buffer, n);
    return out;
}

void checkClose(const nlohmann::json& expected, const Rgb& actual, double relative, const char* what) {
    for (int band = 0; band < 3; ++band) {
        const double e = expected.at(static_cast<std::size_t>(band)).get<double>();
        INFO(what << " band " << band << ": radiant probe " << e << ", lab " << actual[band]);
        CHECK(std::abs(actual[band] - e) <= relative * std::abs(e) + 1e-9);
    }
}

} // namespace

TEST_SUITE("gl lab") {

TEST_CASE("the view brightens as the solve advances, and frames keep coming while it runs") {
    requireDisplay();
    Lab lab(coarseCornell());
    waitForSolver(lab);
    CHECK(lab.snapshot()->method == SolverMethod::Progressive);  // the default at a small mesh (DefaultMethod.h)
    // Gauss-Seidel's sweeps only add light; progressive refinement's picture starts bright (Cohen et
    // al.'s ambient term stands in for the unshot power) and may darken as the shots replace it.
    lab.send(command::SetMethod{SolverMethod::GaussSeidel});
    waitForSolver(lab);

    // A fixed false-colour range, so brightness follows radiosity (tone mapping adapts its exposure).
    lab.send(command::Step{1});
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 1; });
    double firstMax = 0;
    const app::Snapshot& first = *lab.snapshot();
    for (std::size_t p = 0; p < first.mesh->size(); ++p) {
        const Surface& surface = first.scene->surfaces[first.mesh->patches[p].surface];
        if (!first.scene->materials[surface.material].emits())
            firstMax = std::max(firstMax, first.radiosity[p].x + first.radiosity[p].y + first.radiosity[p].z);
    }
    REQUIRE(firstMax > 0);
    lab.display().colourMode = render::ColourMode::FalseColour;
    lab.display().falseColourMaxW_m2 = static_cast<float>(firstMax * 3.0);

    lab.send(command::Reset{});
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 0 && s.history.empty(); });
    const double emitted = meanBrightness(lab.frameAndCapture());
    double previous = emitted;
    for (const std::size_t iteration : {1u, 2u, 4u}) {
        lab.send(command::Step{iteration - lab.snapshot()->stats.iteration});
        frameUntil(lab, [&](const app::Snapshot& s) { return s.stats.iteration == iteration && !s.running; });
        const double brightness = meanBrightness(lab.frameAndCapture());
        INFO("iteration " << iteration << ": mean " << brightness << ", before " << previous);
        CHECK(brightness > previous);
        previous = brightness;
    }
    CHECK(previous > emitted + 2.0);  // clearly visible, not rounding noise

    // A long run: progressive refinement on a finer mesh, to a tolerance it needs many shots for.
    lab.send(command::Remesh{MeshingOptions{kCoarsePatchArea / 8}});
    lab.send(command::SetMethod{SolverMethod::Progressive});
    lab.send(command::SetTolerance{1e-14});
    lab.send(command::Run{});
    frameUntil(lab, [](const app::Snapshot& s) { return s.running && s.stats.iteration > 0; });
    const std::uint64_t framesBefore = lab.frameCount();
    const std::uint64_t generationBefore = lab.snapshot()->generation;
    std::uint64_t framesWhileRunning = 0;
    for (int i = 0; i < 40 && lab.snapshot()->running; ++i) {
        lab.frame();
        if (lab.snapshot()->running) ++framesWhileRunning;
    }
    INFO("iteration reached " << lab.snapshot()->stats.iteration);
    CHECK(framesWhileRunning >= 10);
    CHECK(lab.frameCount() >= framesBefore + framesWhileRunning);
    CHECK(lab.snapshot()->generation > generationBefore);  // the frames showed new solutions
    lab.send(command::Pause{});
}

TEST_CASE("a click on the floor probes the point as `radiant probe` does with the same solver settings") {
    requireDisplay();
    Lab lab(coarseCornell());
    // Both use the default method (progressive refinement at this mesh: DefaultMethod.h) and stop at
    // the first shot that leaves less unshot power than this; each is then within about tolerance /
    // (1 - rho_max) of the solution of the same form factors, so they agree to 1e-4.
    constexpr double kTolerance = 1e-7;
    constexpr double kAgreement = 1e-4;
    lab.send(command::SetTolerance{kTolerance});
    lab.send(command::Run{});
    waitForSolver(lab);
    frameUntil(lab, [](const app::Snapshot& s) { return !s.running && s.stats.iteration > 0; });
    REQUIRE(lab.snapshot()->stats.residual < kTolerance);

    const glm::dvec3 floorPoint{0.42, 0.0, 0.12};  // in front of the tall block, seen by the Cornell camera
    const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), floorPoint);
    REQUIRE(lab.clickAt({pixel.x, pixel.y}));
    const std::uint64_t solved = lab.snapshot()->generation;
    frameUntil(lab, [&](const app::Snapshot&) { return lab.probeGeneration() == solved && lab.probeReading(); });
    const ProbeReading reading = *lab.probeReading();
    const Scene& scene = *lab.snapshot()->scene;
    CHECK(scene.surfaces[reading.at.surface].name == "floor");
    CHECK(reading.at.point.x == doctest::Approx(floorPoint.x).epsilon(1e-3).scale(0));
    CHECK(reading.at.point.z == doctest::Approx(floorPoint.z).epsilon(1e-3).scale(0));
    CHECK(reading.normal.y == doctest::Approx(1.0).scale(0));

    char arguments[512];
    std::snprintf(arguments, sizeof arguments,
                  " probe cornell-box --point %.17g,%.17g,%.17g --normal %.17g,%.17g,%.17g"
                  " --max-patch-area %.17g --tolerance %.17g --json -",
                  reading.at.point.x, reading.at.point.y, reading.at.point.z, reading.normal.x, reading.normal.y,
                  reading.normal.z, kCoarsePatchArea, kTolerance);
    const std::string output = runCommand(std::string(RADIANT_BINARY) + arguments);
    INFO("radiant probe said: " << output);
    const nlohmann::json expected = nlohmann::json::parse(output);
    CHECK(expected.at("surface").get<std::string>() == "floor");
    checkClose(expected.at("radiosity_W_m2"), reading.radiosity.value(), kAgreement, "B");
    checkClose(expected.at("radiance_W_m2_sr"), reading.radiance.value(), kAgreement, "L");
    checkClose(expected.at("irradiance_W_m2"), reading.irradiance.value(), kAgreement, "E");
    REQUIRE(reading.target);
    const nlohmann::json& target = expected.at("target");
    CHECK(target.at("name").get<std::string>() == reading.target->name);
    // Geometry only: identical rays from the identical point.
    CHECK(reading.target->solidAngle.value() == doctest::Approx(target.at("solid_angle_sr").get<double>()).epsilon(1e-9).scale(0));
    CHECK(reading.target->formFactor == doctest::Approx(target.at("form_factor").get<double>()).epsilon(1e-9).scale(0));
}

TEST_CASE("a wall's reflectance edit recolours it without computing form factors again") {
    requireDisplay();
    Lab lab(coarseCornell());
    lab.send(command::SetTolerance{1e-5});
    lab.send(command::Run{});
    waitForSolver(lab);
    frameUntil(lab, [](const app::Snapshot& s) { return !s.running && s.stats.iteration > 0; });
    const std::uint64_t builds = lab.snapshot()->solverBuilds;
    const std::size_t rightWall = lab.snapshot()->scene->findSurface("right wall");
    REQUIRE(rightWall != Scene::npos);

    const glm::dvec3 wallPoint{0.0, 0.35, 0.40};  // the green wall, above both blocks
    const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), wallPoint);
    const glm::dvec3 before = meanColour(lab.frameAndCapture(), pixel);
    INFO("before: " << before.x << ", " << before.y << ", " << before.z);
    REQUIRE(before.y > before.x);  // green

    // Reflectance >= 1 is refused with a reason, and nothing is sent.
    CHECK_FALSE(lab.editMaterial(rightWall, Rgb(1.0, 0.1, 0.1), Rgb(0.0)).empty());
    CHECK(lab.editMaterial(rightWall, Rgb(0.63, 0.065, 0.05), Rgb(0.0)).empty());  // the red wall's material
    frameUntil(lab, [&](const app::Snapshot& s) {
        const Material& m = s.scene->materials[s.scene->surfaces[rightWall].material];
        return m.reflectance.x > 0.6 && !s.running && s.stats.residual < 1e-5;
    });
    const glm::dvec3 after = meanColour(lab.frameAndCapture(), pixel);
    INFO("after: " << after.x << ", " << after.y << ", " << after.z);
    CHECK(after.x > after.y + 20.0);  // red now
    CHECK(after.x > before.x + 20.0);
    CHECK(lab.snapshot()->solverBuilds == builds);
}

TEST_CASE("keyboard shortcuts drive the solve and the display") {
    requireDisplay();
    Lab lab(coarseCornell());
    waitForSolver(lab);
    lab.pressKey(GLFW_KEY_N);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 1 && !s.running; });
    lab.pressKey(GLFW_KEY_RIGHT);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 2 && !s.running; });
    lab.pressKey(GLFW_KEY_R);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 0 && s.history.empty(); });
    const auto mode = lab.display().colourMode;
    lab.pressKey(GLFW_KEY_F);
    CHECK(lab.display().colourMode != mode);
    const bool wire = lab.display().wireframe;
    lab.pressKey(GLFW_KEY_W);
    CHECK(lab.display().wireframe != wire);
    lab.pressKey(GLFW_KEY_SPACE);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration > 0; });
    lab.pressKey(GLFW_KEY_ESCAPE);
    CHECK(lab.shouldClose());
}

TEST_CASE("after a click on a panel widget, Space, N, R, F and F12 still act through the window's key callbacks") {
    requireDisplay();
    LabOptions options = coarseCornell();
    options.showPanels = true;
    options.width = 1600;
    options.height = 1000;
    Lab lab(options);
    waitForSolver(lab);

    // A widget in the sidebar: the first point down its middle that ImGui reports hovering an item.
    std::optional<glm::vec2> widget;
    for (float y = 30; y < 600 && !widget; y += 6) {
        lab.overrideMouse(glm::vec2{120, y});
        lab.frame();
        if (ImGui::IsAnyItemHovered()) widget = glm::vec2{120, y};
    }
    REQUIRE(widget);
    lab.overrideMouse(widget, true);
    lab.frame();
    CHECK(ImGui::IsAnyItemActive());  // the click landed on a widget
    lab.overrideMouse(widget, false);
    lab.frame();
    lab.frame();
    lab.overrideMouse(std::nullopt);
    CHECK_FALSE(ImGui::IsAnyItemActive());

    // Keys enter as GLFW delivers them: ImGui's key callback first, chaining to the lab's.
    GLFWwindow* window = glfwGetCurrentContext();
    REQUIRE(window);
    const GLFWkeyfun callbacks = glfwSetKeyCallback(window, nullptr);
    glfwSetKeyCallback(window, callbacks);
    const bool chained = callbacks != nullptr;
    REQUIRE(chained);
    const auto press = [&](int key) {
        callbacks(window, key, glfwGetKeyScancode(key), GLFW_PRESS, 0);
        lab.frame();
        callbacks(window, key, glfwGetKeyScancode(key), GLFW_RELEASE, 0);
        lab.frame();
    };
    press(GLFW_KEY_N);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 1 && !s.running; });
    press(GLFW_KEY_R);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration == 0 && s.history.empty(); });
    press(GLFW_KEY_SPACE);
    frameUntil(lab, [](const app::Snapshot& s) { return s.stats.iteration > 0; });
    const auto mode = lab.display().colourMode;
    press(GLFW_KEY_F);
    CHECK(lab.display().colourMode != mode);

    const auto directory = std::filesystem::temp_directory_path() / "radiant-test-keys";
    std::filesystem::create_directories(directory);
    const auto previous = std::filesystem::current_path();
    std::filesystem::current_path(directory);  // F12 saves into the working directory
    press(GLFW_KEY_F12);
    std::filesystem::current_path(previous);
    INFO("status: " << lab.statusMessage());
    CHECK(lab.statusMessage().rfind("saved ", 0) == 0);
    std::filesystem::remove_all(directory);
}

TEST_CASE("an idle, converged lab stops drawing until input arrives") {
    requireDisplay();
    Lab lab(coarseCornell());
    lab.send(command::Run{});
    waitForSolver(lab);
    frameUntil(lab, [](const app::Snapshot& s) { return !s.running && s.stats.iteration > 0; });
    // Input moments ago keeps frames coming; then the lab settles.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (lab.changing() && std::chrono::steady_clock::now() < deadline) lab.frame();
    REQUIRE_FALSE(lab.changing());
    const std::uint64_t frames = lab.frameCount();
    // Each call waits for an event or the timeout, then draws one frame. How long it waited is not
    // checked: under ctest -j another client's traffic on the shared Xvfb may wake it early.
    for (int i = 0; i < 3; ++i) lab.frameWhenNeeded(0.2);
    CHECK(lab.frameCount() == frames + 3);
    const std::size_t iterations = lab.snapshot()->stats.iteration;
    lab.send(command::Step{1});  // a command makes a new snapshot: frames come again
    const auto stepped = [&](const app::Snapshot& s) { return s.stats.iteration == iterations + 1; };
    frameUntil(lab, stepped);
    CHECK(lab.frameCount() > frames + 3);
}

} // TEST_SUITE

TEST_CASE("a click with hierarchical radiosity singles out the links the point gathers through") {
    requireDisplay();
    LabOptions options = coarseCornell();
    options.maxPatchArea = 0.01;
    options.showPanels = true;
    options.width = 1600;
    options.height = 1000;
    Lab lab(options);
    lab.send(command::SetMethod{SolverMethod::Hierarchical});
    lab.send(command::Step{6});
    frameUntil(lab, [](const app::Snapshot& s) { return s.linkSegments && s.stats.iteration >= 6 && !s.running; });
    CHECK_FALSE(lab.snapshot()->focusLinkSegments);  // nothing picked yet
    lab.display().showLinks = true;

    const glm::dvec3 floorPoint{0.42, 0.0, 0.12};  // in front of the tall block
    const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), floorPoint);
    REQUIRE(lab.clickAt({pixel.x, pixel.y}));
    frameUntil(lab, [](const app::Snapshot& s) { return s.focusLinkSegments && !s.focusLinkSegments->empty(); });
    const app::Snapshot& focused = *lab.snapshot();
    CHECK(focused.focusLevels >= 1);
    // Every one starts at the picked point, on the floor.
    for (std::size_t i = 0; i < focused.focusLinkSegments->size(); i += 2) {
        const glm::vec3 from = (*focused.focusLinkSegments)[i];
        CHECK(std::abs(from.y) < 1e-5f);
        CHECK(from.x == doctest::Approx(floorPoint.x).epsilon(1e-3).scale(0));
        CHECK(from.z == doctest::Approx(floorPoint.z).epsilon(1e-3).scale(0));
    }
    if (const char* directory = std::getenv("RADIANT_SCREENSHOT_DIR")) {
        lab.focusPanel("Probe");
        for (int i = 0; i < 30; ++i) lab.frame();  // the probe's reading arrives
        render::writePng(lab.frameAndCapture(), std::filesystem::path(directory) / "display-focus-links.png");
    }
}

TEST_CASE("a click is taken where the button went down, not where a slow frame finds the pointer (issue #16)") {
    requireDisplay();
    Lab lab(coarseCornell());
    lab.send(command::SetTolerance{1e-3});
    lab.send(command::Run{});
    waitForSolver(lab);
    frameUntil(lab, [](const app::Snapshot& s) { return !s.running && s.stats.iteration > 0; });

    const glm::dvec3 floor = render::projectToPixel(lab.camera(), lab.sceneViewport(), {0.42, 0.0, 0.12});
    const glm::dvec3 wall = render::projectToPixel(lab.camera(), lab.sceneViewport(), {0.15, 0.45, 0.559});
    // The window's own callbacks, as GLFW calls them while polling: ImGui's button callback, which
    // chains to the lab's, and the lab's cursor callback (window coordinates; Xvfb's pixel ratio is 1).
    GLFWwindow* window = glfwGetCurrentContext();
    REQUIRE(window != nullptr);
    const GLFWcursorposfun moved = glfwSetCursorPosCallback(window, nullptr);
    glfwSetCursorPosCallback(window, moved);
    const GLFWmousebuttonfun button = glfwSetMouseButtonCallback(window, nullptr);
    glfwSetMouseButtonCallback(window, button);
    const bool haveCallbacks = moved && button;
    REQUIRE(haveCallbacks);

    // One slow frame's events: a click on the floor, then the hand moves on to the back wall, where
    // ImGui reads the pointer when the frame comes (the override stands in for the X server's pointer).
    moved(window, floor.x, floor.y);
    button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
    moved(window, wall.x, wall.y);
    lab.overrideMouse(glm::vec2(wall.x, wall.y), true);  // ImGui's press frame: the button still down
    lab.frame();
    lab.overrideMouse(glm::vec2(wall.x, wall.y), false);
    lab.frame();
    lab.overrideMouse(std::nullopt);
    REQUIRE(lab.probePoint());
    const glm::dvec3 picked = *lab.probePoint();
    INFO("picked (" << picked.x << ", " << picked.y << ", " << picked.z << ")");
    CHECK(picked.y == doctest::Approx(0.0).epsilon(1e-6));  // the floor, not the back wall at z = 0.559
    CHECK(picked.x == doctest::Approx(0.42).epsilon(1e-3).scale(0));
    CHECK(picked.z == doctest::Approx(0.12).epsilon(1e-3).scale(0));

    // Pressed on the floor, dragged to the wall and let go there within one frame: a drag, not a click,
    // so the probe stays (taken at the frame's pointer, press and release were both on the wall).
    moved(window, floor.x, floor.y);
    button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    moved(window, wall.x, wall.y);
    button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
    lab.overrideMouse(glm::vec2(wall.x, wall.y), true);
    lab.frame();
    lab.overrideMouse(glm::vec2(wall.x, wall.y), false);
    lab.frame();
    lab.overrideMouse(std::nullopt);
    lab.frame();
    CHECK(lab.probePoint() == std::optional(picked));
}
