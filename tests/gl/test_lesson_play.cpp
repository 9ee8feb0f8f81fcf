// Every shipped lesson played to its end in the real lab (docs/lessons.md): each step's actions reach
// the solver thread, the camera, the probe, the panels and the display, and Page Up replays a
// step's state rather than continuing from the later one.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <thread>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/Lab.h"
#include "app/panels/IntegralsPanel.h"
#include "app/lessons/Lesson.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;
namespace lesson = radiant::app::lesson;

namespace {

std::vector<std::filesystem::path> shippedLessons() { return lesson::shippedLessonFiles(); }

LabOptions lessonLab() {
    LabOptions options;
    options.width = 1280;
    options.height = 800;
    options.vsync = false;
    options.maxPatchArea = 0.01;  // coarse unless a lesson asks for finer: the matrix methods' form factors stay quick
    options.runOnStart = false;
    return options;
}

/// Frames until the step's actions have all run and the solver has done what they asked. Progress,
/// not time: every few frames the test waits for the solver thread to go idle, so a slow machine
/// takes longer but never fails for it.
void settle(Lab& lab) {
    for (int frame = 0; frame < 20000 && !lab.lessons().settled(); ++frame) {
        lab.frame();
        if (frame % 20 == 19) lab.waitForSolver();
    }
    REQUIRE_MESSAGE(lab.lessons().settled(), "step " << lab.lessons().step() + 1 << " did not settle");
    lab.waitForSolver();
    // A run goes on after the commands are taken: frames until it stops at its tolerance (each
    // frame shows a newer iteration, so this ends on any machine).
    for (int frame = 0; frame < 200000 && (lab.snapshot()->running || !lab.lessons().settled()); ++frame) lab.frame();
    lab.waitForSolver();
    for (int i = 0; i < 3; ++i) lab.frame();
}

/// Frames until a reading arrives (measured on a worker), at `at` (within `within`, m) when given: the
/// reading of a point probed before may still be the lab's while the new one is gathered (an ASan
/// build's lesson step read the last step's point, 0.62 m away). A bounded number of frames a
/// millisecond apart, which a slow machine stretches but does not fail.
void waitForReading(Lab& lab, std::optional<glm::dvec3> at = std::nullopt, double within = 1e-3) {
    const auto arrived = [&] {
        const std::optional<ProbeReading> reading = lab.probeReading();
        return reading && (!at || glm::length(reading->at.point - *at) < within);
    };
    for (int i = 0; i < 30000 && !arrived(); ++i) {
        lab.frame();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

/// What the step's actions say must now hold in the lab.
void checkStep(Lab& lab, const lesson::LessonStep& step) {
    const std::shared_ptr<const app::Snapshot> shown = lab.snapshot();  // kept: frames below replace the lab's
    const app::Snapshot& s = *shown;
    REQUIRE(s.scene);
    CHECK_MESSAGE(s.error.empty(), s.error);
    for (const lesson::Action& action : step.actions) {
        if (const auto* method = std::get_if<lesson::SetMethod>(&action)) CHECK(s.method == method->method);
        if (const auto* load = std::get_if<lesson::LoadScene>(&action)) CHECK(s.scene->name == load->scene);
        if (const auto* material = std::get_if<lesson::SetMaterial>(&action)) {
            const std::size_t surface = s.scene->findSurface(material->surface);
            REQUIRE(surface != Scene::npos);
            const Material& m = s.scene->materials[s.scene->surfaces[surface].material];
            if (material->exitanceW_m2) CHECK(m.exitance.value().x == (*material->exitanceW_m2)[0]);
            if (material->reflectance) CHECK(m.reflectance.x == (*material->reflectance)[0]);
        }
        if (const auto* probe = std::get_if<lesson::Probe>(&action)) {
            waitForReading(lab, glm::dvec3{probe->point[0], probe->point[1], probe->point[2]});
            const std::optional<ProbeReading> reading = lab.probeReading();
            REQUIRE(reading);
            CHECK(glm::length(reading->at.point - glm::dvec3{probe->point[0], probe->point[1], probe->point[2]}) < 1e-3);
            if (probe->target) CHECK(reading->target);
        }
        if (const auto* display = std::get_if<lesson::SetDisplay>(&action)) {
            if (display->links) CHECK(lab.display().showLinks == *display->links);
            if (display->importance) CHECK(lab.display().showImportance == *display->importance);
            if (display->photometric) CHECK(lab.display().photometric == *display->photometric);
        }
        if (const auto* integrals = std::get_if<lesson::SetIntegrals>(&action)) {
            const app::HemisphereIntegralRun& run = lab.integrals().current();
            const app::IntegralMethod expected = integrals->method == "riemann"     ? app::IntegralMethod::Riemann
                                            : integrals->method == "cosine-mc" ? app::IntegralMethod::CosineMonteCarlo
                                                                               : app::IntegralMethod::UniformMonteCarlo;
            CHECK(run.settings().method == expected);
            // 2 pi sr or pi sr: which integrand the panel took.
            CHECK(run.exact() == doctest::Approx(integrals->integrand == "d-omega" ? 2 * std::numbers::pi : std::numbers::pi));
            if (integrals->run) CHECK(run.taken() > 0);
        }
        // Solved (importance-driven radiosity may be solving again for the camera the step placed).
        if (std::holds_alternative<lesson::Run>(action)) CHECK(s.stats.iteration > 0);
    }
}

} // namespace

TEST_SUITE("lesson play") {

TEST_CASE("every shipped lesson plays to its end in the lab, each step doing what it says") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    const std::vector<std::filesystem::path> files = shippedLessons();
    REQUIRE(files.size() >= 6);
    Lab lab(lessonLab());
    for (const std::filesystem::path& file : files) {
        CAPTURE(file.filename().string());
        lab.openLesson(file.string());
        const lesson::Lesson& played = lab.lessons().lesson();
        // Comparing two methods from the step that says so until one ends it; off when a lesson opens
        // (the previous lesson may have left one on).
        std::optional<app::ComparisonSettings> compared;
        for (std::size_t step = 0; step < played.steps.size(); ++step) {
            CAPTURE(step + 1);
            if (step > 0) lab.pressKey(GLFW_KEY_PAGE_DOWN);
            REQUIRE(lab.lessons().step() == step);
            settle(lab);
            CHECK(lab.lessonError().empty());
            checkStep(lab, played.steps[step]);
            for (const lesson::Action& action : played.steps[step].actions)
                if (const auto* c = std::get_if<lesson::Compare>(&action)) compared = c->settings;
            CHECK(lab.comparison().has_value() == compared.has_value());
            if (compared && lab.comparison()) CHECK(lab.comparison()->method == compared->method);
        }
        lab.pressKey(GLFW_KEY_PAGE_DOWN);  // past the last step: stays there
        CHECK(lab.lessons().step() + 1 == played.steps.size());
    }
}

TEST_CASE("Page Up replays the lesson up to the earlier step: Jacobi's second sweep is sweep 2 again") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    Lab lab(lessonLab());
    lab.openLesson((std::filesystem::path(assetDirectory()) / "lessons" / "04-radiosity-equation.json").string());
    settle(lab);
    CHECK(lab.snapshot()->stats.iteration == 0);  // reset: B = E
    lab.pressKey(GLFW_KEY_PAGE_DOWN);
    settle(lab);
    CHECK(lab.snapshot()->stats.iteration == 1);  // "sweep 1: direct light"
    lab.pressKey(GLFW_KEY_PAGE_DOWN);
    settle(lab);
    CHECK(lab.snapshot()->stats.iteration == 2);
    lab.pressKey(GLFW_KEY_PAGE_DOWN);
    settle(lab);
    CHECK(lab.snapshot()->stats.iteration > 2);  // run to the tolerance
    lab.pressKey(GLFW_KEY_PAGE_UP);
    settle(lab);
    CHECK(lab.lessons().step() == 2);
    CHECK(lab.snapshot()->stats.iteration == 2);
    // The last step sets Jacobi beside Gauss-Seidel; the step before it, replayed, has no comparison.
    while (lab.lessons().step() + 1 < lab.lessons().stepCount()) {
        lab.pressKey(GLFW_KEY_PAGE_DOWN);
        settle(lab);
    }
    REQUIRE(lab.comparison());
    CHECK(lab.comparison()->method == SolverMethod::Jacobi);
    lab.pressKey(GLFW_KEY_PAGE_UP);
    settle(lab);
    CHECK_FALSE(lab.comparison());
    // "Make the lamp brighter" replayed doubles the lamp again; the step before it has the lamp as
    // built, though the replay no longer loads the scene afresh (the materials are reset instead).
    const auto lampRed = [&lab] {
        const Scene& scene = *lab.snapshot()->scene;
        return scene.materials[scene.surfaces[scene.findSurface("light")].material].exitance.value().x;
    };
    CHECK(lampRed() == 34.0);
    lab.pressKey(GLFW_KEY_PAGE_UP);
    settle(lab);
    CHECK(lab.lessons().step() == 4);
    CHECK(lampRed() == 17.0);
}

TEST_CASE("Page Up to an earlier step of the scene shown keeps its mesh and form factors: the replay is instant") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    Lab lab(lessonLab());
    lab.openLesson((std::filesystem::path(assetDirectory()) / "lessons" / "01-radiometric-quantities.json").string());
    for (int step = 0; step < 3; ++step) {  // to "Irradiance at a point", past the diffuse emitter's demo
        if (step > 0) lab.pressKey(GLFW_KEY_PAGE_DOWN);
        settle(lab);
    }
    REQUIRE(lab.lessons().step() == 2);
    const std::uint64_t builds = lab.snapshot()->solverBuilds;
    const std::uint64_t meshGeneration = lab.snapshot()->meshGeneration;
    lab.pressKey(GLFW_KEY_PAGE_UP);  // replays steps 1 and 2, and step 1 loads the Cornell box
    settle(lab);
    CHECK(lab.lessons().step() == 1);
    CHECK(lab.lessonError().empty());
    CHECK(lab.activeDemo() == "diffuse-emitter");
    // Loading the box again rebuilt the solver: every form factor recomputed, the box black meanwhile.
    CHECK(lab.snapshot()->solverBuilds == builds);
    CHECK(lab.snapshot()->meshGeneration == meshGeneration);
    CHECK(lab.snapshot()->method == SolverMethod::GaussSeidel);
    CHECK(lab.snapshot()->stats.iteration > 0);  // step 1's run, solved again
}

TEST_CASE("a bad lesson file is refused in one line and the lab keeps its lesson") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    Lab lab(lessonLab());
    lab.openLesson((std::filesystem::path(assetDirectory()) / "lessons" / "05-progressive-refinement.json").string());
    const std::filesystem::path bad = std::filesystem::temp_directory_path() / "radiant-test-lesson-play-bad.json";
    std::ofstream(bad) << R"({"title": "t", "steps": [{"title": "a", "caption": "c", "actions": [{"scene": "nowhere.gltf"}]}]})";
    CHECK_THROWS_AS(lab.openLesson(bad.string()), RadiantError);
    std::filesystem::remove(bad);
    CHECK(lab.lessons().lesson().title == "Progressive refinement: shooting light");
}

} // TEST_SUITE

#include "render/camera/Camera.h"

TEST_SUITE("lesson play") {

TEST_CASE("a saved session reopens to the same solution, materials, method, display and probe point") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "radiant-test-session.json";
    std::vector<Rgb> solved;
    glm::dvec3 probed{0.0};
    {
        Lab lab(lessonLab());
        settle(lab);
        const std::size_t light = lab.snapshot()->scene->findSurface("light");
        REQUIRE(light != Scene::npos);
        lab.send(app::command::SetMethod{SolverMethod::Jacobi});
        CHECK(lab.editMaterial(light, Rgb(0.78), Rgb(34.0, 24.0, 8.0)).empty());
        lab.display().showLinks = true;
        // Converged far below the lab's 1e-4 (the session keeps the tolerance): a solve stopped at
        // 1e-4 depends on where it started and on how the commands fell between its steps (in an
        // ASan build the two labs ended 5e-4 apart, every run), a converged one does not.
        lab.send(app::command::SetTolerance{1e-10});
        lab.send(app::command::Run{});
        settle(lab);
        const glm::dvec3 floorPoint{0.42, 0.0, 0.12};
        const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), floorPoint);
        REQUIRE(lab.clickAt({pixel.x, pixel.y}));
        waitForReading(lab, floorPoint, 0.01);  // the pick lands within a pixel of it
        REQUIRE(lab.probeReading());
        probed = lab.probeReading()->at.point;
        solved = lab.snapshot()->radiosity;
        REQUIRE(lab.snapshot()->method == SolverMethod::Jacobi);
        lab.saveSession(file.string());
    }
    Lab reopened(lessonLab());  // Gauss-Seidel, the lamp as built, no links shown
    reopened.openLesson(file.string());
    settle(reopened);
    waitForReading(reopened, probed);
    const std::shared_ptr<const app::Snapshot> shown = reopened.snapshot();
    const app::Snapshot& s = *shown;
    CHECK(reopened.lessonError().empty());
    CHECK_FALSE(reopened.lessons().isOpen());  // a session restores the lab and closes
    CHECK(s.method == SolverMethod::Jacobi);
    CHECK(s.scene->materials[s.scene->surfaces[s.scene->findSurface("light")].material].exitance.value().x == 34.0);
    CHECK(reopened.display().showLinks);
    REQUIRE(reopened.probeReading());
    CHECK(glm::length(reopened.probeReading()->at.point - probed) < 1e-6);
    // The same mesh, method, materials and tolerance: the same solution, to the tolerance.
    REQUIRE(s.radiosity.size() == solved.size());
    double worst = 0;
    for (std::size_t i = 0; i < solved.size(); ++i)
        for (int band = 0; band < 3; ++band)
            worst = std::max(worst, std::abs(s.radiosity[i][band] - solved[i][band]) / std::max(1e-12, std::abs(solved[i][band])));
    CHECK(worst < 1e-6);
    std::filesystem::remove(file);
}

TEST_CASE("a session saved while comparing two methods reopens comparing them, in the same units") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "radiant-test-session-compare.json";
    const app::ComparisonSettings compared{SolverMethod::Progressive, 4.0, app::ComparisonView::Difference};
    std::size_t patchesB = 0;
    {
        Lab lab(lessonLab());
        settle(lab);
        lab.setComparison(compared);
        lab.compare(true);
        lab.display().photometric = true;
        lab.send(app::command::Run{});
        settle(lab);
        for (int frame = 0; frame < 200000 && !(lab.secondSnapshot() && lab.secondSnapshot()->mesh); ++frame) lab.frame();
        REQUIRE((lab.secondSnapshot() && lab.secondSnapshot()->mesh));
        patchesB = lab.secondSnapshot()->mesh->size();
        lab.saveSession(file.string());
    }
    Lab reopened(lessonLab());
    reopened.compare(true);  // comparing already (the default pair): the session's B replaces it
    reopened.openLesson(file.string());
    settle(reopened);
    CHECK(reopened.lessonError().empty());
    REQUIRE(reopened.comparison());
    CHECK(*reopened.comparison() == compared);
    CHECK(reopened.display().photometric);
    for (int frame = 0; frame < 200000 && !(reopened.secondSnapshot() && reopened.secondSnapshot()->mesh &&
                                            reopened.secondSnapshot()->mesh->size() == patchesB);
         ++frame)
        reopened.frame();
    REQUIRE((reopened.secondSnapshot() && reopened.secondSnapshot()->mesh));
    CHECK(reopened.secondSnapshot()->method == SolverMethod::Progressive);
    CHECK(reopened.secondSnapshot()->mesh->size() == patchesB);  // B on 4x A's patch area, as saved

    // A session saved with the comparison off turns it off.
    reopened.compare(false);
    reopened.saveSession(file.string());
    reopened.compare(true);
    reopened.openLesson(file.string());
    settle(reopened);
    CHECK_FALSE(reopened.comparison());
    std::filesystem::remove(file);
}
} // TEST_SUITE

TEST_SUITE("lesson play") {

TEST_CASE("at UI scale 1.5 the lesson caption has a band below the 3D view: the probed floor point is on screen, not under it") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display && *display), "no X display: run the GL tests under Xvfb");
    LabOptions options = lessonLab();
    options.uiScale = 1.5f;
    Lab lab(options);
    lab.openLesson((std::filesystem::path(assetDirectory()) / "lessons" / "01-radiometric-quantities.json").string());
    settle(lab);
    lab.pressKey(GLFW_KEY_PAGE_DOWN);  // the diffuse emitter
    settle(lab);
    lab.pressKey(GLFW_KEY_PAGE_DOWN);  // "Irradiance at a point": the probe on the floor near the front
    settle(lab);
    waitForReading(lab);
    REQUIRE(lab.probeReading());
    lab.frame();
    const std::optional<int> captionTop = lab.lessonCaptionTop();
    REQUIRE(captionTop);
    const render::Viewport view = lab.sceneViewport();
    CHECK(view.y + view.height <= *captionTop);
    CHECK(*captionTop < 800);  // the caption is on screen (the window is 800 high)
    // Over the picture, the caption hid the front of the floor, where this point is.
    const glm::dvec3 pixel = render::projectToPixel(lab.camera(), view, lab.probeReading()->at.point);
    CHECK(pixel.x > view.x);
    CHECK(pixel.x < view.x + view.width);
    CHECK(pixel.y > view.y);
    CHECK(pixel.y < view.y + view.height);
}

} // TEST_SUITE
